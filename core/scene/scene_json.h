#pragma once
// The scene file format: a Scene to versioned JSON and back, with the JSON path of a bad value.
#include "scene/scene.h"

#include <string>

namespace chaplygin {

/// Version of the scene file format written by sceneToJson.
constexpr int kSceneFormatVersion = 1;

/// The scene as versioned JSON (the format of File > Save and of --scene).
std::string sceneToJson(const Scene& scene);

/// Parses a scene file's text. Throws InputError whose where() is "scene file" plus the JSON
/// path (e.g. "scene file /system/params/m") or the byte offset of a syntax error. Rejects
/// empty, truncated, binary, deeply nested, oversized and future-version files.
Scene sceneFromJson(const std::string& text);

/// Reads and parses a file; throws InputError naming the file when it cannot be read.
Scene loadSceneFile(const std::string& path);

} // namespace chaplygin
