#include "canvas/body_clip_shapes.h"

#include "canvas/body_painter.h"
#include "scene/solution.h"

#include <QPainterPathStroker>

namespace chaplygin::ui {

const std::pair<QPainterPath, QPainterPath>& BodyClipShapes::of(const Solution& solution,
                                                                double scale, double penPx) {
    if (&solution != m_solution || scale != m_scale || penPx != m_penPx) {
        m_solution = &solution;
        m_scale = scale;
        m_penPx = penPx;
        // the pose and the view map these with a rotation, a uniform scale and a flip: the
        // ring's width in metres is the pen's in pixels over the scale
        QPainterPath shape = bodyShape(solution.scene().system, solution.system());
        QPainterPathStroker pen;
        pen.setWidth(penPx / scale);
        const QPainterPath ring = pen.createStroke(shape);
        // both flattened in pixels, once: the two fills of a first frame at this scale and the
        // fill of their union cover the same pixels, and the union has no curves to flatten
        const QTransform toPixels = QTransform::fromScale(scale, scale);
        const QTransform toMetres = toPixels.inverted();
        auto flattened = [&](const QPainterPath& path) {
            QPainterPath polygons;
            polygons.setFillRule(path.fillRule());
            for (const QPolygonF& polygon : toPixels.map(path).toSubpathPolygons())
                polygons.addPolygon(toMetres.map(polygon));
            return polygons;
        };
        m_shapes = {flattened(shape), flattened(ring)};
        m_covered.reset();
        m_asked = 0;
    }
    ++m_asked;
    return m_shapes;
}

const QPainterPath* BodyClipShapes::covered() {
    if (m_asked < 2)
        return nullptr;
    if (!m_covered) {
        // united in pixels and brought back
        const QTransform toPixels = QTransform::fromScale(m_scale, m_scale);
        m_covered = toPixels.inverted().map(
            toPixels.map(m_shapes.first).united(toPixels.map(m_shapes.second)));
    }
    return &*m_covered;
}

} // namespace chaplygin::ui
