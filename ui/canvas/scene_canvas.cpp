#include "canvas/scene_canvas.h"

#include "canvas/body_painter.h"
#include "document/scene_document.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace chaplygin::ui {

namespace {

constexpr double kStrokeSpacingPx = 10;    // drawn points closer than this are dropped
constexpr double kVertexPickPx = 8;        // how near a click must be to grab a vertex
constexpr int kTopPx = 26, kLegendPx = 78; // the time line and the legend, before the scale

} // namespace

SceneCanvas::SceneCanvas(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(false);
    setAutoFillBackground(false);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setToolTip(
        tr("Wheel or +/-: zoom; drag or arrows: pan; F: fit the path; Shift+F: fit everything "
           "that moves; B: follow body; L: legend"));
    setAccessibleName(tr("Scene canvas"));
    setAccessibleDescription(tr("The animation: the prescribed path, the controlled body and the "
                                "free motion from the same start"));
    connect(document, &SceneDocument::solutionChanged, this, &SceneCanvas::onSolutionChanged);
}

QTransform SceneCanvas::worldTransform() const {
    return worldTransformAt(m_centre);
}

QTransform SceneCanvas::worldTransformAt(QPointF centre) const {
    QTransform t;
    t.translate(width() / 2.0, height() / 2.0);
    t.scale(m_scale, -m_scale);
    t.translate(-centre.x(), -centre.y());
    return t;
}

const CanvasCurves& SceneCanvas::curves() const {
    m_curves.update(m_document->solution(), m_scale * devicePixelRatioF(),
                    worldTransform().inverted().mapRect(QRectF(rect())));
    return m_curves;
}

QPointF SceneCanvas::toPixel(QPointF world) const {
    return worldTransform().map(world);
}

QPointF SceneCanvas::toWorld(QPointF pixel) const {
    return worldTransform().inverted().map(pixel);
}

void SceneCanvas::onSolutionChanged() {
    // a new path is fitted, but a stroke the user drew or a point moved keeps the view where
    // the path stays in it; a parameter change keeps the view steady while a slider moves
    if (m_document->solution()->path() != m_fittedPath) {
        if (m_keepView)
            keepPathInView();
        else if (m_autoFit)
            m_fitAll ? fitEverything() : fitScene();
        m_keepView = false;
    }
    if (m_follow)
        centreOnBody();
    update();
}

void SceneCanvas::setTime(double t) {
    double from = m_time;
    QPointF centre = m_centre;
    m_time = t;
    if (m_follow)
        centreOnBody();
    updateMoving(from, centre);
}

void SceneCanvas::centreOnBody() {
    const auto& solution = m_document->solution();
    if (!solution)
        return;
    MotionSample m = solution->at(std::clamp(m_time, 0.0, solution->tEnd()));
    // on the pixel grid, so that the view moves by whole pixels and the static layer is shifted
    // rather than drawn again
    m_centre = QPointF(std::round(m.x * m_scale) / m_scale, std::round(m.y * m_scale) / m_scale);
}

QRectF SceneCanvas::pathBounds() const {
    const auto& solution = m_document->solution();
    if (!solution)
        return {};
    if (m_boundsOf == solution.get())
        return m_pathBounds;
    // the path's nodes and its two ends (the nodes are inside the panels)
    const PlotSeries& s = m_document->series();
    const Path& path = *solution->path();
    double x0 = std::min(path.start().x, path.end().x), x1 = std::max(path.start().x, path.end().x);
    double y0 = std::min(path.start().y, path.end().y), y1 = std::max(path.start().y, path.end().y);
    for (int i = 0; i < std::min(s.pathX.size(), s.pathY.size()); ++i) {
        if (!std::isfinite(s.pathX[i]) || !std::isfinite(s.pathY[i]))
            continue;
        x0 = std::min(x0, s.pathX[i]);
        x1 = std::max(x1, s.pathX[i]);
        y0 = std::min(y0, s.pathY[i]);
        y1 = std::max(y1, s.pathY[i]);
    }
    m_boundsOf = solution.get();
    m_pathBounds = x0 <= x1 && y0 <= y1 ? QRectF(QPointF(x0, y0), QPointF(x1, y1)) : QRectF();
    return m_pathBounds;
}

BodyDisplay SceneCanvas::shownBodyDisplay() const {
    const auto& solution = m_document->solution();
    if (!solution)
        return m_style.body == BodyDisplay::Automatic ? BodyDisplay::ToScale : m_style.body;
    return ui::shownBodyDisplay(m_style.body, solution->scene().system, solution->system(),
                                pathBounds());
}

BodyLook SceneCanvas::bodyLook() const {
    return {shownBodyDisplay(), m_style.bodyOpacity, m_style.lineScale};
}

