#pragma once

namespace chaplygin::ui {

class AccuracyReadout;
class PlotsPanel;
class SceneCanvas;

/// In plan mode with a motion chosen (docs/physics.md §10), the plots show that motion's genuine
/// vakonomic body and its free ghost with the cursor at the played time (a click on a plot moves
/// the played bodies there), and the Accuracy dock its end error on the target and whether it is
/// certified optimal; out of plan mode, the scene's again.
void installPlanReadouts(SceneCanvas& canvas, PlotsPanel& plots, AccuracyReadout& accuracy);

} // namespace chaplygin::ui
