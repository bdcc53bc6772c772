#pragma once
#include "planning/pose_planner.h"
#include "scene/solution.h"

#include <QString>

namespace chaplygin::ui {

/// The Equations panel's page for time t: the formulas the Solution uses for its system and
/// mode, each with the live values substituted and the paper's equation number (in the
/// corrected form of docs/physics.md's errata). Every value is read from the Solution; the
/// substitutions only display them.
QString equationsHtml(const Solution& solution, double t);

/// The plan's section (docs/physics.md §10): the chosen motion (number `index` of `count`), its
/// family, k, Psi0, lambda(0) substituted, its time and cut time, and its Psi and lambda at time
/// t along it (clamped to the motion).
QString planHtml(const PlanRequest& request, const PlannedGeodesic& motion, int index, int count,
                 double t);

} // namespace chaplygin::ui
