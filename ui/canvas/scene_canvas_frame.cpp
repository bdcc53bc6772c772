#include "canvas/scene_canvas.h"

#include "canvas/masked_layer.h"
#include "canvas/pin_painter.h"
#include "canvas/trail_stroke.h"
#include "document/pin_set.h"
#include "document/scene_document.h"

#include <QPaintEvent>
#include <QPainter>
#include <QPainterPath>
#include <QPainterPathStroker>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

// the canvas's moving layer, painted every frame over the static one: trails, bodies, arrows
// and the time read-out
namespace chaplygin::ui {

std::vector<SceneCanvas::Trail> SceneCanvas::trails(const MotionSample& now) const {
    // the curves flattened at this scale, each up to now (docs/architecture.md, ui/: the desktop
    // application, Canvas): the controlled body runs along the path, up to its arc length
    const CanvasCurves& c = curves();
    QColor free = m_style.free();
    free.setAlpha(m_style.highContrast ? 255 : 150);
    const double w = m_style.trailWidth;
    std::vector<Trail> out;
    out.push_back({&c.free(),
                   m_time,
                   {now.free.x, now.free.y},
                   false,
                   m_style.pen(free, std::max(0.75 * w, 1.5), Qt::DashLine)});
    if (m_showVakonomic)
        out.push_back({&c.vakonomic(),
                       m_time,
                       {now.vak.x, now.vak.y},
                       false,
                       m_style.pen(m_style.vakonomic(), std::max(0.75 * w, 1.5), Qt::DashDotLine)});
    if (drawsOpenLoop())
        out.push_back({&c.openLoop(),
                       m_time,
                       {now.pert.x, now.pert.y},
                       false,
                       m_style.pen(m_style.openLoop(), std::max(0.75 * w, 1.5), Qt::DotLine)});
    if (drawsClosedLoop())
        out.push_back(
            {&c.closedLoop(),
             m_time,
             {now.fb.x, now.fb.y},
             false,
             m_style.pen(m_style.closedLoop(), std::max(0.75 * w, 1.5), Qt::DashDotDotLine)});
    // the controlled body's last, on top: where another trail starts along the path, the path
    // stays visible
    out.push_back(
        {&c.path(), now.s, {now.x, now.y}, true, m_style.pen(m_style.controlled().darker(150), w)});
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
        line << world.map(trail.end);
        // a frame repaints a small area: only the segments near it are stroked
        strokePolylineWithin(p, line, trail.pen, area);
    }
}

