#include "canvas/scene_canvas.h"

#include "canvas/body_painter.h"
#include "canvas/pin_painter.h"
#include "document/pin_set.h"
#include "document/scene_document.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace chaplygin::ui {

namespace {

constexpr double kStrokeSpacingPx = 10;    // drawn points closer than this are dropped
constexpr double kVertexPickPx = 8;        // how near a click must be to grab a vertex
constexpr int kTopPx = 26, kLegendPx = 78; // the time line and the legend, before the scale

// pen widths scale with the canvas style; set at the start of each paint
double t_penScale = 1;

QPen cosmetic(const QColor& c, double w, Qt::PenStyle style = Qt::SolidLine) {
    QPen pen(c, w * t_penScale, style);
    pen.setCosmetic(true);
    pen.setCapStyle(Qt::RoundCap);
    pen.setJoinStyle(Qt::RoundJoin);
    return pen;
}

// curvature colour: grey when straight, blue for left turns (kappa > 0), red for right turns
QColor curvatureColor(double kappa) {
    double w = std::tanh(std::abs(kappa));
    QColor turn = kappa > 0 ? QColor(40, 90, 230) : QColor(220, 60, 40);
    QColor flat(150, 150, 150);
    return QColor::fromRgbF(flat.redF() + w * (turn.redF() - flat.redF()),
                            flat.greenF() + w * (turn.greenF() - flat.greenF()),
                            flat.blueF() + w * (turn.blueF() - flat.blueF()));
}

// halfway to white, opaque (overlapping segments do not darken)
QColor pale(const QColor& c) {
    return QColor::fromRgbF(0.5 + 0.5 * c.redF(), 0.5 + 0.5 * c.greenF(), 0.5 + 0.5 * c.blueF());
}

} // namespace

SceneCanvas::SceneCanvas(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(false);
    setAutoFillBackground(false);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setToolTip(
        tr("Wheel or +/-: zoom; drag or arrows: pan; F: fit scene; B: follow body; L: legend"));
    setAccessibleName(tr("Scene canvas"));
    setAccessibleDescription(tr("The animation: the prescribed path, the controlled body and the "
                                "free motion from the same start"));
    connect(document, &SceneDocument::solutionChanged, this, &SceneCanvas::onSolutionChanged);
}

QTransform SceneCanvas::worldTransform() const {
    QTransform t;
    t.translate(width() / 2.0, height() / 2.0);
    t.scale(m_scale, -m_scale);
    t.translate(-m_centre.x(), -m_centre.y());
    return t;
}

QPointF SceneCanvas::toPixel(QPointF world) const {
    return worldTransform().map(world);
}

QPointF SceneCanvas::toWorld(QPointF pixel) const {
    return worldTransform().inverted().map(pixel);
}

void SceneCanvas::onSolutionChanged() {
    // a new path is fitted; a parameter change keeps the view steady while a slider moves
    if (m_autoFit && m_document->solution()->path() != m_fittedPath)
        fitScene();
    if (m_follow)
        centreOnBody();
    update();
}

void SceneCanvas::setTime(double t) {
    m_time = t;
    if (m_follow)
        centreOnBody();
    update();
}

void SceneCanvas::centreOnBody() {
    const auto& solution = m_document->solution();
    if (!solution)
        return;
    MotionSample m = solution->at(std::clamp(m_time, 0.0, solution->tEnd()));
    m_centre = QPointF(m.x, m.y);
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
    if (x0 > x1)
        return {};
    QRectF box(QPointF(x0, y0), QPointF(x1, y1));
    double pad = m_style.body == BodyDisplay::Marker
                     ? 0.05 * std::max({box.width(), box.height(), 1e-3})
                     : bodyExtent(solution->scene().system, solution->system());
    return box.adjusted(-pad, -pad, pad, pad);
}

int SceneCanvas::topBandPx() const {
    return int(std::lround(kTopPx * m_style.lineScale * (m_style.largeTime ? 2.2 : 1.0)));
}

int SceneCanvas::legendBandPx() const {
    return m_legendVisible ? int(std::lround(kLegendPx * m_style.lineScale)) : 0;
}

QRectF SceneCanvas::drawingArea() const {
    return QRectF(0, topBandPx(), width(), std::max(height() - topBandPx() - legendBandPx(), 0));
}

void SceneCanvas::setCanvasStyle(const CanvasStyle& style) {
    m_style = style.sanitized();
    if (m_autoFit)
        fitScene();
    update();
}

void SceneCanvas::setLegendVisible(bool visible) {
    m_legendVisible = visible;
    if (m_autoFit)
        fitScene();
    update();
}

