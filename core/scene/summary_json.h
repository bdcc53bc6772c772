#pragma once
// The --summary JSON of a Solution.
#include "scene/solution.h"

#include <string>

namespace chaplygin {

/// The --summary JSON: derived parameters (CM offset a, b, m_eff, I about the CM, m_translating),
/// the system's own parameters (and the carriage's half_axle), path length, duration, horizon,
/// mode and speed, and the model or method behind each quantity.
std::string formatSummary(const Solution& solution);

} // namespace chaplygin