QRectF SceneCanvas::sceneBounds() const {
    const auto& solution = m_document->solution();
    if (!solution)
        return {};
    const PlotSeries& s = m_document->series();
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    auto extend = [&](const QVector<double>& xs, const QVector<double>& ys) {
        for (int i = 0; i < std::min(xs.size(), ys.size()); ++i) {
            if (!std::isfinite(xs[i]) || !std::isfinite(ys[i]))
                continue;
            x0 = std::min(x0, xs[i]);
            x1 = std::max(x1, xs[i]);
            y0 = std::min(y0, ys[i]);
            y1 = std::max(y1, ys[i]);
        }
    };
    // everything that moves, over the whole horizon
    extend(s.pathX, s.pathY);
    extend(s.x, s.y);
    extend(s.freeX, s.freeY);
    if (m_showVakonomic)
        extend(s.vakX, s.vakY);
    if (drawsOpenLoop())
        extend(s.pertX, s.pertY);
    if (drawsClosedLoop())
        extend(s.fbX, s.fbY);
    if (x0 > x1)
        return {};
    QRectF box(QPointF(x0, y0), QPointF(x1, y1));
    double pad = shownBodyDisplay() == BodyDisplay::Marker
                     ? 0.05 * std::max({box.width(), box.height(), 1e-3})
                     : bodyExtent(solution->scene().system, solution->system());
    return box.adjusted(-pad, -pad, pad, pad);
}

int SceneCanvas::topBandPx() const {
    return int(std::lround(kTopPx * m_style.lineScale * (m_style.largeTime ? 1.7 : 1.0)));
}

bool SceneCanvas::compactLegend() const {
    // presenting without pushed bodies: the path and the vakonomic body in a second column
    return m_style.largeTime && !drawsOpenLoop() && !drawsClosedLoop();
}

int SceneCanvas::legendBandPx() const {
    if (!m_legendVisible)
        return 0;
    // four rows of 16 px, or two in the compact legend, and 14 px around them
    return int(std::lround((compactLegend() ? kLegendPx - 32 : kLegendPx) * m_style.lineScale));
}

QRectF SceneCanvas::drawingArea() const {
    return QRectF(0, topBandPx(), width(), std::max(height() - topBandPx() - legendBandPx(), 0));
}

void SceneCanvas::setCanvasStyle(const CanvasStyle& style) {
    m_style = style.sanitized();
    m_vectors.setLineScale(m_style.lineScale);
    refit();
    update();
}

CanvasLook SceneCanvas::look() const {
    return {.style = m_style,
            .vakonomic = m_showVakonomic,
            .openLoop = m_showOpenLoop,
            .closedLoop = m_showClosedLoop,
            .legend = m_legendVisible};
}

void SceneCanvas::setLook(const CanvasLook& look) {
    m_showVakonomic = look.vakonomic;
    m_showOpenLoop = look.openLoop;
    m_showClosedLoop = look.closedLoop;
    m_legendVisible = look.legend;
    setCanvasStyle(look.style);
}

void SceneCanvas::setLegendVisible(bool visible) {
    m_legendVisible = visible;
    refit();
    update();
}

void SceneCanvas::frame(const QRectF& box, double margin, double minScale) {
    // the scene goes between the time line at the top and the legend at the bottom
    const QRectF area = drawingArea();
    const double w = std::max(area.width(), 100.0), h = std::max(area.height(), 100.0);
    const double room = std::min(w, h) * 0.4; // a margin never takes more than this
    const double ww = w - 2 * std::min(margin, room), hh = h - 2 * std::min(margin, room);
    const double fit =
        std::min(ww / std::max(box.width(), 1e-9), hh / std::max(box.height(), 1e-9));
    // a view far from the origin (a path at 1e308 m) keeps scale times its centre finite
    const double far = std::max({std::abs(box.center().x()), std::abs(box.center().y()), 1.0});
    m_scale = std::clamp(std::min(std::max(fit, minScale), 1e300 / far), 1e-3, 1e5);
    m_centre = box.center() + QPointF(0, (area.center().y() - height() / 2.0) / m_scale);
    m_fittedPath = m_document->solution()->path();
    m_autoFit = true;
    setFollowBody(false);
    update();
}

void SceneCanvas::fitScene() {
    const auto& solution = m_document->solution();
    const QRectF path = pathBounds();
    if (!solution || path.isNull())
        return;
    m_fitAll = false;
    // the controlled body around the path: its extent [m] to scale or as an outline, the
    // marker's pixels
    const bool marker = shownBodyDisplay() == BodyDisplay::Marker;
    const double body = marker ? 0 : bodyExtent(solution->scene().system, solution->system());
    const double markerPx = marker ? 2.5 * kMarkerRadiusPx * m_style.lineScale : 0;
    const QRectF area = drawingArea();
    const double w = std::max(area.width(), 100.0), h = std::max(area.height(), 100.0);
    // a margin of 5 % of the drawing area on each side
    const double margin = std::max(0.05 * std::min(w, h), markerPx);
    // a large body may reach out of the view, but the path fills at least 80 % of the area in
    // the direction that limits it
    const double pathFill =
        std::min(w / std::max(path.width(), 1e-9), h / std::max(path.height(), 1e-9));
    frame(path.adjusted(-body, -body, body, body), margin, 0.8 * pathFill);
}