void SceneCanvas::fitScene() {
    const auto& solution = m_document->solution();
    if (!solution)
        return;
    QRectF box = sceneBounds();
    if (box.isNull())
        return;
    // the scene goes between the time line at the top and the legend at the bottom
    QRectF area = drawingArea();
    double w = std::max(area.width(), 100.0), h = std::max(area.height(), 100.0);
    m_scale = std::clamp(
        std::min(w / std::max(box.width(), 1e-9), h / std::max(box.height(), 1e-9)) * 0.95, 1e-3,
        1e5);
    m_centre = box.center() + QPointF(0, (area.center().y() - height() / 2.0) / m_scale);
    m_fittedPath = solution->path();
    m_autoFit = true;
    setFollowBody(false);
    update();
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

void SceneCanvas::zoomBy(double factor) {
    m_autoFit = false;
    m_scale = std::clamp(m_scale * factor, 1e-3, 1e5);
    update();
}

void SceneCanvas::resizeEvent(QResizeEvent*) {
    if (m_autoFit)
        fitScene();
}

void SceneCanvas::paintGrid(QPainter& p) const {
    // grid lines every 1, 2 or 5 x 10^k metres, at least 40 px apart
    double decade = std::pow(10.0, std::floor(std::log10(40.0 / m_scale)));
    double step = decade;
    for (double f : {1.0, 2.0, 5.0, 10.0})
        if (f * decade * m_scale >= 40) {
            step = f * decade;
            break;
        }
    QPointF a = toWorld(QPointF(0, height())), b = toWorld(QPointF(width(), 0));
    p.setPen(cosmetic(QColor(232, 232, 232), 1));
    // counted, not accumulated: far from the origin x + step may round back to x
    const double kx0 = std::floor(a.x() / step), kx1 = std::ceil(b.x() / step);
    const double ky0 = std::floor(a.y() / step), ky1 = std::ceil(b.y() / step);
    const bool countable =
        std::max({std::abs(kx0), std::abs(kx1), std::abs(ky0), std::abs(ky1)}) < 1e15;
    if (countable && kx1 - kx0 < 2000 && ky1 - ky0 < 2000) {
        for (double k = kx0; k <= kx1; ++k)
            p.drawLine(toPixel({k * step, a.y()}), toPixel({k * step, b.y()}));
        for (double k = ky0; k <= ky1; ++k)
            p.drawLine(toPixel({a.x(), k * step}), toPixel({b.x(), k * step}));
    }
    p.setPen(cosmetic(QColor(200, 200, 200), 1));
    p.drawLine(toPixel({a.x(), 0}), toPixel({b.x(), 0}));
    p.drawLine(toPixel({0, a.y()}), toPixel({0, b.y()}));
    // scale bar, top right: one grid step
    double len = step * m_scale;
    QPointF right(width() - 14, topBandPx() - 2), left = right - QPointF(len, 0);
    p.setPen(cosmetic(QColor(60, 60, 60), 1.5));
    p.drawLine(left, right);
    p.drawLine(left, left - QPointF(0, 5));
    p.drawLine(right, right - QPointF(0, 5));
    QFont f = font();
    f.setPointSizeF(8 * m_style.lineScale);
    p.setFont(f);
    QString label =
        step >= 1 ? QStringLiteral("%1 m").arg(step) : QStringLiteral("%1 cm").arg(step * 100);
    p.drawText(QRectF(left.x() - 40, left.y() - 8 - 14 * m_style.lineScale, len + 80,
                      14 * m_style.lineScale),
               Qt::AlignCenter, label);
}

void SceneCanvas::paintPath(QPainter& p) const {
    const auto& solution = m_document->solution();
    for (const PathPiece& piece : solution->path()->pieces()) {
        if (piece.kind == PathPiece::Kind::Pivot) {
            p.setPen(cosmetic(QColor(120, 60, 160), 1.5));
            p.setBrush(Qt::NoBrush);
            p.drawEllipse(toPixel({piece.x, piece.y}), 5, 5);
            continue;
        }
        const auto& nodes = piece.table->nodes();
        for (std::size_t i = 1; i < nodes.size(); ++i) {
            // a wide pale band, so that the trail on top of it stays visible
            QPen pen =
                cosmetic(m_style.highContrast
                             ? m_style.path()
                             : pale(curvatureColor(0.5 * (nodes[i - 1].kappa + nodes[i].kappa))),
                         6);
            pen.setCapStyle(Qt::FlatCap);
            p.setPen(pen);
            p.drawLine(toPixel({nodes[i - 1].x, nodes[i - 1].y}),
                       toPixel({nodes[i].x, nodes[i].y}));
        }
    }
    // start (filled) and end (open) of the path
    const Path& path = *solution->path();
    p.setPen(cosmetic(QColor(40, 40, 40), 1.5));
    p.setBrush(QColor(40, 40, 40));
    p.drawEllipse(toPixel({path.start().x, path.start().y}), 4, 4);
    p.setBrush(Qt::white);
    p.drawRect(QRectF(toPixel({path.end().x, path.end().y}) - QPointF(4, 4), QSizeF(8, 8)));
}

void SceneCanvas::paintTrails(QPainter& p, const MotionSample& now) const {
    const PlotSeries& s = m_document->series();
    auto trail = [&](const QVector<double>& t, const QVector<double>& x, const QVector<double>& y,
                     QPointF end, const QPen& pen) {
        QPolygonF line;
        for (int i = 0; i < t.size() && t[i] <= m_time; ++i)
            line << toPixel({x[i], y[i]});
        line << toPixel(end);
        p.setPen(pen);
        p.drawPolyline(line);
    };
    QColor free = m_style.free();
    free.setAlpha(m_style.highContrast ? 255 : 150);
    double w = m_style.trailWidth;
    trail(s.freeT, s.freeX, s.freeY, {now.free.x, now.free.y},
          cosmetic(free, std::max(0.75 * w, 1.5), Qt::DashLine));
    trail(s.t, s.x, s.y, {now.x, now.y}, cosmetic(m_style.controlled().darker(150), w));
    if (m_showVakonomic)
        trail(s.vakT, s.vakX, s.vakY, {now.vak.x, now.vak.y},
              cosmetic(m_style.vakonomic(), std::max(0.75 * w, 1.5), Qt::DashDotLine));
}

void SceneCanvas::paintLegend(QPainter& p) const {
    // the legend has its own strip under the drawing area: nothing moves under it
    const double k = m_style.lineScale;
    QFont f = font();
    f.setPointSizeF(9 * k);
    p.setFont(f);
    if (m_legendVisible) {
        QRectF band(0, height() - legendBandPx(), width(), legendBandPx());
        p.fillRect(band, QColor(246, 246, 246));
        p.setPen(cosmetic(QColor(200, 200, 200), 1));
        p.drawLine(band.topLeft(), band.topRight());
        double y = band.top() + 8 * k, dy = 16 * k, x = 10, len = 24 * k;
        p.setPen(cosmetic(m_style.controlled().darker(150), 2));
        p.drawLine(QPointF(x, y), QPointF(x + len, y));
        p.setPen(cosmetic(m_style.free(), 2, Qt::DashLine));
        p.drawLine(QPointF(x, y + dy), QPointF(x + len, y + dy));
        if (m_showVakonomic) {
            p.setPen(cosmetic(m_style.vakonomic(), 2, Qt::DashDotLine));
            p.drawLine(QPointF(x, y + 3 * dy), QPointF(x + len, y + 3 * dy));
        }
        for (int i = 0; i < 24; ++i) {
            QColor c =
                m_style.highContrast ? m_style.path() : pale(curvatureColor((i - 11.5) / 4.0));
            QPen pen = cosmetic(c, 6);
            pen.setCapStyle(Qt::FlatCap);
            p.setPen(pen);
            p.drawLine(QPointF(x + i * k, y + 2 * dy), QPointF(x + (i + 1) * k, y + 2 * dy));
        }
        p.setPen(Qt::black);
        double tx = x + len + 6;
        auto text = [&](double row, const QString& s) {
            QRectF r(tx, y + row * dy - 0.5 * dy, width() - tx - 4, dy);
            p.drawText(r, Qt::AlignLeft | Qt::AlignVCenter,
                       p.fontMetrics().elidedText(s, Qt::ElideRight, int(r.width())));
        };
        text(0, tr("controlled body and its trail (tracks the path)"));
        text(1, tr("free motion from the same start (ghost)"));
        if (m_showVakonomic)
            text(3, tr("genuine vakonomic body: \u03bb obeys its own equation (21)"));
        text(2, m_style.highContrast
                    ? tr("path (\u25cf start, \u25a1 end)")
                    : tr("path (\u25cf start, \u25a1 end), coloured by its curvature \u03ba: red "
                         "right turn, grey straight, blue left turn"));
    }
    if (m_drawMode)
        p.drawText(QRectF(8, topBandPx(), width() - 16, 20 * k), Qt::AlignLeft,
                   tr("Draw mode: drag to draw a new path; drag a square to move a point, "
                      "right-click it to delete it"));
}

void SceneCanvas::paintBackground() {
    // grid, path and legend change only with the view or the solution: cached between frames
    qreal dpr = devicePixelRatioF();
    BackgroundKey key{m_document->solution().get(),
                      size(),
                      m_scale,
                      m_centre,
                      m_drawMode,
                      dpr,
                      m_showVakonomic,
                      m_style,
                      m_legendVisible};
    t_penScale = m_style.lineScale;
    if (key == m_backgroundKey && !m_background.isNull())
        return;
    m_backgroundKey = key;
    m_background = QPixmap(size() * dpr);
    m_background.setDevicePixelRatio(dpr);
    m_background.fill(Qt::white);
    QPainter p(&m_background);
    p.setRenderHint(QPainter::Antialiasing, true);
    paintGrid(p);
    if (m_document->solution()) {
        paintPath(p);
        paintLegend(p);
    }
}

void SceneCanvas::paintEvent(QPaintEvent*) {
    paintBackground();
    t_penScale = m_style.lineScale;
    QPainter p(this);
    p.drawPixmap(0, 0, m_background);
    p.setRenderHint(QPainter::Antialiasing, true);
    const auto& solution = m_document->solution();
    if (solution) {
        MotionSample now = solution->at(m_time);
        p.save();
        p.setClipRect(drawingArea());
        paintTrails(p, now);
        paintPinnedRuns(p, *PinSet::of(m_document), worldTransform(), m_time, QPointF(10, 42));
        const SystemSpec& spec = solution->scene().system;
        p.setTransform(worldTransform());
        // the translucent ghost on top, so that both stay visible where they overlap
        BodyLook look{m_style.body, m_style.bodyOpacity, m_style.lineScale};
        paintBody(p, spec, solution->system(), {now.x, now.y, now.phi}, m_style.controlled(), false,
                  look);
        paintBody(p, spec, solution->system(), {now.free.x, now.free.y, now.free.phi},
                  m_style.free(), true, look);
        if (m_showVakonomic)
            paintBody(p, spec, solution->system(), {now.vak.x, now.vak.y, now.vak.phi},
                      m_style.vakonomic(), true, look);
        p.restore();
        m_vectors.paint(p, solution, m_document->scene().vectors, now, worldTransform(), m_scale,
                        rect());
        paintTimeReadout(p, solution->tEnd());
    }
    if (m_drawMode)
        paintVertices(p);
    if (m_stroke.size() > 1) {
        QPolygonF line;
        for (QPointF w : m_stroke)
            line << toPixel(w);
        p.setPen(cosmetic(QColor(40, 40, 40), 2));
        p.drawPolyline(line);
    }
}

void SceneCanvas::paintTimeReadout(QPainter& p, double tEnd) const {
    QFont f = font();
    p.setPen(Qt::black);
    if (m_style.largeTime) {
        // presentation: the time large enough for the back of the room
        f.setPointSizeF(9 * m_style.lineScale * 2);
        f.setBold(true);
        p.setFont(f);
        const QString now = tr("t = %1 s").arg(m_time, 0, 'f', 2);
        QRectF band(10, 0, width() - 20, topBandPx());
        p.drawText(band, Qt::AlignLeft | Qt::AlignVCenter, now);
        double after =
            10 + p.fontMetrics().horizontalAdvance(now) + p.fontMetrics().averageCharWidth();
        f.setPointSizeF(9 * m_style.lineScale);
        f.setBold(false);
        p.setFont(f);
        p.drawText(band.adjusted(after - 10, 0, 0, 0), Qt::AlignLeft | Qt::AlignVCenter,
                   tr("of %1 s").arg(tEnd, 0, 'f', 2));
        return;
    }
    f.setPointSizeF(9 * m_style.lineScale);
    p.setFont(f);
    p.drawText(QRectF(8, 6, width() - 16, topBandPx()), Qt::AlignLeft,
               tr("t = %1 s of %2 s    scale %3 px/m")
                   .arg(m_time, 0, 'f', 2)
                   .arg(tEnd, 0, 'f', 2)
                   .arg(m_scale, 0, 'g', 3));
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

void SceneCanvas::paintVertices(QPainter& p) const {
    const auto points = m_dragVertex >= 0 ? m_editPoints : drawnPoints();
    if (m_dragVertex >= 0) {
        QPolygonF line;
        for (const auto& [x, y] : points)
            line << toPixel({x, y});
        p.setPen(cosmetic(QColor(60, 60, 60), 1, Qt::DashLine));
        p.drawPolyline(line);
    }
    p.setPen(cosmetic(QColor(60, 60, 60), 1));
    p.setBrush(QColor(255, 255, 255, 220));
    for (const auto& [x, y] : points) {
        QPointF c = toPixel({x, y});
        p.drawRect(QRectF(c.x() - 3, c.y() - 3, 6, 6));
    }
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
        if (points.size() >= 3)
            emit pathDrawn(points);
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
