#pragma once
// A lecture: an ordered list of scenes, each with its note and a title, stepped through with
// Page Up / Page Down; its versioned JSON file and back, every scene checked by the scene reader.
#include "scene/scene.h"

#include <cstddef>
#include <string>
#include <vector>

namespace chaplygin {

/// Version of the lecture file format written by lectureToJson.
constexpr int kLectureFormatVersion = 1;
/// The "format" of a lecture file.
constexpr const char* kLectureFormatName = "chaplygin-lab-lecture";
/// At most this many scenes in a lecture.
constexpr std::size_t kMaxLectureScenes = 500;
/// A lecture file is at most this many bytes (as many as a scene file).
constexpr std::size_t kMaxLectureFileBytes = 16u << 20;
/// A lecture's or an entry's title is at most this many bytes (UTF-8).
constexpr std::size_t kMaxLectureTitleBytes = 1000;

/// One scene of a lecture, with the line the list shows for it (may be empty). What the
/// lecturer says about it is the scene's note.
struct LectureEntry {
    std::string title;
    Scene scene;

    bool operator==(const LectureEntry&) const = default;
};

/// Scenes in the order of a lesson. Each keeps what its scene file keeps (its arrows, pins,
/// plan and note).
struct Lecture {
    std::string title;
    std::vector<LectureEntry> entries;

    bool operator==(const Lecture&) const = default;
};

/// The lecture as versioned JSON: {"format": "chaplygin-lab-lecture", "version": 1, "title",
/// "scenes": [scene objects as sceneToJson writes them, each with an optional "title"]}.
std::string lectureToJson(const Lecture& lecture);

/// Parses a lecture file's text. Throws InputError whose where() is "lecture file" plus the JSON
/// path; a scene that fails the scene file's checks is named by its index and the field inside
/// it ("lecture file /scenes/2/system/params/m"). Rejects empty, truncated, binary, deeply
/// nested, oversized and future-version files, and more than kMaxLectureScenes scenes.
Lecture lectureFromJson(const std::string& text);

/// Whether text is a JSON object whose "format" is a lecture's (so that File > Open can tell a
/// lecture from a scene); false for anything else, never throws.
bool isLectureText(const std::string& text);

/// Reads a file's text, at most kMaxLectureFileBytes + 1 bytes; throws InputError naming the
/// file when it cannot be read.
std::string readLectureOrSceneText(const std::string& path);

/// Reads and parses a lecture file; throws InputError naming the file when it cannot be read.
Lecture loadLectureFile(const std::string& path);

/// Writes the lecture whole or not at all (writeFileAtomically); throws IoError.
void saveLectureFile(const std::string& path, const Lecture& lecture);

} // namespace chaplygin
