#include "scene/presets.h"

#include "common/input_error.h"
#include "scene/scene_json.h"
#include "scene/scene_resources.h"

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace chaplygin {
namespace {

struct Preset {
    std::string name;
    std::string description;
    Scene scene;
};

// resources/scenes/presets/*.json, each a scene file with "preset" and "description"
const std::vector<Preset>& presets() {
    static const std::vector<Preset> all = [] {
        std::vector<Preset> list;
        for (const SceneResource& file : sceneResources()) {
            if (!file.path.starts_with("presets/"))
                continue;
            std::string text(file.text);
            try {
                Scene scene = sceneFromJson(text);
                nlohmann::json j = nlohmann::json::parse(text);
                list.push_back({scene.preset, j.at("description").get<std::string>(), scene});
            } catch (const std::exception& err) {
                // a resource compiled into the program: a build defect, not bad input
                throw std::logic_error("resources/scenes/" + std::string(file.path) + ": " +
                                       err.what());
            }
        }
        return list;
    }();
    return all;
}

} // namespace

std::vector<std::string> presetNames() {
    std::vector<std::string> names;
    for (const Preset& p : presets())
        names.push_back(p.name);
    return names;
}

Scene presetScene(const std::string& name) {
    for (const Preset& p : presets())
        if (p.name == name)
            return p.scene;
    std::string known;
    const std::vector<std::string> names = presetNames();
    for (std::size_t i = 0; i < names.size(); ++i)
        known += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    throw InputError("preset", "unknown preset '" + name + "' (use " + known + ")");
}

std::string presetDescription(const std::string& name) {
    for (const Preset& p : presets())
        if (p.name == name)
            return p.description;
    return {};
}

} // namespace chaplygin
