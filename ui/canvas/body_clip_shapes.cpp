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
        QPainterPath ring = pen.createStroke(shape);
        // united in pixels, where Qt flattens the curves to its tolerance, and brought back
        const QTransform toPixels = QTransform::fromScale(scale, scale);
        m_covered = toPixels.inverted().map(toPixels.map(shape).united(toPixels.map(ring)));
        m_shapes = {std::move(shape), std::move(ring)};
    }
    return m_shapes;
}

} // namespace chaplygin::ui
