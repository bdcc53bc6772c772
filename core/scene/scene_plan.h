#pragma once
// A scene's plan from pose to pose (docs/physics.md §10): the planner's request made from the
// scene, and the planned motions with the chosen one checked.
#include "planning/pose_planner.h"
#include "scene/scene.h"
#include "scene/solution.h"

namespace chaplygin {

/// The start pose of a plan: its own, else the controlled body's at t = 0 (the path's start).
Pose planStart(const ScenePlan& plan, const Solution& solution);

/// The planner's request for a plan of the solution's scene: the solution's system (its
/// effective b), v_T the scene's speed. Throws InputError ("plan") in the constant-speed mode,
/// which keeps the speed, not the energy, and so has no genuine vakonomic motion to plan.
PlanRequest planRequestOf(const ScenePlan& plan, const Solution& solution);

/// Every motion of the plan (planVakonomic). Throws InputError naming the field: "plan choice"
/// when the chosen motion is not in the list, "plan to" when no motion reaches the target within
/// the horizon.
Plan planOf(const ScenePlan& plan, const Solution& solution);

} // namespace chaplygin
