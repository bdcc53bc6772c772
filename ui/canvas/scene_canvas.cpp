#include "canvas/scene_canvas.h"

#include "canvas/body_painter.h"
#include "canvas/draw_tool.h"
#include "canvas/edit_points_tool.h"
#include "canvas/measure_tool.h"
#include "canvas/pan_tool.h"
#include "canvas/pen_tool.h"
#include "canvas/plan_tool.h"
#include "document/scene_document.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>

#include <QLineF>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace chaplygin::ui {

namespace {

constexpr int kTopPx = 26, kLegendPx = 78; // the time line and the legend, before the scale

} // namespace

SceneCanvas::SceneCanvas(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_view(*this) {
    m_tools.draw = new DrawTool(m_view, m_look.style, this);
    m_tools.edit = new EditPointsTool(
        m_view, m_look.style, [this] { return drawnPoints(); }, this);
    m_tools.push = new PushTool(
        m_view, m_look.style, [this](QPointF p) { return grabAt(p); }, this);
    m_tools.plan = new PlanTool(m_view, m_look.style, document, this);
    m_tools.measure = new MeasureTool(
        m_view, m_look.style, document,
        [this] {
            return MeasureTool::Shown{m_time,          m_look.vakonomic,
                                      m_look.openLoop, m_look.closedLoop,
                                      &curves(),       drawingArea()};
        },
        this);
    m_tools.pen = new PenTool(
        m_view, m_look.style, [this] { return sceneArea(); }, this);
    m_tools.pan = new PanTool(m_view, this);
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
    for (CanvasTool* tool : m_tools.all())
        connect(tool, &CanvasTool::changed, this, qOverload<>(&QWidget::update));
    // a stroke drawn or a point moved keeps the view where the path stays in it
    connect(m_tools.draw, &DrawTool::pathDrawn, this, [this](const auto& points) {
        m_view.setKeepViewForNextPath(true);
        emit pathDrawn(points);
    });
    connect(m_tools.edit, &EditPointsTool::pointsEdited, this, [this](const auto& points) {
        m_view.setKeepViewForNextPath(true);
        emit pointsEdited(points);
    });
    connect(m_tools.push, &PushTool::pushDragged, this, &SceneCanvas::pushDragged);
    connect(document, &SceneDocument::solutionChanged, m_tools.plan, [this] {
        if (m_tools.planMode)
            m_tools.plan->syncFromDocument();
    });
    connect(m_tools.pan, &PanTool::panned, this, [this] {
        setFollowBody(false);
        update();
    });
}

const CanvasCurves& SceneCanvas::curves() const {
    m_curves.update(m_document->solution(), m_view.scale() * devicePixelRatioF(),
                    m_view.transform().inverted().mapRect(QRectF(rect())));
    return m_curves;
}

QPointF SceneCanvas::toPixel(QPointF world) const {
    return m_view.toPixel(world);
}

QPointF SceneCanvas::toWorld(QPointF pixel) const {
    return m_view.toWorld(pixel);
}

void SceneCanvas::onSolutionChanged() {
    // a new path is fitted, but a stroke the user drew or a point moved keeps the view where
    // the path stays in it; a parameter change keeps the view steady while a slider moves
    if (m_document->solution()->path() != m_view.fittedPath()) {
        if (m_view.keepsViewForNextPath())
            keepPathInView();
        else if (m_view.autoFit())
            m_view.fitsEverything() ? fitEverything() : fitScene();
        m_view.setKeepViewForNextPath(false);
    }
    if (m_view.follows())
        centreOnBody();
    update();
}

void SceneCanvas::setTime(double t) {
    double from = m_time;
    QPointF centre = m_view.centre();
    m_time = t;
    if (m_view.follows())
        centreOnBody();
    updateMoving(from, centre);
}

void SceneCanvas::centreOnBody() {
    const auto& solution = m_document->solution();
    if (!solution)
        return;
    MotionSample m = solution->at(std::clamp(m_time, 0.0, solution->tEnd()));
    m_view.centreOn({m.x, m.y});
}

BodyDisplay SceneCanvas::shownBodyDisplay() const {
    const auto& solution = m_document->solution();
    if (!solution)
        return m_look.style.body == BodyDisplay::Automatic ? BodyDisplay::ToScale
                                                           : m_look.style.body;
    return ui::shownBodyDisplay(m_look.style.body, solution->scene().system, solution->system(),
                                pathBounds());
}

BodyLook SceneCanvas::bodyLook() const {
    return {shownBodyDisplay(), m_look.style.bodyOpacity, m_look.style.lineScale};
}

std::vector<SceneCanvas::DrawnBody> SceneCanvas::drawnBodies(const MotionSample& now) const {
    std::vector<DrawnBody> out{{{now.x, now.y, now.phi}, m_look.style.controlled(), false},
                               {{now.free.x, now.free.y, now.free.phi}, m_look.style.free(), true}};
    if (m_look.vakonomic)
        out.push_back({{now.vak.x, now.vak.y, now.vak.phi}, m_look.style.vakonomic(), true});
    if (drawsOpenLoop())
        out.push_back({{now.pert.x, now.pert.y, now.pert.phi}, m_look.style.openLoop(), true});
    if (drawsClosedLoop())
        out.push_back({{now.fb.x, now.fb.y, now.fb.phi}, m_look.style.closedLoop(), true});
    return out;
}

int SceneCanvas::topBandPx() const {
    return int(std::lround(kTopPx * m_look.style.lineScale * (m_look.style.largeTime ? 1.7 : 1.0)));
}

bool SceneCanvas::compactLegend() const {
    // presenting without pushed bodies: the path and the vakonomic body in a second column
    return m_look.style.largeTime && !drawsOpenLoop() && !drawsClosedLoop();
}

int SceneCanvas::legendBandPx() const {
    if (!m_look.legend)
        return 0;
    // four rows of 16 px, or two in the compact legend, and 14 px around them
    return int(
        std::lround((compactLegend() ? kLegendPx - 32 : kLegendPx) * m_look.style.lineScale));
}

QRectF SceneCanvas::drawingArea() const {
    return QRectF(0, topBandPx(), width(), std::max(height() - topBandPx() - legendBandPx(), 0));
}

QRectF SceneCanvas::sceneArea() const {
    return QRectF(0, 0, width(), std::max(height() - legendBandPx(), 0));
}

void SceneCanvas::setCanvasStyle(const CanvasStyle& style) {
    m_look.style = style.sanitized();
    m_vectors.setLineScale(m_look.style.lineScale);
    refit();
    update();
}

CanvasLook SceneCanvas::look() const {
    return m_look;
}

void SceneCanvas::setLook(const CanvasLook& look) {
    m_look.vakonomic = look.vakonomic;
    m_look.openLoop = look.openLoop;
    m_look.closedLoop = look.closedLoop;
    m_look.legend = look.legend;
    setCanvasStyle(look.style);
}

void SceneCanvas::setLegendVisible(bool visible) {
    m_look.legend = visible;
    refit();
    update();
}

void SceneCanvas::setFollowBody(bool follow) {
    if (!m_view.setFollows(follow))
        return;
    if (follow) {
        m_view.setFollowScale(readableBodyScale());
        centreOnBody();
    }
    emit followBodyChanged(follow);
    update();
}

void SceneCanvas::setFollowing(bool on) {
    if (on) {
        setFollowBody(true);
        return;
    }
    if (!m_view.returnFromFollow())
        return;
    if (m_view.autoFit()) // the fit, for the canvas's size now
        m_view.fitsEverything() ? fitEverything() : fitScene();
    emit followBodyChanged(false);
    update();
}

void SceneCanvas::setDrawMode(bool on) {
    m_tools.drawMode = on;
    m_tools.draw->cancel();
    if (on) {
        setPlanMode(false);
        setMeasureMode(false);
        setPenMode(false);
    }
    setCursor(on ? Qt::CrossCursor : Qt::ArrowCursor);
    update();
}

void SceneCanvas::setPlanMode(bool on) {
    if (on == m_tools.planMode)
        return;
    m_tools.planMode = on;
    m_tools.plan->cancel();
    m_tools.plan->stopPlaying();
    if (on) {
        setMeasureMode(false);
        setPenMode(false);
        m_tools.draw->cancel();
        m_tools.edit->cancel();
        m_tools.plan->syncFromDocument();
        // the plan in view, unless the user chose the view
        if (m_view.autoFit() && !m_view.follows())
            fitScene();
    }
    updateCursor();
    update();
    emit planModeChanged(on);
}

bool SceneCanvas::measureMode() const {
    return m_tools.measureMode();
}

void SceneCanvas::setMeasureMode(bool on) {
    if (on == measureMode())
        return;
    if (on) {
        setPlanMode(false);
        setPenMode(false);
    }
    m_tools.measure->setEnabled(on);
    // the probe follows the mouse without a button
    setMouseTracking(on);
    updateCursor();
    update();
    emit measureModeChanged(on);
}

bool SceneCanvas::penMode() const {
    return m_tools.penMode();
}

void SceneCanvas::setPenMode(bool on) {
    if (on == penMode())
        return;
    if (on) {
        setPlanMode(false);
        setMeasureMode(false);
    }
    m_tools.pen->setEnabled(on);
    updateCursor();
    update();
    emit penModeChanged(on);
}

void SceneCanvas::updateCursor() {
    for (CanvasTool* tool : m_tools.all())
        if (tool->active()) {
            setCursor(tool->cursor());
            return;
        }
    setCursor(m_tools.drawMode || measureMode() || penMode() ? Qt::CrossCursor : Qt::ArrowCursor);
}

void SceneCanvas::setShowVakonomic(bool show) {
    m_look.vakonomic = show;
    update();
}

void SceneCanvas::setShowOpenLoop(bool show) {
    m_look.openLoop = show;
    update();
}

void SceneCanvas::setShowClosedLoop(bool show) {
    m_look.closedLoop = show;
    update();
}

bool SceneCanvas::drawsOpenLoop() const {
    return m_look.openLoop && m_document->series().perturbed;
}

bool SceneCanvas::drawsClosedLoop() const {
    return m_look.closedLoop && m_document->series().perturbed;
}

PushTool::Grab SceneCanvas::grabAt(QPointF pixel) const {
    const auto& solution = m_document->solution();
    if (!solution)
        return {};
    const double t = std::clamp(m_time, 0.0, solution->tEnd());
    const MotionSample m = solution->at(t);
    const BodyLook look = bodyLook();
    const QRectF box =
        BodySprites::pixelBounds(worldTransform(), m_view.scale(), solution->scene().system,
                                 solution->system(), {m.x, m.y, m.phi}, look);
    // the body's box, at least a finger's width around P
    const QPointF p = toPixel({m.x, m.y});
    if (!box.contains(pixel) && QLineF(p, pixel).length() > 12 * m_look.style.lineScale)
        return {};
    return {.onBody = true, .t = t, .phi = m.phi};
}

void SceneCanvas::zoomBy(double factor) {
    if (m_view.follows()) {
        m_view.zoomFollow(factor);
        centreOnBody();
    } else {
        m_view.zoomBy(factor);
    }
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

void SceneCanvas::wheelEvent(QWheelEvent* e) {
    // zoom about the point under the cursor; following, the follow zoom about the body
    const double factor = std::pow(1.0015, e->angleDelta().y());
    if (m_view.follows()) {
        zoomBy(factor);
        e->accept();
        return;
    }
    m_view.zoomAbout(e->position(), factor);
    update();
    e->accept();
}

void SceneCanvas::mousePressEvent(QMouseEvent* e) {
    // a click on a body's edge marker frames that body
    if (e->button() == Qt::LeftButton)
        for (const EdgeMarker& marker : m_edgeMarkers.markers())
            if (marker.box.contains(e->position())) {
                frameBody(marker.worldBox);
                e->accept();
                return;
            }
    for (CanvasTool* tool : m_tools.reachable())
        if (tool->press(*e))
            break;
    updateCursor();
    e->accept();
}

void SceneCanvas::mouseMoveEvent(QMouseEvent* e) {
    // the gestures under way in the order of their priority: editing a point, a stroke, a push,
    // panning
    for (CanvasTool* tool : m_tools.all())
        if (tool->active() && tool->move(*e))
            return;
    // no gesture under way: the mode's tools may show something where the mouse is
    if (e->buttons() == Qt::NoButton)
        for (CanvasTool* tool : m_tools.reachable())
            if (tool->hover(*e))
                return;
}

void SceneCanvas::mouseReleaseEvent(QMouseEvent* e) {
    for (CanvasTool* tool : m_tools.all())
        if (tool->active())
            tool->release(*e);
    updateCursor();
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
        setFollowing(!m_view.follows());
        break;
    case Qt::Key_L:
        setLegendVisible(!m_look.legend);
        break;
    case Qt::Key_M:
        setMeasureMode(!measureMode());
        break;
    case Qt::Key_P:
        setPenMode(!penMode());
        break;
    case Qt::Key_A:
    case Qt::Key_C:
    case Qt::Key_E:
        // the pen's arrows, its next colour, and clearing its marks
        if (!penMode())
            QWidget::keyPressEvent(e);
        else if (e->key() == Qt::Key_A)
            m_tools.pen->setKind(m_tools.pen->kind() == MarkKind::Arrow ? MarkKind::Freehand
                                                                        : MarkKind::Arrow);
        else if (e->key() == Qt::Key_C)
            m_tools.pen->nextColour();
        else
            m_tools.pen->clear();
        break;
    case Qt::Key_Escape:
    case Qt::Key_Delete:
    case Qt::Key_Backspace:
        // forget the pen's marks, or what was measured
        if (penMode() && e->key() == Qt::Key_Delete)
            m_tools.pen->clear();
        else if (measureMode())
            m_tools.measure->clear();
        else
            QWidget::keyPressEvent(e);
        break;
    case Qt::Key_Left:
    case Qt::Key_Right:
    case Qt::Key_Up:
    case Qt::Key_Down: {
        // arrows pan by a tenth of the view
        double dx = e->key() == Qt::Key_Left ? -1 : e->key() == Qt::Key_Right ? 1 : 0;
        double dy = e->key() == Qt::Key_Down ? -1 : e->key() == Qt::Key_Up ? 1 : 0;
        m_view.moveCentre(QPointF(dx * width(), dy * height()) * (0.1 / m_view.scale()));
        setFollowBody(false);
        update();
        break;
    }
    default:
        QWidget::keyPressEvent(e);
    }
}

} // namespace chaplygin::ui
