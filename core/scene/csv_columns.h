#pragma once
#include "scene/solution.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

namespace chaplygin {

/// One column of the time-series CSV (`--csv`, File > Export CSV): its header name, its SI unit,
/// what it means, and how it is read from a sample.
struct CsvColumn {
    std::string_view name;    ///< in the header: lower case, digits and '_'
    std::string_view unit;    ///< "s", "m", "rad", "m/s", "rad/s", "J", "N", "N m", "kg m/s"
    std::string_view meaning; ///< one line, no '|' (the README's table shows it)
    double (*value)(const MotionSample&);
    bool perturbed = false; ///< written only for a scene with a perturbation (docs/physics.md §9)
};

/// The columns in CSV order: the one table the header, every row and the README's list come from.
std::span<const CsvColumn> csvColumns();

/// The columns written for rows of a scene with or without a perturbation: without one the
/// perturbed bodies' columns (the last ones) are left out.
std::span<const CsvColumn> csvColumnsWritten(bool perturbed);

/// The bodies a column is read from, by its name's prefix (free_, vak_, pert_ or fb_; t from
/// none; the rest from the controlled body): Solution::at(t, parts) with the union of these
/// gives the same values in these columns as the whole state.
MotionParts csvColumnParts(const CsvColumn& column);

/// The position of the column called NAME in csvColumns(), or nothing.
std::optional<std::size_t> csvColumnIndex(std::string_view name);

} // namespace chaplygin
