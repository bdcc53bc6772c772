#pragma once
// The path of any scene: the typed and drawn paths (buildPath) and the geodesic tracks of the
// planner (buildGeodesicTrack).
#include "paths/path.h"

#include <memory>

namespace chaplygin {

/// buildPath for the graph, parametric and polyline kinds, buildGeodesicTrack for a geodesic
/// track; throws InputError as they do.
std::shared_ptr<const Path> buildScenePath(const PathSource& source,
                                           std::size_t halvingBudget = PathTable::kHalvingBudget);

} // namespace chaplygin
