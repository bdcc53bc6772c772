// The path laid over the bodies drawn to scale: the band and the controlled trail kept within
// each body's area, from the path's layer or drawn anew at a view's first paint, only where they
// can ink (docs/numerics.md §10).
#include "canvas/scene_canvas.h"

#include "canvas/ink_rows.h"
#include "canvas/masked_layer.h"
#include "canvas/trail_stroke.h"
#include "document/scene_document.h"
#include "scene/solution.h"

#include <QPainter>
#include <QPainterPath>

#include <cmath>
#include <vector>

namespace chaplygin::ui {

const QImage& SceneCanvas::pathLayer(QPoint& origin) {
    // the layer lies under the static one: the window's pixel p is the layer's p + origin
    const bool following = followsWithWorldLayer();
    LayerKey key = layerKey();
    QTransform world = worldTransform();
    QSize size = this->size();
    origin = {};
    if (following) {
        // the world layer's view: drawn at its centre over its margin, shifted as it is
        key.centre = m_layers.worldCentre();
        origin = worldLayerOrigin();
        world = worldLayerTransform();
        const int margin = m_layers.worldMargin();
        size += QSize(2 * margin, 2 * margin);
    }
    return m_layers.pathLayer(key, following, size, [&](QPainter& l) { paintPath(l, world); });
}

void SceneCanvas::paintPathOverBodies(QPainter& p, const MotionSample& now) {
    // an outline or a marker has no fill: the path shows through it
    if (bodyLook().display != BodyDisplay::ToScale)
        return;
    const QTransform world = worldTransform();
    const auto& [shape, ring] =
        m_bodyClips.of(*m_document->solution(), m_view.scale(), 3 * m_look.style.lineScale + 2);
    const QPainterPath* covered = m_bodyClips.covered();
    // each body's area and the ring its outline's pen covers, in pixels, and both as one when
    // the union is made
    struct Clip {
        QPainterPath area, outline, both;
    };
    std::vector<Clip> clips;
    for (const DrawnBody& body : drawnBodies(now)) {
        QTransform pose;
        pose.translate(body.pose.x, body.pose.y);
        pose.rotate(body.pose.phi * 180.0 / M_PI);
        const QTransform map = pose * world;
        QPainterPath mapped = map.map(shape);
        if (!mapped.boundingRect().intersects(QRectF(rect())))
            continue;
        clips.push_back(
            {std::move(mapped), map.map(ring), covered ? map.map(*covered) : QPainterPath()});
    }
    if (clips.empty())
        return;
    const Trail controlled = trails(now).back();
    QPolygonF line;
    const std::size_t n = controlled.curve->countUpTo(controlled.limit);
    line.reserve(qsizetype(n) + 1);
    for (std::size_t i = 0; i < n; ++i)
        line << world.map(controlled.curve->points[i]);
    if (controlled.curve->reaches(controlled.limit))
        line << world.map(controlled.end);
    const qreal dpr = devicePixelRatioF();
    QPoint origin;
    const QImage* layer = dpr == std::round(dpr) ? &pathLayer(origin) : nullptr;
    m_pathOverBodies.fromLayer = layer && !layer->isNull();
    // where in a body's box the band, its marks and the trail can ink: only there is the
    // layer masked and laid over, in bands of 64 device rows
    const QPolygonF band = layer ? bandPoints(world) : QPolygonF();
    const std::vector<InkLine> inks{{&band, bandInkReach()}, {&line, controlled.pen.widthF() + 2}};
    const std::vector<InkMark> marks = layer ? pathMarks(world) : std::vector<InkMark>();
    const int rows = std::max(8, int(64 / dpr));
    // the band and the controlled trail up to now on it, then the knife at P
    for (const auto& [area, outline, both] : clips) {
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
        // the parts pay where they leave out most of the box; where the ink crosses most of it
        // (zoomed far in on the band), each part's fixed cost is lost: the whole box then
        std::vector<QRect> parts{box};
        if (!m_pathOverBodies.whole) {
            std::vector<QRect> ink = inkRows(box, rows, inks, marks);
            qint64 inked = 0;
            for (const QRect& r : ink)
                inked += qint64(r.width()) * r.height();
            if (inked <= qint64(box.width()) * box.height() / 2)
                parts = std::move(ink);
        }
        // the layer's band within each part (or the band drawn there, at a view's first paint)
        // and the trail on it, in the body's area or under its outline
        for (const QRect& part : parts) {
            const auto over = [&](QPainter& c) {
                if (layer->isNull())
                    paintPath(c, world, QRectF(box), QRectF(part));
                strokePolylineWithin(c, line, controlled.pen, QRegion(part));
            };
            if (covered)
                drawMaskedLayer(p, *layer, origin, part, {&both}, over);
            else
                drawMaskedLayer(p, *layer, origin, part, {&area, &outline}, over);
        }
    }
    p.save();
    const QPointF at = world.map(QPointF(now.x, now.y));
    const QPointF along =
        QPointF(std::cos(now.phi), -std::sin(now.phi)) * 9 * m_look.style.lineScale;
    p.setPen(m_look.style.pen(m_look.style.controlled().darker(170), 3.5));
    p.drawLine(at - along, at + along);
    p.restore();
}

} // namespace chaplygin::ui
