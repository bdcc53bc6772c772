#include "scene/summary_json.h"

#include <nlohmann/json.hpp>

namespace chaplygin {

std::string formatSummary(const Solution& solution) {
    const DerivedSystem& sys = solution.system();
    const Scene& scene = solution.scene();
    const ModelReport& m = solution.models();
    nlohmann::json j;
    j["system"] = systemKindName(scene.system.kind);
    if (!scene.preset.empty())
        j["preset"] = scene.preset;
    j["a"] = sys.a;
    j["b"] = sys.b;
    j["m_eff"] = sys.mass;
    j["I"] = sys.inertia();
    j["mode"] = speedModeName(scene.mode);
    j[scene.mode == SpeedMode::Energy ? "v_T" : "v_s"] = scene.speed;
    j["path_length"] = solution.path()->length();
    j["duration"] = solution.duration();
    j["t_end"] = solution.tEnd();
    j["pivots"] = solution.path()->pivotCount();
    j["models"] = {{"path", m.path},
                   {"time_law", m.timeLaw},
                   {"inversion", m.inversion},
                   {"control", m.control},
                   {"free_velocity", m.freeVelocity},
                   {"free_position", m.freePosition},
                   {"vakonomic", m.vakonomic}};
    return j.dump(2) + "\n";
}

} // namespace chaplygin
