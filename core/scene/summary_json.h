#pragma once
#include "scene/solution.h"

#include <string>

namespace chaplygin {

/// The --summary JSON: derived parameters (a, b, m_eff, I), path length, duration, horizon,
/// mode and speed, and the model or method behind each quantity.
std::string formatSummary(const Solution& solution);

} // namespace chaplygin
