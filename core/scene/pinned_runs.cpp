#include "scene/pinned_runs.h"

#include <cstdio>
#include <set>

namespace chaplygin {
namespace {

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

std::string unitOf(const std::string& name) {
    if (name == "m" || name == "M")
        return " kg";
    if (name == "I" || name == "I1" || name == "I2")
        return " kg m\u00b2";
    return " m"; // a, b, R
}

void add(std::string& label, const std::string& part) {
    label += (label.empty() ? "" : ", ") + part;
}

} // namespace

PinnedRun pinOf(const Scene& scene) {
    return {scene.path, scene.system, scene.mode, scene.speed, scene.tEnd};
}

Scene sceneOf(const PinnedRun& pin) {
    Scene s;
    s.path = pin.path;
    s.system = pin.system;
    s.mode = pin.mode;
    s.speed = pin.speed;
    s.tEnd = pin.tEnd;
    return s;
}

std::string pinLabel(const PinnedRun& pin, const Scene& current) {
    std::string label;
    if (pin.system.kind != current.system.kind) {
        add(label, systemKindName(pin.system.kind));
    } else {
        std::set<std::string> names;
        for (const auto& [k, v] : pin.system.params)
            names.insert(k);
        for (const auto& [k, v] : current.system.params)
            names.insert(k);
        for (const std::string& k : names) {
            auto p = pin.system.params.find(k);
            auto c = current.system.params.find(k);
            if (p == pin.system.params.end())
                continue; // the pin did not set it (e.g. I where b was given)
            if (c == current.system.params.end() || c->second != p->second)
                add(label, k + " = " + number(p->second) + unitOf(k));
        }
    }
    if (pin.mode != current.mode)
        add(label, pin.mode == SpeedMode::Energy ? "constant energy" : "constant speed");
    if (pin.speed != current.speed || pin.mode != current.mode)
        add(label, std::string(pin.mode == SpeedMode::Energy ? "v_T" : "v_s") + " = " +
                       number(pin.speed) + " m/s");
    if (pin.path != current.path)
        add(label, "another path");
    if (pin.tEnd != current.tEnd)
        add(label, pin.tEnd ? "t_end = " + number(*pin.tEnd) + " s" : "to the path's end");
    return label.empty() ? "same parameters" : label;
}

} // namespace chaplygin