void SceneCanvas::fitEverything() {
    const auto& solution = m_document->solution();
    const QRectF box = sceneBounds();
    if (!solution || box.isNull())
        return;
    m_fitAll = true;
    const QRectF area = drawingArea();
    frame(box, 0.025 * std::min(std::max(area.width(), 100.0), std::max(area.height(), 100.0)), 0);
}

void SceneCanvas::refit() {
    if (m_follow)
        centreOnBody();
    else if (m_autoFit)
        m_fitAll ? fitEverything() : fitScene();
}

void SceneCanvas::keepPathInView() {
    const auto& solution = m_document->solution();
    const QRectF path = pathBounds();
    if (!solution || path.isNull())
        return;
    m_fittedPath = solution->path();
    const QRectF pixels = QRectF(toPixel(path.topLeft()), toPixel(path.bottomRight())).normalized();
    if (m_follow || drawingArea().adjusted(-1, -1, 1, 1).contains(pixels)) {
        m_autoFit = false; // the view the user drew in: a resize does not refit it either
        update();
        return;
    }
    fitScene();
}

void SceneCanvas::setFollowBody(bool follow) {
    if (follow == m_follow)
        return;
    m_follow = follow;
    if (m_follow) {
        m_autoFit = false;
        centreOnBody();
    }
    emit followBodyChanged(m_follow);
    update();
}

void SceneCanvas::setDrawMode(bool on) {
    m_drawMode = on;
    m_stroke.clear();
    setCursor(on ? Qt::CrossCursor : Qt::ArrowCursor);
    update();
}

void SceneCanvas::setShowVakonomic(bool show) {
    m_showVakonomic = show;
    update();
}

void SceneCanvas::setShowOpenLoop(bool show) {
    m_showOpenLoop = show;
    update();
}

void SceneCanvas::setShowClosedLoop(bool show) {
    m_showClosedLoop = show;
    update();
}

bool SceneCanvas::drawsOpenLoop() const {
    return m_showOpenLoop && m_document->series().perturbed;
}

bool SceneCanvas::drawsClosedLoop() const {
    return m_showClosedLoop && m_document->series().perturbed;
}

bool SceneCanvas::onControlledBody(QPointF pixel) const {
    const auto& solution = m_document->solution();
    if (!solution)
        return false;
    const MotionSample m = solution->at(std::clamp(m_time, 0.0, solution->tEnd()));
    const BodyLook look = bodyLook();
    const QRectF box = BodySprites::pixelBounds(worldTransform(), m_scale, solution->scene().system,
                                                solution->system(), {m.x, m.y, m.phi}, look);
    // the body's box, at least a finger's width around P
    const QPointF p = toPixel({m.x, m.y});
    return box.contains(pixel) || QLineF(p, pixel).length() <= 12 * m_style.lineScale;
}

void SceneCanvas::zoomBy(double factor) {
    m_autoFit = false;
    m_scale = std::clamp(m_scale * factor, 1e-3, 1e5);
    update();
}

void SceneCanvas::resizeEvent(QResizeEvent*) {
    refit();
}

std::vector<std::pair<double, double>> SceneCanvas::drawnPoints() const {
    const auto& solution = m_document->solution();
    if (!solution || solution->scene().path.kind != PathKind::Polyline)
        return {};
    return solution->scene().path.points;
}

int SceneCanvas::vertexAt(QPointF pos) const {
    const auto points = drawnPoints();
    int best = -1;
    double bestDistance = kVertexPickPx;
    for (std::size_t i = 0; i < points.size(); ++i) {
        double d = QLineF(toPixel({points[i].first, points[i].second}), pos).length();
        if (d <= bestDistance) {
            bestDistance = d;
            best = int(i);
        }
    }
    return best;
}

void SceneCanvas::wheelEvent(QWheelEvent* e) {
    // zoom about the point under the cursor
    QPointF pos = e->position();
    QPointF before = toWorld(pos);
    zoomBy(std::pow(1.0015, e->angleDelta().y()));
    QPointF after = toWorld(pos);
    m_centre += before - after;
    setFollowBody(false);
    update();
    e->accept();
}

