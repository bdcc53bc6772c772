#include "scene/summary_json.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace chaplygin {

std::string formatSummary(const Solution& solution) {
    const DerivedSystem& sys = solution.system();
    const Scene& scene = solution.scene();
    const ModelReport& m = solution.models();
    nlohmann::json j;
    j["system"] = systemKindName(scene.system.kind);
    if (!scene.preset.empty())
        j["preset"] = scene.preset;
    // a: the CM offset the control law uses (0 for the disk and the carriage); I: the inertia
    // about the CM that goes with b (I2 for the disk, J for the carriage), docs/physics.md §1
    j["a"] = sys.a;
    j["b"] = sys.b;
    j["m_eff"] = sys.mass;
    j["I"] = sys.inertia();
    j["m_translating"] = sys.translatingMass;
    j["parameters"] = scene.system.params; // as given, under their own names
    if (scene.system.kind == SystemKind::Carriage)
        j["half_axle"] = scene.system.params.at("a");
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
    if (solution.perturbed()) {
        // the two perturbed bodies' integrator and tolerance (docs/physics.md §9)
        j["models"]["perturbed"] = m.perturbed;
        j["models"]["feedback"] = m.feedback;
    }
    return j.dump(2) + "\n";
}

std::string formatPlanSummary(const PlanRequest& request, const Plan& plan,
                              const Solution* solution) {
    nlohmann::json j =
        solution ? nlohmann::json::parse(formatSummary(*solution)) : nlohmann::json::object();
    nlohmann::json motions = nlohmann::json::array();
    for (const PlannedGeodesic& g : plan.geodesics) {
        nlohmann::json m;
        m["t"] = g.t;
        m["psi0"] = g.psi0;
        m["psidot0"] = g.psidot0;
        m["lambda0"] = g.lambda0;
        m["family"] = geodesicFamilyName(g.family);
        m["cut_time"] = std::isfinite(g.cutTime) ? nlohmann::json(g.cutTime) : nlohmann::json();
        m["optimal"] = g.optimal;
        // the pendulum's modulus and 1 - k^2, carried exactly next to the separatrix where it
        // does not follow from psi0 and psidot0 in double (docs/physics.md §10)
        m["modulus"] = g.modulus;
        m["modulus_gap"] = g.modulusGap;
        motions.push_back(m);
    }
    j["plan"] = {{"from", {request.from.x, request.from.y, request.from.phi}},
                 {"to", {request.to.x, request.to.y, request.to.phi}},
                 {"horizon", plan.horizon},
                 {"certified", plan.certified},
                 {"geodesics", motions}};
    return j.dump(2) + "\n";
}

} // namespace chaplygin
