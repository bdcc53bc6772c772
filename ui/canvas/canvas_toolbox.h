#pragma once
#include <array>
#include <vector>

namespace chaplygin::ui {

class CanvasTool;
class DrawTool;
class EditPointsTool;
class MeasureTool;
class PanTool;
class PenTool;
class PlanTool;
class PushTool;

/// The canvas's tools, one per gesture, and which of them the mouse reaches. Drawing the path
/// (a stroke, or moving its points) is on while the Path panel's button is; the Plan tool, the
/// Measure tool and the pen are each a mode of their own over it; pushing the body is what the
/// mouse does otherwise; panning goes with every mode. The canvas owns the tools (as their
/// QObject parent).
struct CanvasToolbox {
    DrawTool* draw = nullptr;
    EditPointsTool* edit = nullptr;
    PushTool* push = nullptr;
    PlanTool* plan = nullptr;
    MeasureTool* measure = nullptr;
    PenTool* pen = nullptr;
    PanTool* pan = nullptr;
    bool drawMode = false; ///< the Path panel's Draw on the canvas
    bool planMode = false; ///< the Plan tool's mode

    /// Every tool, in the order of their gestures' priority: editing a point, a stroke, a plan's
    /// handle, a measurement, a pen's mark, a push, panning.
    std::array<CanvasTool*, 7> all() const;
    /// The tools the mouse reaches in the current mode, in the order they are offered a press.
    std::vector<CanvasTool*> reachable() const;
    /// Whether the Measure tool's mode is on.
    bool measureMode() const;
    /// Whether the pen's mode is on.
    bool penMode() const;
};

} // namespace chaplygin::ui