void SceneCanvas::mousePressEvent(QMouseEvent* e) {
    m_lastMouse = e->position();
    int vertex = m_drawMode ? vertexAt(e->position()) : -1;
    if (vertex >= 0 && e->button() == Qt::LeftButton) {
        m_dragVertex = vertex;
        m_editPoints = drawnPoints();
    } else if (vertex >= 0 && e->button() == Qt::RightButton) {
        auto points = drawnPoints();
        if (points.size() > 2) {
            points.erase(points.begin() + vertex);
            emit pointsEdited(points);
        }
    } else if (m_drawMode && e->button() == Qt::LeftButton) {
        m_stroke = {toWorld(e->position())};
    } else if (e->button() == Qt::LeftButton && onControlledBody(e->position())) {
        // grab and push (docs/physics.md §9): the drag's sideways part is the push
        const auto& solution = m_document->solution();
        m_pushing = true;
        m_pushTime = std::clamp(m_time, 0.0, solution->tEnd());
        m_pushPhi = solution->at(m_pushTime).phi;
        m_pushFrom = toWorld(e->position());
        m_pushTo = e->position();
        setCursor(Qt::SizeAllCursor);
    } else {
        m_panning = true;
        setCursor(Qt::ClosedHandCursor);
    }
    e->accept();
}

void SceneCanvas::mouseMoveEvent(QMouseEvent* e) {
    if (m_dragVertex >= 0) {
        QPointF w = toWorld(e->position());
        m_editPoints[std::size_t(m_dragVertex)] = {w.x(), w.y()};
        update();
    } else if (m_drawMode && !m_stroke.empty() && (e->buttons() & Qt::LeftButton)) {
        if (QLineF(toPixel(m_stroke.back()), e->position()).length() >= kStrokeSpacingPx) {
            m_stroke.push_back(toWorld(e->position()));
            update();
        }
    } else if (m_pushing) {
        m_pushTo = e->position();
        update();
    } else if (m_panning) {
        QPointF d = e->position() - m_lastMouse;
        m_centre -= QPointF(d.x() / m_scale, -d.y() / m_scale);
        m_lastMouse = e->position();
        m_autoFit = false;
        setFollowBody(false);
        update();
    }
}

void SceneCanvas::mouseReleaseEvent(QMouseEvent* e) {
    if (m_dragVertex >= 0 && e->button() == Qt::LeftButton) {
        QPointF w = toWorld(e->position());
        m_editPoints[std::size_t(m_dragVertex)] = {w.x(), w.y()};
        m_dragVertex = -1;
        update();
        m_keepView = true;
        emit pointsEdited(m_editPoints);
        return;
    }
    if (m_drawMode && e->button() == Qt::LeftButton && !m_stroke.empty()) {
        if (QLineF(toPixel(m_stroke.back()), e->position()).length() >= kStrokeSpacingPx / 2)
            m_stroke.push_back(toWorld(e->position()));
        std::vector<std::pair<double, double>> points;
        for (QPointF w : m_stroke)
            points.emplace_back(w.x(), w.y());
        m_stroke.clear();
        update();
        if (points.size() >= 3) {
            m_keepView = true;
            emit pathDrawn(points);
        }
    }
    if (m_pushing && e->button() == Qt::LeftButton) {
        m_pushing = false;
        setCursor(m_drawMode ? Qt::CrossCursor : Qt::ArrowCursor);
        // the drag's component along the heading's left normal [m]
        const QPointF d = toWorld(e->position()) - m_pushFrom;
        const double left = -d.x() * std::sin(m_pushPhi) + d.y() * std::cos(m_pushPhi);
        if (QLineF(toPixel(m_pushFrom), e->position()).length() >= 3)
            emit pushDragged(m_pushTime, left);
        update();
    }
    if (m_panning) {
        m_panning = false;
        setCursor(m_drawMode ? Qt::CrossCursor : Qt::ArrowCursor);
    }
}

void SceneCanvas::keyPressEvent(QKeyEvent* e) {
    switch (e->key()) {
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        zoomBy(1.25);
        break;
    case Qt::Key_Minus:
        zoomBy(0.8);
        break;
    case Qt::Key_F:
        if (e->modifiers() & Qt::ShiftModifier)
            fitEverything();
        else
            fitScene();
        break;
    case Qt::Key_B:
        setFollowBody(!m_follow);
        break;
    case Qt::Key_L:
        setLegendVisible(!m_legendVisible);
        break;
    case Qt::Key_Left:
    case Qt::Key_Right:
    case Qt::Key_Up:
    case Qt::Key_Down: {
        // arrows pan by a tenth of the view
        double dx = e->key() == Qt::Key_Left ? -1 : e->key() == Qt::Key_Right ? 1 : 0;
        double dy = e->key() == Qt::Key_Down ? -1 : e->key() == Qt::Key_Up ? 1 : 0;
        m_centre += QPointF(dx * width(), dy * height()) * (0.1 / m_scale);
        m_autoFit = false;
        setFollowBody(false);
        update();
        break;
    }
    default:
        QWidget::keyPressEvent(e);
    }
}

} // namespace chaplygin::ui
