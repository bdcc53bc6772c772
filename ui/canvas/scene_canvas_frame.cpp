#include "canvas/scene_canvas.h"

#include "canvas/legend_text.h"

#include "canvas/draw_tool.h"
#include "canvas/edit_points_tool.h"
#include "canvas/halo_text.h"
#include "canvas/measure_tool.h"
#include "canvas/pen_tool.h"
#include "canvas/pin_painter.h"
#include "canvas/plan_tool.h"
#include "canvas/trail_stroke.h"
#include "canvas/wheel_marks.h"
#include "document/pin_set.h"
#include "document/scene_document.h"
#include "scene/wheel_angles.h"

#include <QFontMetricsF>
#include <QPaintEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>

// the canvas's moving layer, painted every frame over the static one: trails, bodies, arrows
// and the time read-out
namespace chaplygin::ui {

std::vector<SceneCanvas::Trail> SceneCanvas::trails(const MotionSample& now) const {
    // the curves flattened at this scale, each up to now (docs/architecture.md, ui/: the desktop
    // application, Canvas): the controlled body runs along the path, up to its arc length
    const CanvasCurves& c = curves();
    QColor free = m_look.style.free();
    free.setAlpha(m_look.style.highContrast ? 255 : 150);
    const double w = m_look.style.trailWidth;
    std::vector<Trail> out;
    out.push_back({&c.free(),
                   m_time,
                   {now.free.x, now.free.y},
                   false,
                   m_look.style.pen(free, std::max(0.75 * w, 1.5), Qt::DashLine)});
    if (m_look.vakonomic)
        out.push_back(
            {&c.vakonomic(),
             m_time,
             {now.vak.x, now.vak.y},
             false,
             m_look.style.pen(m_look.style.vakonomic(), std::max(0.75 * w, 1.5), Qt::DashDotLine)});
    if (drawsOpenLoop())
        out.push_back(
            {&c.openLoop(),
             m_time,
             {now.pert.x, now.pert.y},
             false,
             m_look.style.pen(m_look.style.openLoop(), std::max(0.75 * w, 1.5), Qt::DotLine)});
    if (drawsClosedLoop())
        out.push_back({&c.closedLoop(),
                       m_time,
                       {now.fb.x, now.fb.y},
                       false,
                       m_look.style.pen(m_look.style.closedLoop(), std::max(0.75 * w, 1.5),
                                        Qt::DashDotDotLine)});
    // the controlled body's last, on top: where another trail starts along the path, the path
    // stays visible
    out.push_back({&c.path(),
                   now.s,
                   {now.x, now.y},
                   true,
                   m_look.style.pen(m_look.style.controlled().darker(150), w)});
    return out;
}

void SceneCanvas::paintTrails(QPainter& p, const MotionSample& now, const QRegion& area) const {
    const QTransform world = worldTransform();
    for (const Trail& trail : trails(now)) {
        const FlatCurve& curve = *trail.curve;
        QPolygonF line;
        const std::size_t n = curve.countUpTo(trail.limit);
        line.reserve(qsizetype(n) + 1);
        for (std::size_t i = 0; i < n; ++i)
            line << world.map(curve.points[i]);
        if (curve.reaches(trail.limit)) // a curve the budget ended does not jump to the body
            line << world.map(trail.end);
        // a frame repaints a small area: only the segments near it are stroked
        strokePolylineWithin(p, line, trail.pen, area);
    }
}

std::vector<QRectF> SceneCanvas::trailEndsBounds(const MotionSample& now, double from) const {
    const QTransform world = worldTransform();
    std::vector<QRectF> boxes;
    const double pad = 2 * std::max(m_look.style.trailWidth, 1.5) * m_look.style.lineScale + 3;
    // the controlled trail's parameter is the arc length: where the body was at `from`
    const double since = std::min(from, m_time);
    const double sinceS = since < m_time ? m_document->solution()->at(since).s : now.s;
    for (const Trail& trail : trails(now)) {
        const FlatCurve& curve = *trail.curve;
        QRectF box;
        auto point = [&](QPointF q) {
            QPointF c = world.map(q);
            QRectF r(c.x() - pad, c.y() - pad, 2 * pad, 2 * pad);
            box = box.isNull() ? r : box.united(r);
        };
        const std::size_t first = curve.countUpTo(trail.byArcLength ? sinceS : since);
        const std::size_t last = curve.countUpTo(trail.limit);
        for (std::size_t i = first > 0 ? first - 1 : 0; i < last; ++i)
            point(curve.points[i]);
        point(trail.end);
        boxes.push_back(box);
    }
    return boxes;
}

QRegion SceneCanvas::movingBounds(const Solution& solution, const MotionSample& now,
                                  double from) const {
    const QTransform world = worldTransform();
    const QRectF widget = QRectF(rect()).adjusted(-4, -4, 4, 4);
    QRegion region;
    bool finite = true;
    auto add = [&](const QRectF& r) {
        if (r.isNull())
            return;
        // only the widget is painted: a body far outside the view (a wild zoom) must not
        // overflow int
        if (!std::isfinite(r.x()) || !std::isfinite(r.y()) || !std::isfinite(r.width()) ||
            !std::isfinite(r.height())) {
            finite = false;
            return;
        }
        const QRectF seen = r.intersected(widget);
        if (!seen.isEmpty())
            region += seen.toAlignedRect().adjusted(-2, -2, 2, 2);
    };
    for (const QRectF& r : trailEndsBounds(now, from))
        add(r);
    const SystemSpec& spec = solution.scene().system;
    const BodyLook look = bodyLook();
    for (const DrawnBody& body : drawnBodies(now))
        add(BodySprites::pixelBounds(world, m_view.scale(), spec, solution.system(), body.pose,
                                     look));
    for (const QRectF& r :
         m_vectors.bounds(m_document->solution(), m_document->scene().vectors, now, world))
        add(r);
    return finite ? region : QRegion(rect());
}

std::vector<int> SceneCanvas::bodiesCrossing(const Solution& solution,
                                             const std::vector<QRectF>& boxes) const {
    constexpr int kSamples = 48;
    std::vector<int> crossed(boxes.size(), 0);
    const QTransform world = worldTransform();
    const SystemSpec& spec = solution.scene().system;
    const BodyLook look = bodyLook();
    for (int k = 0; k <= kSamples; ++k) {
        const MotionSample at = solution.at(solution.tEnd() * k / kSamples);
        for (const DrawnBody& drawn : drawnBodies(at)) {
            const QRectF body = BodySprites::pixelBounds(world, m_view.scale(), spec,
                                                         solution.system(), drawn.pose, look);
            for (std::size_t c = 0; c < boxes.size(); ++c)
                crossed[c] += body.intersects(boxes[c]) ? 1 : 0;
        }
    }
    return crossed;
}

void SceneCanvas::placeScaleBars(const Solution& solution) {
    const VectorOverlay& overlay = m_document->scene().vectors;
    const QRectF area = drawingArea();
    const QRect here = m_vectors.scaleBarsBounds(overlay, area, Qt::BottomRightCorner);
    if (here.isEmpty())
        return;
    const QTransform world = worldTransform();
    const ScaleBarsPlacement key{&solution,
                                 m_view.scale(),
                                 area,
                                 QPointF(std::floor(world.dx() * 4 / std::max(1.0, area.width())),
                                         std::floor(world.dy() * 4 / std::max(1.0, area.height()))),
                                 here.size(),
                                 m_look.vakonomic,
                                 drawsOpenLoop(),
                                 drawsClosedLoop()};
    if (!m_vectors.placeBarsAnew(key))
        return;
    // the bodies at 49 times of the run against each corner's box
    constexpr Qt::Corner kCorners[] = {Qt::BottomRightCorner, Qt::BottomLeftCorner,
                                       Qt::TopRightCorner};
    std::vector<QRectF> boxes;
    for (Qt::Corner corner : kCorners)
        boxes.push_back(QRectF(m_vectors.scaleBarsBounds(overlay, area, corner)));
    const std::vector<int> crossed = bodiesCrossing(solution, boxes);
    const auto best = std::min_element(crossed.begin(), crossed.end()) - crossed.begin();
    if (kCorners[best] != m_vectors.barsCorner()) {
        const QRect left = m_vectors.scaleBarsBounds(overlay, area);
        m_vectors.setBarsCorner(kCorners[best]);
        // the corner they leave, and the one they take where this paint does not reach
        update(QRegion(left) + m_vectors.scaleBarsBounds(overlay, area));
    }
}

QFont SceneCanvas::wheelInsetFont() const {
    QFont f = font();
    f.setPointSizeF(8.5 * m_look.style.lineScale);
    return f;
}

QRectF SceneCanvas::wheelInsetBounds(Qt::Corner corner) const {
    const auto& solution = m_document->solution();
    if (!m_look.style.wheelInset || !solution)
        return {};
    const int wheels = wheelAngles(solution->scene().system, 0, 0).wheels;
    const QSizeF size = wheelInsetLayout(wheels, m_look.style.lineScale, wheelInsetFont()).size;
    const QRectF area = drawingArea();
    const double margin = 8 * m_look.style.lineScale;
    if (size.isEmpty() || size.width() + 2 * margin > area.width() ||
        size.height() + 2 * margin > area.height())
        return {};
    const bool right = corner == Qt::TopRightCorner || corner == Qt::BottomRightCorner;
    const bool bottom = corner == Qt::BottomLeftCorner || corner == Qt::BottomRightCorner;
    const double x = right ? area.right() - margin - size.width() : area.left() + margin;
    const double y = bottom ? area.bottom() - margin - size.height() : area.top() + margin;
    return {QPointF(std::round(x), std::round(y)), size};
}

QRectF SceneCanvas::wheelInsetBounds() const {
    return wheelInsetBounds(m_insetCorner);
}

void SceneCanvas::placeWheelInset(const Solution& solution) {
    const QRectF here = wheelInsetBounds(Qt::BottomLeftCorner);
    if (here.isEmpty())
        return;
    const VectorOverlay& overlay = m_document->scene().vectors;
    const QRectF area = drawingArea();
    const bool barsShown = !m_vectors.scaleBarsBounds(overlay, area).isEmpty();
    const QTransform world = worldTransform();
    const WheelInsetPlacement key{
        &solution,
        m_view.scale(),
        area,
        QPointF(std::floor(world.dx() * 4 / std::max(1.0, area.width())),
                std::floor(world.dy() * 4 / std::max(1.0, area.height()))),
        here.size(),
        m_vectors.barsCorner(),
        barsShown};
    if (key == m_insetPlacedFor)
        return;
    m_insetPlacedFor = key;
    // the corners the scale bars leave, each scored by the bodies at 49 times of the run that
    // cross it, then by the path's points under it; the first of the least crossed
    std::vector<Qt::Corner> corners;
    std::vector<QRectF> boxes;
    for (Qt::Corner c : {Qt::BottomLeftCorner, Qt::TopRightCorner, Qt::BottomRightCorner})
        if (!barsShown || c != m_vectors.barsCorner()) {
            corners.push_back(c);
            boxes.push_back(wheelInsetBounds(c));
        }
    const std::vector<int> crossed = bodiesCrossing(solution, boxes);
    std::vector<std::pair<int, int>> score(corners.size());
    for (std::size_t c = 0; c < corners.size(); ++c) {
        const QRectF box = wheelInsetBounds(corners[c]);
        int under = 0;
        for (const QPointF& q : curves().path().points)
            under += box.contains(world.map(q)) ? 1 : 0;
        score[c] = {crossed[c], under};
    }
    const Qt::Corner best =
        corners[std::size_t(std::min_element(score.begin(), score.end()) - score.begin())];
    if (best != m_insetCorner) {
        const QRectF left = wheelInsetBounds();
        m_insetCorner = best;
        update(QRegion(left.toAlignedRect().adjusted(-2, -2, 2, 2)) +
               wheelInsetBounds().toAlignedRect().adjusted(-2, -2, 2, 2));
    }
}

void SceneCanvas::updateTrailLayer(const MotionSample& now, const QPixmap& base, QPoint origin) {
    const qreal dpr = base.devicePixelRatio();
    // the layer's extent in the widget's pixels
    const QRect extent(-origin, (QSizeF(base.size()) / dpr).toSize());
    const LayerCache::TrailUpdate update = m_layers.bringTrailLayerTo(base, m_time);
    QRegion area;
    if (update.anew) {
        area = extent;
    } else if (m_time > update.since) {
        for (const QRectF& r : trailEndsBounds(now, update.since)) {
            if (!std::isfinite(r.x()) || !std::isfinite(r.y()) || !std::isfinite(r.width()) ||
                !std::isfinite(r.height())) {
                area = extent;
                break;
            }
            area += r.intersected(QRectF(extent)).toAlignedRect();
        }
    }
    if (area.isEmpty())
        return;
    QPainter p(&m_layers.trailLayer());
    p.translate(origin);
    p.setClipRegion(area);
    // where the ends moved, the base's pixels first
    if (area != QRegion(extent)) {
        p.setCompositionMode(QPainter::CompositionMode_Source);
        for (const QRect& r : area)
            p.drawPixmap(QRectF(r), base,
                         QRectF(QPointF(r.topLeft() + origin) * dpr, QSizeF(r.size()) * dpr));
        p.setCompositionMode(QPainter::CompositionMode_SourceOver);
    }
    p.setRenderHint(QPainter::Antialiasing, true);
    paintTrails(p, now, area);
}

void SceneCanvas::updateMoving(double from, QPointF centre) {
    // only the moving parts when nothing else changed: the view (but for following the body by
    // whole pixels), the static layer, the pins (their runs move too), a stroke or a vertex
    // being drawn, a trail that shrinks
    const auto& solution = m_document->solution();
    bool steady = solution && from <= m_time && m_movingPainted && !m_tools.draw->active() &&
                  !m_tools.edit->active() && m_document->pins()->count() == 0;
    QPoint shift; // [px] how far the scene's pixels move
    if (steady && !m_view.follows()) {
        steady = m_layers.hasBackground(layerKey());
    } else if (steady) {
        LayerKey key = layerKey();
        key.centre = {};
        // the centre snaps to the pixel grid: the scene moves by whole pixels, y up
        const QPointF now = m_view.centre();
        const QPointF moved((centre.x() - now.x()) * m_view.scale(),
                            (now.y() - centre.y()) * m_view.scale());
        shift = moved.toPoint();
        steady = followsWithWorldLayer() && m_layers.hasWorldLayer(key) &&
                 std::abs(moved.x() - shift.x()) < 1e-6 && std::abs(moved.y() - shift.y()) < 1e-6;
    }
    if (!steady) {
        update();
        return;
    }
    QRegion dirty;
    if (!shift.isNull()) {
        // Qt moves the pixels and repaints what they uncover; the scale bars stay put, and
        // so do the rows at the area's edges, where the bands' antialiased lines reach in
        const QRect area = drawingArea().toAlignedRect();
        const QRect moving = area.adjusted(0, 3, 0, -3);
        scroll(shift.x(), shift.y(), moving);
        m_movingPainted->translate(shift);
        dirty += QRegion(area) - moving;
        dirty += m_vectors.scaleBarsBounds(m_document->scene().vectors, drawingArea());
    }
    dirty += *m_movingPainted;
    const MotionSample now = solution->at(m_time);
    dirty += movingBounds(*solution, now, from);
    // the edge markers where they were (and where scrolling moved them) and where they go
    dirty += m_edgeMarkers.painted();
    dirty += m_edgeMarkers.painted().translated(shift);
    for (const EdgeMarker& marker : edgeMarkersAt(now))
        dirty += marker.box.toAlignedRect().adjusted(-2, -2, 2, 2);
    dirty += QRect(0, 0, width(), topBandPx()); // the time read-out
    // the wheels' side view turns every frame; scrolling moved its pixels too
    const QRect inset = wheelInsetBounds().toAlignedRect().adjusted(-2, -2, 2, 2);
    dirty += inset;
    dirty += inset.translated(shift);
    update(dirty);
}

QFont SceneCanvas::edgeMarkerFont() const {
    QFont f = font();
    f.setPointSizeF(8.5 * m_look.style.lineScale);
    return f;
}

std::vector<EdgeMarker> SceneCanvas::edgeMarkersAt(const MotionSample& now) const {
    const auto& solution = m_document->solution();
    if (!solution)
        return {};
    const SystemSpec& spec = solution->scene().system;
    const QTransform world = worldTransform();
    const BodyLook look = bodyLook();
    std::vector<ShownBody> shown;
    for (const DrawnBody& body : drawnBodies(now)) {
        const BodyPose& pose = body.pose;
        const QRectF box = look.display == BodyDisplay::Marker
                               ? QRectF(pose.x, pose.y, 0, 0)
                               : bodyBounds(spec, solution->system(), pose);
        shown.push_back(
            {body.colour, QPointF(pose.x, pose.y),
             BodySprites::pixelBounds(world, m_view.scale(), spec, solution->system(), pose, look),
             box});
    }
    // a body in the time line's band is in view: the scene is drawn there too
    return layoutEdgeMarkers(shown, drawingArea(), sceneArea(), world, edgeMarkerFont(),
                             m_look.style.lineScale);
}

QPointF SceneCanvas::pinKeyOrigin() const {
    QPointF origin(10, 42);
    // below the draw-mode hint, which shares the corner under the time line
    const QRectF hint = drawHintBounds();
    const QRectF key = chaplygin::ui::pinKeyBounds(*m_document->pins(), {}, font());
    if (!hint.isEmpty() && !key.isEmpty())
        origin.setY(std::max(origin.y(), hint.bottom() + 4 - key.top()));
    return origin;
}

QRectF SceneCanvas::pinKeyBounds() const {
    return chaplygin::ui::pinKeyBounds(*m_document->pins(), pinKeyOrigin(), font());
}

void SceneCanvas::paintEvent(QPaintEvent* e) {
    QPainter p(this);
    const auto& solution = m_document->solution();
    std::optional<MotionSample> now;
    if (solution)
        now = solution->at(m_time);
    paintStaticLayer(p, e->region(), now ? &*now : nullptr);
    p.setRenderHint(QPainter::Antialiasing, true);
    if (solution) {
        p.save();
        // up to the canvas's top, under the read-out: only the legend's strip is not the scene's
        p.setClipRect(sceneArea());
        curves(); // at this scale, for the pins too
        paintPinnedRuns(p, *m_document->pins(), m_curves, worldTransform(), m_time, pinKeyOrigin());
        const SystemSpec& spec = solution->scene().system;
        const QTransform world = worldTransform();
        // the ghosts first and the controlled body, the lesson's, on top of them: its fill is
        // nearly opaque, and where the translucent ghosts lay over it its colour was lost
        const BodyLook look = bodyLook();
        // the scale bars under the bodies: a body crossing their corner hides them, not it
        placeScaleBars(*solution);
        m_vectors.paintScaleBars(p, solution, m_document->scene().vectors, m_view.scale(),
                                 drawingArea(), e->region());
        const std::vector<DrawnBody> bodies = drawnBodies(*now);
        bool bodiesDrawn = true;
        for (auto body = bodies.rbegin(); body != bodies.rend(); ++body)
            bodiesDrawn &= m_bodies.paint(p, world, m_view.scale(), spec, solution->system(),
                                          body->pose, body->colour, body->ghost, look);
        paintPathOverBodies(p, *now);
        // the controlled body's wheels rolling: stripes on their treads, a side view in a corner
        const WheelAngles angles = wheelAnglesAt(*solution, *now);
        if (look.display != BodyDisplay::Marker && angles.wheels > 0) {
            p.save();
            QTransform pose;
            pose.translate(now->x, now->y);
            pose.rotate(now->phi * 180.0 / M_PI);
            p.setTransform(pose * world);
            paintTreadStripes(p, spec, angles, m_look.style.controlled().darker(140),
                              m_look.style.lineScale);
            p.restore();
        }
        // the arrows end at the scene's edge, never over the legend under it
        m_vectors.paint(p, solution, m_document->scene().vectors, *now, worldTransform());
        p.restore();
        if (angles.wheels > 0 && m_look.style.wheelInset) {
            placeWheelInset(*solution);
            const QRectF inset = wheelInsetBounds();
            if (!inset.isEmpty())
                paintWheelInset(p, inset, angles, m_look.style.controlled().darker(140),
                                m_look.style.lineScale, wheelInsetFont());
        }
        // where the bodies out of view went
        m_edgeMarkers.paint(p, edgeMarkersAt(*now), edgeMarkerFont(), m_look.style.lineScale);
        // a planned motion played: its time along it and its arrival (docs/physics.md §10)
        const int played =
            m_tools.planMode && m_tools.plan->playTime() >= 0 ? m_tools.plan->chosen() : -1;
        if (played >= 0)
            paintTimeReadout(p, m_tools.plan->playTime(),
                             m_tools.plan->planned().geodesics[std::size_t(played)].t, bodiesDrawn);
        else
            paintTimeReadout(p, m_time, solution->tEnd(), bodiesDrawn);
        m_movingPainted = movingBounds(*solution, *now, m_time);
    } else {
        m_movingPainted = {};
        m_edgeMarkers.clear();
    }
    // what the gestures show: a push being dragged, the drawn path's points, a stroke
    m_tools.push->paint(p);
    if (m_tools.planMode) {
        p.save();
        p.setClipRect(drawingArea());
        m_tools.plan->paint(p);
        paintPlanReadout(p);
        p.restore();
    }
    if (m_tools.drawMode && !m_tools.planMode) {
        m_tools.edit->paint(p);
        m_tools.draw->paint(p);
    }
    // the pen's marks over the scene
    m_tools.pen->paint(p);
    // the ruler, the protractor and the probe over everything, in the widget's font
    p.setFont(font());
    m_tools.measure->paint(p);
}

double SceneCanvas::planReadoutHeight() const {
    if (!m_tools.planMode)
        return 0;
    QFont font = this->font();
    font.setPointSizeF(font.pointSizeF() * m_look.style.lineScale);
    const QFontMetricsF metrics(font);
    const int lines = m_look.style.largeTime ? 1 : 2;
    return 6 * m_look.style.lineScale + lines * (metrics.lineSpacing() + 4);
}

void SceneCanvas::paintPlanReadout(QPainter& p) const {
    // the chosen motion's family, k, Psi0, lambda(0), t and cut time, and how to use the tool,
    // in the corner under the time line
    QFont font = this->font();
    font.setPointSizeF(font.pointSizeF() * m_look.style.lineScale);
    p.setFont(font);
    const QFontMetricsF metrics(font);
    QStringList lines{m_tools.plan->chosenSummary()};
    // presenting, the chosen motion alone: the drawing keeps the room
    if (!m_look.style.largeTime)
        lines << tr("Plan: drag the target's dot or its heading's handle (Shift snaps), or the "
                    "start; click a motion to choose it");
    const QRectF area = drawingArea();
    QPointF at = area.topLeft() + QPointF(10, 6 * m_look.style.lineScale + metrics.ascent());
    for (const QString& line : lines) {
        const QString shown = metrics.elidedText(line, Qt::ElideRight, area.width() - 24);
        const QRectF box = metrics.boundingRect(shown).translated(at).adjusted(-4, -2, 4, 2);
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(255, 255, 255, 215));
        p.drawRect(box);
        p.setPen(Qt::black);
        p.drawText(at, shown);
        at.ry() += metrics.lineSpacing() + 4;
    }
}

