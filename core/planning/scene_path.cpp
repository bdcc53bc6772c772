#include "planning/scene_path.h"

#include "planning/plan_track.h"

namespace chaplygin {

std::shared_ptr<const Path> buildScenePath(const PathSource& source, std::size_t halvingBudget) {
    if (source.kind == PathKind::Geodesic)
        return buildGeodesicTrack(source.geodesic, halvingBudget);
    return buildPath(source, halvingBudget);
}

} // namespace chaplygin
