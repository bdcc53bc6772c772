#pragma once
// The command line's CSV: the header and the rows of a Solution, written from the column table.
#include "planning/pose_planner.h"
#include "scene/csv_columns.h"
#include "scene/solution.h"

#include <string>
#include <vector>

namespace chaplygin {

/// The rows as CSV text with a header, one column per entry of csvColumnsWritten() (the perturbed
/// bodies' columns when the rows have them), full double
/// precision. Throws InputError naming the column and time if any value is not finite: a NaN
/// never reaches a CSV.
std::string formatCsv(const std::vector<MotionSample>& rows);

/// A planned motion's time series (docs/physics.md §10): t and the genuine vakonomic body's
/// columns (vak_*, the names and units of the run's CSV) at the given times, from its closed form.
std::string formatPlanCsv(const PlanRequest& request, const PlannedGeodesic& motion,
                          const std::vector<double>& times);

} // namespace chaplygin
