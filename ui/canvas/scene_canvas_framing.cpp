// The canvas's framing: the path's, the scene's and the bodies' boxes, and the views that frame
// them (the two fits, a body framed, the view kept on the path, a readable zoom).
#include "canvas/scene_canvas.h"

#include "canvas/body_painter.h"
#include "canvas/plan_tool.h"
#include "document/scene_document.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace chaplygin::ui {

QRectF SceneCanvas::pathBounds() const {
    const auto& solution = m_document->solution();
    if (!solution)
        return {};
    if (m_pathBounds.of == solution.get())
        return m_pathBounds.box;
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
    m_pathBounds = {solution.get(),
                    x0 <= x1 && y0 <= y1 ? QRectF(QPointF(x0, y0), QPointF(x1, y1)) : QRectF()};
    return m_pathBounds.box;
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
    if (m_look.vakonomic)
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

std::optional<QRectF> SceneCanvas::bodiesBounds() const {
    const auto& solution = m_document->solution();
    if (!solution)
        return {};
    const MotionSample now = solution->at(std::clamp(m_time, 0.0, solution->tEnd()));
    const bool marker = shownBodyDisplay() == BodyDisplay::Marker;
    std::optional<QRectF> box;
    for (const DrawnBody& body : drawnBodies(now)) {
        const BodyPose& pose = body.pose;
        if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.phi))
            continue;
        const QRectF r = marker ? QRectF(pose.x, pose.y, 0, 0)
                                : bodyBounds(solution->scene().system, solution->system(), pose);
        // by the corners: united() would drop a box of no size (a marker's point)
        box = box ? QRectF(QPointF(std::min(box->left(), r.left()), std::min(box->top(), r.top())),
                           QPointF(std::max(box->right(), r.right()),
                                   std::max(box->bottom(), r.bottom())))
                  : r;
    }
    return box;
}

void SceneCanvas::frame(const QRectF& box, double margin, double minScale, double maxScale) {
    // the scene goes between the time line at the top and the legend at the bottom
    m_view.frame(box, drawingArea().adjusted(0, planReadoutHeight(), 0, 0), margin, minScale,
                 maxScale);
    m_view.setFittedPath(m_document->solution()->path());
    setFollowBody(false);
    update();
}

void SceneCanvas::fitScene() {
    const auto& solution = m_document->solution();
    // in plan mode the plan's start, target and tracks too
    const QRectF path =
        m_tools.planMode ? pathBounds().united(m_tools.plan->worldBounds()) : pathBounds();
    if (!solution || path.isNull())
        return;
    m_view.setFitsEverything(false);
    // the controlled body around the path: its extent [m] to scale or as an outline, the
    // marker's pixels
    const bool marker = shownBodyDisplay() == BodyDisplay::Marker;
    const double body = marker ? 0 : bodyExtent(solution->scene().system, solution->system());
    const double markerPx = marker ? 2.5 * kMarkerRadiusPx * m_look.style.lineScale : 0;
    const QRectF area = drawingArea();
    const double w = std::max(area.width(), 100.0), h = std::max(area.height(), 100.0);
    // a margin of 5 % of the drawing area on each side
    const double margin = std::max(0.05 * std::min(w, h), markerPx);
    // a large body may reach out of the view, but the path fills at least 80 % of the area in
    // the direction that limits it
    const double pathFill =
        std::min(w / std::max(path.width(), 1e-9), h / std::max(path.height(), 1e-9));
    frame(path.adjusted(-body, -body, body, body), margin, 0.8 * pathFill);
    // but the bodies shown now are not cut: where one would be, the path and the bodies
    const std::optional<QRectF> bodies = bodiesBounds();
    if (!bodies)
        return;
    const QRectF room = drawingArea().adjusted(0, planReadoutHeight(), 0, 0);
    const QRectF shown =
        QRectF(toPixel(bodies->topLeft()), toPixel(bodies->bottomRight())).normalized();
    if (room.contains(shown.adjusted(-markerPx, -markerPx, markerPx, markerPx)))
        return;
    // united() would drop a box of no size (the markers' points)
    const QRectF lesson(
        QPointF(std::min(path.left(), bodies->left()), std::min(path.top(), bodies->top())),
        QPointF(std::max(path.right(), bodies->right()),
                std::max(path.bottom(), bodies->bottom())));
    // centred on them at the path's scale where they fit at it, else smaller
    frame(lesson, margin, 0, m_view.scale());
}

void SceneCanvas::fitEverything() {
    const auto& solution = m_document->solution();
    const QRectF box = sceneBounds();
    if (!solution || box.isNull())
        return;
    m_view.setFitsEverything(true);
    const QRectF area = drawingArea();
    frame(box, 0.025 * std::min(std::max(area.width(), 100.0), std::max(area.height(), 100.0)), 0);
}

void SceneCanvas::frameBody(const QRectF& box) {
    // what the view shows now and the body: the view zooms out (and pans) to include it
    const QRectF area = drawingArea();
    const QRectF shown = m_view.transform().inverted().mapRect(area);
    const QRectF both(
        QPointF(std::min(shown.left(), box.left()), std::min(shown.top(), box.top())),
        QPointF(std::max(shown.right(), box.right()), std::max(shown.bottom(), box.bottom())));
    const double markerPx = shownBodyDisplay() == BodyDisplay::Marker
                                ? 2.5 * kMarkerRadiusPx * m_look.style.lineScale
                                : 0;
    const double w = std::max(area.width(), 100.0), h = std::max(area.height(), 100.0);
    frame(both, std::max(0.05 * std::min(w, h), markerPx), 0);
    m_view.setAutoFit(false); // the user's view: a resize does not refit it
}

void SceneCanvas::refit() {
    if (m_view.follows()) {
        m_view.setFollowScale(readableBodyScale());
        centreOnBody();
    } else if (m_view.autoFit()) {
        m_view.fitsEverything() ? fitEverything() : fitScene();
    }
}

void SceneCanvas::keepPathInView() {
    const auto& solution = m_document->solution();
    const QRectF path = pathBounds();
    if (!solution || path.isNull())
        return;
    m_view.setFittedPath(solution->path());
    const QRectF pixels = QRectF(toPixel(path.topLeft()), toPixel(path.bottomRight())).normalized();
    if (m_view.follows() || drawingArea().adjusted(-1, -1, 1, 1).contains(pixels)) {
        m_view.setAutoFit(false); // the view the user drew in: a resize does not refit it either
        update();
        return;
    }
    fitScene();
}

double SceneCanvas::readableBodyScale() const {
    const auto& solution = m_document->solution();
    if (!solution)
        return 0;
    const double body = 2 * bodyExtent(solution->scene().system, solution->system());
    const QRectF area = drawingArea();
    const double side = std::max(std::min(area.width(), area.height()), 100.0);
    return body > 0 && std::isfinite(body) ? kFollowBodyPart * side / body : 0;
}

} // namespace chaplygin::ui
