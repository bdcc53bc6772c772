#pragma once
// Plain names on screen for the core's models and method ids; the technical wording stays
// behind a "Details" disclosure or a tooltip.
#include "scene/solution.h"

#include <QString>

#include <string>

namespace chaplygin::ui {

/// A method id of the registry (e.g. "gsl_msadams") as a person reads it ("Multistep Adams
/// (GSL)"); an unknown id is returned as it is.
QString plainMethodName(const std::string& id);

/// The same in a few characters, for a legend beside a small diagram ("Adams (GSL)", "RK4");
/// the table beside it gives the plain name.
QString shortMethodName(const std::string& id);

/// One short line on how the solution's quantities are computed, in plain words: the time
/// along the path by an exact formula or a quadrature, the ghost and the vakonomic body by
/// exact formulas, the pushed bodies by an ODE integrator.
QString plainModelSummary(const Solution& solution);

/// One of the core's technical descriptions of a model (ModelReport) in the user's language; a
/// description built with numbers in it stays as the core wrote it.
QString technicalModel(const std::string& description);

/// The solution's models in the core's own technical words, one line each.
QString technicalModels(const Solution& solution);

} // namespace chaplygin::ui
