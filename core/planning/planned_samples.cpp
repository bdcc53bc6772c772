#include "planning/planned_samples.h"

#include <algorithm>

namespace chaplygin {

std::vector<PlannedSample> samplePlannedMotion(const PlanRequest& request,
                                               const PlannedGeodesic& motion, int count) {
    count = std::max(count, 2);
    const VakonomicInitial start = plannedStart(request, motion);
    const VakonomicMotion body(request.system, start);
    // the ghost starts with the body's pose and velocities; its lambda is 0 (docs/physics.md §4)
    const FreeMotion ghost(request.system, {start.x, start.y, start.phi, start.sdot, start.phidot},
                           motion.t);
    std::vector<PlannedSample> out;
    out.reserve(std::size_t(count));
    for (int i = 0; i < count; ++i) {
        const double t = i + 1 == count ? motion.t : motion.t * i / (count - 1);
        out.push_back({t, body.at(t), ghost.at(t)});
    }
    return out;
}

} // namespace chaplygin
