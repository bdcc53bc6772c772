#pragma once
// A planned motion sampled from its closed forms: the genuine vakonomic body along it and the
// free (Lagrange-d'Alembert) ghost from the same start (docs/physics.md §10).
#include "motion/free_motion.h"
#include "motion/vakonomic_motion.h"
#include "planning/pose_planner.h"

#include <vector>

namespace chaplygin {

struct PlannedSample {
    double t = 0;             ///< [s]
    VakonomicState vakonomic; ///< the genuine vakonomic body (Psi, chi, lambda, T among them)
    FreeState free;           ///< the free ghost from the same start pose and velocities
};

/// `count` (at least 2) evenly spaced times over [0, motion.t], the last exactly motion.t; each
/// value from VakonomicMotion and FreeMotion, nothing integrated step by step.
std::vector<PlannedSample> samplePlannedMotion(const PlanRequest& request,
                                               const PlannedGeodesic& motion, int count);

} // namespace chaplygin
