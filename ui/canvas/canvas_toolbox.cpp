#include "canvas/canvas_toolbox.h"

#include "canvas/draw_tool.h"
#include "canvas/edit_points_tool.h"
#include "canvas/measure_tool.h"
#include "canvas/pan_tool.h"
#include "canvas/pen_tool.h"
#include "canvas/plan_tool.h"
#include "canvas/push_tool.h"

namespace chaplygin::ui {

std::array<CanvasTool*, 7> CanvasToolbox::all() const {
    return {edit, draw, plan, measure, pen, push, pan};
}

std::vector<CanvasTool*> CanvasToolbox::reachable() const {
    if (penMode())
        return {pen, pan};
    if (measureMode())
        return {measure, pan};
    if (planMode)
        return {plan, pan};
    if (drawMode)
        return {edit, draw, pan};
    return {push, pan};
}

bool CanvasToolbox::measureMode() const {
    return measure->enabled();
}

bool CanvasToolbox::penMode() const {
    return pen->enabled();
}

} // namespace chaplygin::ui