void SceneCanvas::paintTimeReadout(QPainter& p, double t, double tEnd, bool bodiesDrawn) const {
    QFont f = font();
    const double halo = std::max(1.0, std::round(m_look.style.lineScale));
    if (m_look.style.largeTime) {
        // presentation: the time large enough for the back of the room
        f.setPointSizeF(9 * m_look.style.lineScale * 2);
        f.setBold(true);
        p.setFont(f);
        const QString now = tr("t = %1 s").arg(t, 0, 'f', 2);
        QRectF band(10, 0, width() - 20, topBandPx());
        drawHaloText(p, band, Qt::AlignLeft | Qt::AlignVCenter, now, halo);
        double after =
            10 + p.fontMetrics().horizontalAdvance(now) + p.fontMetrics().averageCharWidth();
        f.setPointSizeF(9 * m_look.style.lineScale);
        f.setBold(false);
        p.setFont(f);
        drawHaloText(p, band.adjusted(after - 10, 0, 0, 0), Qt::AlignLeft | Qt::AlignVCenter,
                     tr("of %1 s").arg(tEnd, 0, 'f', 2), halo);
        return;
    }
    f.setPointSizeF(9 * m_look.style.lineScale);
    p.setFont(f);
    const QString full = tr("t = %1 s of %2 s    scale %3 px/m")
                             .arg(t, 0, 'f', 2)
                             .arg(tEnd, 0, 'f', 2)
                             .arg(m_view.scale(), 0, 'g', 3);
    const QString time =
        tr("t = %1 s").arg(t, 0, 'f', 2) + QLatin1Char(' ') + tr("of %1 s").arg(tEnd, 0, 'f', 2);
    // said, not hidden: a curve too dense for a frame at this zoom ends where its budget did,
    // and a body larger than BodySprites draws is left out
    QString part = m_curves.truncated()
                       ? QStringLiteral("    ") + tr("curves drawn in part at this zoom")
                       : QString();
    if (!bodiesDrawn)
        part += QStringLiteral("    ") + tr("a body too large to draw at this zoom");
    // on a narrow canvas the longest form that ends before the scale bar's label
    const double room = scaleBarLeft() - 8 - 12 * m_look.style.lineScale;
    const QString readout = fittingLegendText(
        f, this, room, {full + part, time + part, full, time, tr("t = %1 s").arg(t, 0, 'f', 2)});
    drawHaloText(p, QRectF(8, 6, width() - 16, topBandPx()), Qt::AlignLeft, readout, halo);
}

} // namespace chaplygin::ui