std::vector<QRectF> SceneCanvas::trailEndsBounds(const MotionSample& now, double from) const {
    const QTransform world = worldTransform();
    std::vector<QRectF> boxes;
    const double pad = 2 * std::max(m_style.trailWidth, 1.5) * m_style.lineScale + 3;
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

namespace {

// f(x, y, phi) for each body the canvas shows at `now`: the controlled and the free body, and the
// vakonomic and pushed ones when they are drawn
template <class F>
void forEachShownPose(const MotionSample& now, bool vakonomic, bool openLoop, bool closedLoop,
                      F&& f) {
    f(now.x, now.y, now.phi);
    f(now.free.x, now.free.y, now.free.phi);
    if (vakonomic)
        f(now.vak.x, now.vak.y, now.vak.phi);
    if (openLoop)
        f(now.pert.x, now.pert.y, now.pert.phi);
    if (closedLoop)
        f(now.fb.x, now.fb.y, now.fb.phi);
}

// `to` becomes an RGB32 copy of `from`'s pixels, in its own memory when that has the size (a
// new image at every zoom step would cost its pages' first touch)
void copyPixels(const QImage& from, QImage& to) {
    const QImage source =
        from.format() == QImage::Format_RGB32 ? from : from.convertToFormat(QImage::Format_RGB32);
    if (to.size() != source.size() || to.format() != QImage::Format_RGB32)
        to = QImage(source.size(), QImage::Format_RGB32);
    const auto bytes = std::size_t(std::min(to.bytesPerLine(), source.bytesPerLine()));
    for (int y = 0; y < source.height(); ++y)
        std::memcpy(to.scanLine(y), source.constScanLine(y), bytes);
}

} // namespace

QRect SceneCanvas::movingBounds(const Solution& solution, const MotionSample& now,
                                double from) const {
    const QTransform world = worldTransform();
    QRectF box;
    auto add = [&](const QRectF& r) { box = box.isNull() ? r : box.united(r); };
    for (const QRectF& r : trailEndsBounds(now, from))
        add(r);
    const SystemSpec& spec = solution.scene().system;
    const BodyLook look = bodyLook();
    auto body = [&](double x, double y, double phi) {
        add(BodySprites::pixelBounds(world, m_scale, spec, solution.system(), {x, y, phi}, look));
    };
    forEachShownPose(now, m_showVakonomic, drawsOpenLoop(), drawsClosedLoop(), body);
    add(m_vectors.bounds(m_document->solution(), m_document->scene().vectors, now, world));
    // only the widget is painted: a body far outside the view (a wild zoom) must not overflow int
    if (!std::isfinite(box.x()) || !std::isfinite(box.y()) || !std::isfinite(box.width()) ||
        !std::isfinite(box.height()))
        return rect();
    return box.intersected(QRectF(rect()).adjusted(-4, -4, 4, 4))
        .toAlignedRect()
        .adjusted(-2, -2, 2, 2);
}

void SceneCanvas::updateTrailLayer(const MotionSample& now, const QPixmap& base, QPoint origin) {
    const qreal dpr = base.devicePixelRatio();
    // the layer's extent in the widget's pixels
    const QRect extent(-origin, (QSizeF(base.size()) / dpr).toSize());
    QRegion area;
    if (m_trailLayer.isNull() || m_trailBase != base.cacheKey() || m_time < m_trailsTime) {
        copyPixels(base.toImage(), m_trailLayer);
        m_trailLayer.setDevicePixelRatio(dpr);
        m_trailBase = base.cacheKey();
        area = extent;
    } else if (m_time > m_trailsTime) {
        for (const QRectF& r : trailEndsBounds(now, m_trailsTime)) {
            if (!std::isfinite(r.x()) || !std::isfinite(r.y()) || !std::isfinite(r.width()) ||
                !std::isfinite(r.height())) {
                area = extent;
                break;
            }
            area += r.intersected(QRectF(extent)).toAlignedRect();
        }
    }
    m_trailsTime = m_time;
    if (area.isEmpty())
        return;
    QPainter p(&m_trailLayer);
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
    bool steady = solution && from <= m_time && !m_movingPainted.isNull() && m_stroke.empty() &&
                  m_dragVertex < 0 && m_document->pins()->count() == 0;
    QPoint shift; // [px] how far the scene's pixels move
    if (steady && !m_follow) {
        steady = !m_background.isNull() && backgroundKey() == m_backgroundKey;
    } else if (steady) {
        BackgroundKey key = backgroundKey();
        key.centre = {};
        // the centre snaps to the pixel grid: the scene moves by whole pixels, y up
        const QPointF moved((centre.x() - m_centre.x()) * m_scale,
                            (m_centre.y() - centre.y()) * m_scale);
        shift = moved.toPoint();
        steady = followsWithWorldLayer() && key == m_worldKey && !m_worldLayer.isNull() &&
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
        m_movingPainted.translate(shift);
        dirty += QRegion(area) - moving;
        dirty += m_vectors.scaleBarsBounds(m_document->scene().vectors, drawingArea());
    }
    dirty += m_movingPainted;
    dirty += movingBounds(*solution, solution->at(m_time), from);
    dirty += QRect(0, 0, width(), topBandPx()); // the time read-out
    update(dirty);
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
        p.setClipRect(drawingArea());
        curves(); // at this scale, for the pins too
        paintPinnedRuns(p, *m_document->pins(), m_curves, worldTransform(), m_time,
                        pinKeyOrigin());
        const SystemSpec& spec = solution->scene().system;
        const QTransform world = worldTransform();
        // the translucent ghost on top, so that both stay visible where they overlap
        const BodyLook look = bodyLook();
        auto body = [&](const BodyPose& pose, const QColor& color, bool ghost) {
            m_bodies.paint(p, world, m_scale, spec, solution->system(), pose, color, ghost, look);
        };
        body({now->x, now->y, now->phi}, m_style.controlled(), false);
        body({now->free.x, now->free.y, now->free.phi}, m_style.free(), true);
        if (m_showVakonomic)
            body({now->vak.x, now->vak.y, now->vak.phi}, m_style.vakonomic(), true);
        if (drawsOpenLoop())
            body({now->pert.x, now->pert.y, now->pert.phi}, m_style.openLoop(), true);
        if (drawsClosedLoop())
            body({now->fb.x, now->fb.y, now->fb.phi}, m_style.closedLoop(), true);
        paintPathOverBodies(p, *now);
        p.restore();
        m_vectors.paint(p, solution, m_document->scene().vectors, *now, worldTransform(), m_scale,
                        drawingArea(), e->region());
        paintTimeReadout(p, solution->tEnd());
        m_movingPainted = movingBounds(*solution, *now, m_time);
    } else {
        m_movingPainted = {};
    }
    if (m_pushing) {
        // the push being dragged: a line from where the body was grabbed
        p.setPen(m_style.pen(m_style.closedLoop().darker(140), 2, Qt::DashLine));
        p.drawLine(toPixel(m_pushFrom), m_pushTo);
    }
    if (m_drawMode)
        paintVertices(p);
    if (m_stroke.size() > 1) {
        QPolygonF line;
        for (QPointF w : m_stroke)
            line << toPixel(w);
        p.setPen(m_style.pen(QColor(40, 40, 40), 2));
        p.drawPolyline(line);
    }
}

