#pragma once
// Pose to pose: every genuine vakonomic motion (geodesic of the sub-Riemannian problem on SE(2)
// with the metric ds^2 + b^2 dphi^2) from a start pose to a target pose within a horizon, each
// certified optimal or not by its cut time (docs/physics.md §10).
#include "motion/vakonomic_motion.h"
#include "systems/system.h"

#include <string>
#include <vector>

namespace chaplygin {

struct Pose {
    double x = 0, y = 0, phi = 0; ///< the knife point P [m] and the heading [rad]
};

enum class GeodesicFamily {
    Rest,       ///< the target is the start: t = 0
    Pivot,      ///< Psi = 0 or pi: turning in place about P
    Line,       ///< Psi = +-pi/2: straight ahead or backing up
    Libration,  ///< k < 1
    Rotation,   ///< k > 1
    Separatrix, ///< k = 1
};
std::string geodesicFamilyName(GeodesicFamily family);

/// One genuine vakonomic motion that reaches the target.
struct PlannedGeodesic {
    double t = 0;       ///< arrival time [s]
    double psi0 = 0;    ///< Psi(0) = atan2(sdot, b phidot) in (-pi, pi] [rad]
    double psidot0 = 0; ///< Psidot(0) [rad/s]
    double lambda0 = 0; ///< lambda(0) = m (b Psidot0 - a phidot0) [kg m/s]
    double modulus = 0; ///< the pendulum's k
    /// 1 - k^2, exact: next to the separatrix the motion is the one of Psi0 with this 1 - k^2
    /// (psidot0 is +-sqrt(cos^2 Psi0 - modulusGap) rounded, docs/physics.md §10); 1 pivoting
    double modulusGap = 1;
    GeodesicFamily family = GeodesicFamily::Rest;
    double cutTime = 0;   ///< first Maxwell time [s] (infinity on the separatrix and the line)
    bool optimal = false; ///< a least-time motion, certified by t <= cutTime
    double endError = 0;  ///< |dx|/b + |dy|/b + |dphi mod 2 pi| at t, from the closed form
};

struct PlanRequest {
    Pose from, to;
    DerivedSystem system; ///< the effective b (and m, a for lambda(0))
    double vT = 1;        ///< speed sqrt(sdot^2 + b^2 phidot^2) [m/s]
    /// Motions arriving later than this are not listed [s]; 0: three times the least time, at
    /// least 2 pi b/v_T.
    double horizon = 0;
    /// Only the least-time motion(s): stops once one is certified (and its Maxwell twin found).
    bool optimalOnly = false;
};

struct Plan {
    std::vector<PlannedGeodesic> geodesics; ///< sorted by t
    double horizon = 0;                     ///< the horizon used [s]
    /// The least time found is at most its motion's cut time: it is the least time of all.
    bool certified = false;
};

/// Throws InputError naming the field for a non-finite pose, b <= 0, v_T <= 0 or a negative or
/// non-finite horizon.
Plan planVakonomic(const PlanRequest& request);

/// The genuine vakonomic body's start for a planned motion: the start pose, sdot = v_T sin Psi0,
/// phidot = v_T cos Psi0 / b (exactly 0 on a line, sdot exactly 0 pivoting) and lambda(0), for
/// VakonomicMotion with the request's system (docs/physics.md §8).
VakonomicInitial plannedStart(const PlanRequest& request, const PlannedGeodesic& motion);

} // namespace chaplygin
