#pragma once
// Independent references for the planner's tests: an rk8pd integration of (19)-(21) from a
// planned start, and a multi-start shooting search for the least time (GSL's hybrid Newton from
// random starts), neither using the planner's code.
#include "planning/pose_planner.h"

#include <vector>

namespace chaplygin::test {

/// The pose reached at t by the genuine vakonomic body started at `from` with speed vT, heading
/// of the velocity Psi0 = atan2(sdot, b phidot) and lambda(0), by rk8pd at 1e-13.
Pose integratedEnd(const DerivedSystem& system, double vT, const Pose& from, double psi0,
                   double lambda0, double t);

/// The pose the normalised problem's (b = v_T = 1, a = 0) genuine vakonomic body reaches at t
/// from (0, 0, 0) with Psi0 and lambda(0), by its closed form.
Pose unitEnd(double psi0, double lambda0, double t);

/// |dx|/b + |dy|/b + |dphi mod 2 pi|.
double poseError(const Pose& a, const Pose& b, double length);

struct ShootingResult {
    double t = 0, psi0 = 0, psidot0 = 0; ///< the least time found (b = v_T = 1)
    int converged = 0;                   ///< starts that reached the target
};

/// The least time to (X, Y, Phi) from (0, 0, 0) in the normalised problem (b = v_T = 1) by
/// `starts` random starts (Psi0, Psidot0, t) of GSL's hybrid Newton on the closed-form end pose.
ShootingResult leastTimeByShooting(double X, double Y, double Phi, int starts, unsigned seed);

/// Every distinct motion the same search reaches with t <= tMax (Psi0 in (-pi, pi]).
std::vector<ShootingResult> motionsByShooting(double X, double Y, double Phi, double tMax,
                                              int starts, unsigned seed);

} // namespace chaplygin::test
