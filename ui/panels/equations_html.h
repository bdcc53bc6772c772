#pragma once
#include "scene/solution.h"

#include <QString>

namespace chaplygin::ui {

/// The Equations panel's page for time t: the formulas the Solution uses for its system and
/// mode, each with the live values substituted and the paper's equation number (in the
/// corrected form of docs/physics.md's errata). Every value is read from the Solution; the
/// substitutions only display them.
QString equationsHtml(const Solution& solution, double t);

} // namespace chaplygin::ui
