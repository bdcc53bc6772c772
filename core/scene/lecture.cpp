#include "scene/lecture.h"

#include "common/atomic_file.h"
#include "common/input_error.h"
#include "scene/json_file_shape.h"
#include "scene/scene_json.h"

#include <nlohmann/json.hpp>

#include <fstream>

namespace chaplygin {
namespace {

using nlohmann::json;

// a scene inside is nested two levels deeper than in its own file
constexpr int kMaxNesting = 34;

[[noreturn]] void bad(const std::string& pointer, const std::string& what) {
    throw InputError("lecture file " + (pointer.empty() ? std::string("/") : pointer), what);
}

void checkShape(const std::string& text) {
    checkJsonFileShape(text, "lecture file", "a lecture", kMaxLectureFileBytes, kMaxNesting);
}

json parse(const std::string& text) {
    try {
        return json::parse(text);
    } catch (const json::parse_error& e) {
        const std::string msg = e.what();
        const auto pos = msg.find("parse error");
        throw InputError("lecture file, byte " + std::to_string(e.byte),
                         "not valid JSON (" + (pos == std::string::npos ? msg : msg.substr(pos)) +
                             ")");
    } catch (const json::exception& e) {
        // a number beyond double range is out_of_range, not a parse_error
        const std::string msg = e.what();
        const auto pos = msg.find("] ");
        throw InputError("lecture file",
                         "not readable (" + (pos == std::string::npos ? msg : msg.substr(pos + 2)) +
                             ")");
    }
}

std::string title(const json& v, const std::string& pointer) {
    if (!v.is_string())
        bad(pointer, std::string("must be a string, got ") + v.type_name());
    std::string t = v.get<std::string>();
    if (t.size() > kMaxLectureTitleBytes)
        bad(pointer, "is " + std::to_string(t.size()) + " bytes; a title is at most " +
                         std::to_string(kMaxLectureTitleBytes) + " bytes");
    return t;
}

// the scene reader's checks, its place moved under the scene's index: "scene file /speed"
// becomes "lecture file /scenes/2/speed"
Scene readScene(const json& v, const std::string& at) {
    try {
        return sceneFromJson(v.dump(-1, ' ', false, json::error_handler_t::replace));
    } catch (const InputError& e) {
        const std::string message = e.what();
        const std::string what = message.substr(std::min(message.size(), e.where().size() + 2));
        const std::string prefix = "scene file ";
        std::string inside;
        if (e.where().starts_with(prefix + "/") && e.where() != prefix + "/")
            inside = e.where().substr(prefix.size());
        bad(at + inside, what);
    }
}

} // namespace

std::string lectureToJson(const Lecture& lecture) {
    json j;
    j["format"] = kLectureFormatName;
    j["version"] = kLectureFormatVersion;
    j["title"] = lecture.title;
    j["scenes"] = json::array();
    for (const LectureEntry& e : lecture.entries) {
        json scene = json::parse(sceneToJson(e.scene));
        if (!e.title.empty())
            scene["title"] = e.title;
        j["scenes"].push_back(std::move(scene));
    }
    return j.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

Lecture lectureFromJson(const std::string& text) {
    checkShape(text);
    const json j = parse(text);
    if (!j.is_object())
        bad("", std::string("must be an object, got ") + j.type_name());
    if (auto it = j.find("format"); it == j.end() || !it->is_string() || *it != kLectureFormatName)
        bad("/format", std::string("must be \"") + kLectureFormatName +
                           "\" (is this a Chaplygin Lab lecture?)");
    const auto version = j.find("version");
    if (version == j.end())
        bad("", "missing \"version\"");
    if (!version->is_number_integer())
        bad("/version", "must be an integer");
    if (version->get<long long>() > kLectureFormatVersion)
        bad("/version", "the file is version " + std::to_string(version->get<long long>()) +
                            "; this Chaplygin Lab reads up to version " +
                            std::to_string(kLectureFormatVersion) +
                            " (it was written by a newer release)");
    if (version->get<long long>() < 1)
        bad("/version", "must be >= 1");
    Lecture lecture;
    if (auto it = j.find("title"); it != j.end())
        lecture.title = title(*it, "/title");
    const auto scenes = j.find("scenes");
    if (scenes == j.end())
        bad("", "missing \"scenes\"");
    if (!scenes->is_array())
        bad("/scenes", std::string("must be an array, got ") + scenes->type_name());
    if (scenes->size() > kMaxLectureScenes)
        bad("/scenes", "has " + std::to_string(scenes->size()) + " scenes; a lecture has at most " +
                           std::to_string(kMaxLectureScenes));
    for (std::size_t i = 0; i < scenes->size(); ++i) {
        const std::string at = "/scenes/" + std::to_string(i);
        const json& s = (*scenes)[i];
        if (!s.is_object())
            bad(at, std::string("must be a scene object, got ") + s.type_name());
        LectureEntry entry;
        if (auto it = s.find("title"); it != s.end())
            entry.title = title(*it, at + "/title");
        entry.scene = readScene(s, at);
        lecture.entries.push_back(std::move(entry));
    }
    return lecture;
}

bool isLectureText(const std::string& text) {
    const json j = json::parse(text, nullptr, false);
    if (!j.is_object())
        return false;
    const auto it = j.find("format");
    return it != j.end() && it->is_string() && *it == kLectureFormatName;
}

std::string readLectureOrSceneText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError("lecture file", "cannot open '" + path + "'");
    std::string text(kMaxLectureFileBytes + 1, '\0');
    in.read(text.data(), std::streamsize(text.size()));
    if (in.bad())
        throw InputError("lecture file", "cannot read '" + path + "'");
    text.resize(std::size_t(in.gcount()));
    return text;
}

Lecture loadLectureFile(const std::string& path) {
    return lectureFromJson(readLectureOrSceneText(path));
}

void saveLectureFile(const std::string& path, const Lecture& lecture) {
    writeFileAtomically(path, lectureToJson(lecture));
}

} // namespace chaplygin
