#pragma once
// The command line's CSV: its columns and the rows of a Solution.
#include "scene/solution.h"

#include <string>
#include <vector>

namespace chaplygin {

/// The CSV header of the command-line contract (README, Headless examples), columns in order.
const std::vector<std::string>& csvColumns();

/// The rows as CSV text with a header, full double precision. Throws std::runtime_error naming
/// the column and time if any value is not finite: a NaN never reaches a CSV.
std::string formatCsv(const std::vector<MotionSample>& rows);

} // namespace chaplygin
