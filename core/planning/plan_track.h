#pragma once
// A planned motion's knife track as a scene's path: tracking it is the genuine vakonomic motion
// itself (docs/physics.md §10).
//
//   PathSource planTrack(const PlanRequest& request, const PlannedGeodesic& motion);
//   std::shared_ptr<const Path> buildGeodesicTrack(const GeodesicTrack& track, budget);
#include "paths/path.h"
#include "planning/pose_planner.h"

#include <memory>

namespace chaplygin {

/// The path source (kind Geodesic) of the knife track of `motion`, a motion planned for
/// `request`: from the start pose, its (Psi0, b Psidot0/v_T) and length v_T t, with the
/// request's effective b. Tracking it at the request's v_T in constant-energy mode gives the
/// controlled body that moves as the genuine vakonomic body, (x, y, phi, lambda) alike. Throws
/// InputError("plan") for the motion at rest (t = 0: nothing to track).
PathSource planTrack(const PlanRequest& request, const PlannedGeodesic& motion);

/// The path of a geodesic track: one pivot about P when Psi is 0 or pi for ever, else the
/// closed-form curve (GeodesicTrackCurve) split at its cusps, the first stretch backing up when
/// the motion starts with sdot < 0, the heading starting at the track's phi exactly. Throws
/// InputError("path ...") naming a non-finite field, b <= 0 or a length <= 0.
std::shared_ptr<const Path>
buildGeodesicTrack(const GeodesicTrack& track,
                   std::size_t halvingBudget = PathTable::kHalvingBudget);

} // namespace chaplygin
