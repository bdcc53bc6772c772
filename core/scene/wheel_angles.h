#pragma once
// The wheels' rolling angles read from a solution's columns (docs/physics.md §1, Rolling
// angles): the disk's theta with sdot = R thetadot (paper A5), the carriage's theta1 and theta2
// with R thetadot1 = sdot + a phidot and R thetadot2 = sdot - a phidot (paper B2-B3). Both are
// integrated in closed form from s and phi: no equation is solved.
#include "paths/path.h"
#include "systems/system.h"

namespace chaplygin {

class Solution;
struct MotionSample;

/// The rolling angles of a body's wheels [rad]: 0 at t = 0, growing while the wheel rolls
/// forwards (its top moving along the heading).
struct WheelAngles {
    int wheels = 0; ///< 0 for the sleigh, 1 for the disk, 2 for the carriage
    double theta1 =
        0; ///< the disk's theta; the carriage's wheel 1, right of the heading (-a n-hat)
    double theta2 = 0; ///< the carriage's wheel 2, left of the heading (+a n-hat)
};

/// The distance P has travelled along its heading when the path's arc length is s [m], the
/// integral of sdot: a stretch driven backwards (after a cusp) counts negative, a pivot nothing.
double signedTravel(const Path& path, double s);

/// The angles from the signed travel [m] and the heading's turn phi - phi(0) [rad]:
/// theta = travel/R (A5); theta1 = (travel + a turn)/R (B2), theta2 = (travel - a turn)/R (B3),
/// with a the half-axle. R and a missing from spec take the system's defaults.
WheelAngles wheelAngles(const SystemSpec& spec, double travel, double turn);

/// The controlled body's angles at m, a sample of solution (its s and phi).
WheelAngles wheelAnglesAt(const Solution& solution, const MotionSample& m);

} // namespace chaplygin
