#pragma once
// Nothing non-finite leaves the core: a path, a sample or a solution with an inf or a NaN is
// refused with an InputError that names the body, the quantity and the time (docs/robustness.md,
// Non-finite results).
#include "paths/path.h"
#include "scene/solution.h"

#include <string>

namespace chaplygin {

/// How far from the origin a path may lie [m]: there double precision resolves 0.1 µm, below the
/// canvas's smallest pixel (1e-5 m at its largest zoom), and every pixel stays finite.
inline constexpr double kMaxPathExtent = 1e9;

/// Throws InputError("path at (x, y)", ...) when a node of the path's table, or its interpolant
/// at a panel's ends or middle, has a non-finite position, heading or arc length, or (after
/// those) when a node lies farther than kMaxPathExtent from the origin.
void requireFinitePath(const Path& path);

/// Throws InputError("column NAME is not finite at t = T s: ...") for the first CSV column read
/// from `parts` whose value in m is not finite, with its meaning and value; context is appended.
void requireFiniteSample(const MotionSample& m, const MotionParts& parts = {},
                         const std::string& context = {});

/// The path, the controlled motion at every panel end, and every body at kFiniteCheckTimes
/// evenly spaced times from 0 to t_end: throws InputError at the first non-finite value, with
/// the scene's system parameters when a body's motion is what fails.
void requireFiniteSolution(const Solution& solution);

/// How many evenly spaced times requireFiniteSolution checks every body at.
inline constexpr int kFiniteCheckTimes = 33;

} // namespace chaplygin
