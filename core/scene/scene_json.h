#pragma once
// The scene file format: a Scene to versioned JSON and back, with the JSON path of a bad value.
#include "common/input_error.h"
#include "scene/scene.h"

#include <optional>
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

/// A scene read apart from its "annotations" member: the scene, with the marks when they were
/// good, and the refusal of a bad member.
struct SceneSparingMarks {
    Scene scene;
    std::optional<InputError> marksError;
};
/// A scene file's text read as sceneFromJson reads it, except that a bad "annotations" member
/// costs the marks only: the crash-recovery copy gives its scene back whatever became of them
/// (docs/robustness.md, Crash recovery). The member is read by the same reader; its refusal is
/// in marksError (where() "scene file /annotations..."), the scene then without marks.
SceneSparingMarks sceneFromJsonSparingMarks(const std::string& text);

/// Reads and parses a file; throws InputError naming the file when it cannot be read.
Scene loadSceneFile(const std::string& path);

} // namespace chaplygin
