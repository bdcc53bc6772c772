#pragma once
// The paper's four examples as presets (resources/scenes/presets).
#include "scene/scene.h"

#include <string>
#include <vector>

namespace chaplygin {

/// The paper's four examples (its sec. 6) with its parameters: b = 1, v_T = 1, x0 = 1, R = 1 for
/// the sinusoid. The paper leaves m, a, the line's A and B and the circle's R open; the
/// presets take m = 1, a = 0.5, A = 0.5, B = 1, R = 2. They are the files of
/// resources/scenes/presets, compiled in (scene/scene_resources.h).
std::vector<std::string> presetNames();
/// Throws InputError("preset") for unknown names.
Scene presetScene(const std::string& name);
/// One sentence for the GUI and the docs.
std::string presetDescription(const std::string& name);

} // namespace chaplygin
