#pragma once
// The --summary JSON of a Solution.
#include "planning/pose_planner.h"
#include "scene/solution.h"

#include <string>

namespace chaplygin {

/// The --summary JSON: derived parameters (CM offset a, b, m_eff, I about the CM, m_translating),
/// the system's own parameters (and the carriage's half_axle), path length, duration, horizon,
/// mode and speed, and the model or method behind each quantity.
std::string formatSummary(const Solution& solution);

/// The --summary JSON of a plan (docs/physics.md §10): the solution's summary when a path was
/// given (else an object of its own) with "plan": {"from": [x, y, phi], "to": [x, y, phi],
/// "horizon", "certified", "geodesics": [...]}, the motions sorted by t, each {"t", "psi0",
/// "psidot0", "lambda0", "family", "cut_time" (null where it is infinite), "optimal", "modulus"
/// (the pendulum's k), "modulus_gap" (1 - k^2)}.
std::string formatPlanSummary(const PlanRequest& request, const Plan& plan,
                              const Solution* solution);

} // namespace chaplygin