const std::pair<QPainterPath, QPainterPath>& SceneCanvas::bodyClipShapes() const {
    const Solution* solution = m_document->solution().get();
    const double penPx = 3 * m_style.lineScale + 2;
    if (solution != m_bodyClipOf || m_scale != m_bodyClipScale || penPx != m_bodyClipPen) {
        m_bodyClipOf = solution;
        m_bodyClipScale = m_scale;
        m_bodyClipPen = penPx;
        // the pose and the view map these with a rotation, a uniform scale and a flip: the
        // ring's width in metres is the pen's in pixels over the scale
        QPainterPath shape = bodyShape(solution->scene().system, solution->system());
        QPainterPathStroker pen;
        pen.setWidth(penPx / m_scale);
        QPainterPath ring = pen.createStroke(shape);
        m_bodyClips = {std::move(shape), std::move(ring)};
    }
    return m_bodyClips;
}

const QImage& SceneCanvas::pathLayer(QPoint& origin) {
    // the layer lies under the static one: the window's pixel p is the layer's p + origin
    const bool following = followsWithWorldLayer();
    BackgroundKey key = backgroundKey();
    QTransform world = worldTransform();
    QSize size = this->size();
    origin = {};
    if (following) {
        // the world layer's view: drawn at its centre over its margin, shifted as it is
        key.centre = m_worldCentre;
        origin = worldLayerOrigin();
        world = worldLayerTransform();
        size += QSize(2 * m_worldMargin, 2 * m_worldMargin);
    }
    // the key's size fixes the world layer's margin too
    if (!(key == m_pathKey) || following != m_pathFollowing || m_pathLayer.isNull()) {
        if (!(key == m_pathSeenKey) || following != m_pathSeenFollowing) {
            m_pathSeenKey = key;
            m_pathSeenFollowing = following;
            static const QImage none;
            return none;
        }
        m_pathKey = key;
        m_pathFollowing = following;
        m_pathLayer = QImage(size * key.dpr, QImage::Format_ARGB32_Premultiplied);
        m_pathLayer.setDevicePixelRatio(key.dpr);
        m_pathLayer.fill(Qt::transparent);
        QPainter l(&m_pathLayer);
        l.setRenderHint(QPainter::Antialiasing, true);
        paintPath(l, world);
    }
    return m_pathLayer;
}

