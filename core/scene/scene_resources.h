#pragma once
// The scene files of resources/scenes, compiled into the core at build time.
#include <span>
#include <string_view>

namespace chaplygin {

/// One JSON file of resources/scenes, compiled into the core at build time (core/CMakeLists.txt).
struct SceneResource {
    std::string_view path; ///< relative to resources/scenes, e.g. "presets/line.json"
    std::string_view text; ///< the file's contents
};

/// Every scene file in the order of core/CMakeLists.txt: the presets, then the gallery.
std::span<const SceneResource> sceneResources();

} // namespace chaplygin