void SceneCanvas::paintPathOverBodies(QPainter& p, const MotionSample& now) {
    // an outline or a marker has no fill: the path shows through it
    if (bodyLook().display != BodyDisplay::ToScale)
        return;
    const QTransform world = worldTransform();
    const auto& [shape, ring] = bodyClipShapes();
    // each body's area and the ring its outline's pen covers, in pixels
    std::vector<std::pair<QPainterPath, QPainterPath>> clips;
    auto add = [&](double x, double y, double phi) {
        QTransform pose;
        pose.translate(x, y);
        pose.rotate(phi * 180.0 / M_PI);
        const QTransform map = pose * world;
        QPainterPath mapped = map.map(shape);
        if (!mapped.boundingRect().intersects(QRectF(rect())))
            return;
        clips.emplace_back(std::move(mapped), map.map(ring));
    };
    forEachShownPose(now, m_showVakonomic, drawsOpenLoop(), drawsClosedLoop(), add);
    if (clips.empty())
        return;
    const Trail controlled = trails(now).back();
    QPolygonF line;
    const std::size_t n = controlled.curve->countUpTo(controlled.limit);
    line.reserve(qsizetype(n) + 1);
    for (std::size_t i = 0; i < n; ++i)
        line << world.map(controlled.curve->points[i]);
    line << world.map(controlled.end);
    const qreal dpr = devicePixelRatioF();
    QPoint origin;
    const QImage* layer = dpr == std::round(dpr) ? &pathLayer(origin) : nullptr;
    m_pathOverBodiesFromLayer = layer && !layer->isNull();
    // the band and the controlled trail up to now on it, then the knife at P
    for (const auto& [area, outline] : clips) {
        const QRect box =
            area.boundingRect().united(outline.boundingRect()).toAlignedRect() & rect();
        // the controlled trail lies on the band: where no band is, there is nothing to draw
        if (box.isEmpty() || !bandReaches(world, QRectF(box)))
            continue;
        if (!layer) {
            // a fractional device pixel ratio: drawn under the clips (a layer's pixels would
            // land between the device's)
            for (const QPainterPath* clip : {&area, &outline}) {
                p.save();
                p.setClipPath(*clip, Qt::IntersectClip);
                paintPath(p, world, clip->boundingRect().intersected(QRectF(rect())));
                strokePolylineWithin(p, line, controlled.pen, QRegion(box));
                p.restore();
            }
            continue;
        }
        // the layer's band within the box (or the band drawn there, at a view's first paint)
        // and the trail on it, in the body's area or under its outline
        drawMaskedLayer(p, *layer, origin, box, {&area, &outline}, [&](QPainter& c) {
            if (layer->isNull())
                paintPath(c, world, QRectF(box));
            strokePolylineWithin(c, line, controlled.pen, QRegion(box));
        });
    }
    p.save();
    const QPointF at = world.map(QPointF(now.x, now.y));
    const QPointF along = QPointF(std::cos(now.phi), -std::sin(now.phi)) * 9 * m_style.lineScale;
    p.setPen(m_style.pen(m_style.controlled().darker(170), 3.5));
    p.drawLine(at - along, at + along);
    p.restore();
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

void SceneCanvas::paintVertices(QPainter& p) const {
    const auto points = m_dragVertex >= 0 ? m_editPoints : drawnPoints();
    if (m_dragVertex >= 0) {
        QPolygonF line;
        for (const auto& [x, y] : points)
            line << toPixel({x, y});
        p.setPen(m_style.pen(QColor(60, 60, 60), 1, Qt::DashLine));
        p.drawPolyline(line);
    }
    p.setPen(m_style.pen(QColor(60, 60, 60), 1));
    p.setBrush(QColor(255, 255, 255, 220));
    for (const auto& [x, y] : points) {
        QPointF c = toPixel({x, y});
        p.drawRect(QRectF(c.x() - 3, c.y() - 3, 6, 6));
    }
}

} // namespace chaplygin::ui
