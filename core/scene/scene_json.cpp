#include "scene/scene_json.h"

#include "common/input_error.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

namespace chaplygin {
namespace {

using nlohmann::json;

constexpr std::size_t kMaxFileBytes = 16u << 20;
constexpr int kMaxNesting = 32;
constexpr const char* kFormatName = "chaplygin-lab-scene";

std::string kindName(PathKind k) {
    switch (k) {
    case PathKind::Graph:
        return "graph";
    case PathKind::Parametric:
        return "parametric";
    case PathKind::Polyline:
        return "polyline";
    }
    return "graph";
}

[[noreturn]] void bad(const std::string& pointer, const std::string& what) {
    throw InputError("scene file " + (pointer.empty() ? std::string("/") : pointer), what);
}

const json& member(const json& obj, const std::string& pointer, const char* key) {
    auto it = obj.find(key);
    if (it == obj.end())
        bad(pointer, std::string("missing \"") + key + "\"");
    return *it;
}

double number(const json& v, const std::string& pointer) {
    if (!v.is_number())
        bad(pointer, std::string("must be a number, got ") + v.type_name());
    double d = v.get<double>();
    if (!std::isfinite(d))
        bad(pointer, "must be finite");
    return d;
}

std::string string(const json& v, const std::string& pointer) {
    if (!v.is_string())
        bad(pointer, std::string("must be a string, got ") + v.type_name());
    return v.get<std::string>();
}

const json& object(const json& v, const std::string& pointer) {
    if (!v.is_object())
        bad(pointer, std::string("must be an object, got ") + v.type_name());
    return v;
}

void checkShape(const std::string& text) {
    if (text.empty())
        bad("", "the file is empty");
    if (text.size() > kMaxFileBytes)
        bad("", "the file is " + std::to_string(text.size()) + " bytes; a scene is at most " +
                    std::to_string(kMaxFileBytes) + " bytes");
    if (text.size() >= 3 && static_cast<unsigned char>(text[0]) == 0xEF &&
        static_cast<unsigned char>(text[1]) == 0xBB && static_cast<unsigned char>(text[2]) == 0xBF)
        bad("", "the file starts with a UTF-8 byte-order mark; save it as plain UTF-8");
    int depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (c == '\0')
            bad("",
                "the file contains a NUL byte at offset " + std::to_string(i) + " (binary data?)");
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '{' || c == '[') {
            if (++depth > kMaxNesting)
                bad("", "nested deeper than " + std::to_string(kMaxNesting) + " levels at offset " +
                            std::to_string(i));
        } else if (c == '}' || c == ']') {
            --depth;
        }
    }
}

PathSource readPath(const json& p) {
    object(p, "/path");
    PathSource src;
    std::string kind = string(member(p, "/path", "kind"), "/path/kind");
    auto range = [&]() {
        const json& r = member(p, "/path", "range");
        if (!r.is_array() || r.size() != 2)
            bad("/path/range", "must be an array of two numbers [from, to]");
        src.from = number(r[0], "/path/range/0");
        src.to = number(r[1], "/path/range/1");
    };
    if (kind == "graph") {
        src.kind = PathKind::Graph;
        src.y = string(member(p, "/path", "y"), "/path/y");
        range();
    } else if (kind == "parametric") {
        src.kind = PathKind::Parametric;
        src.xOfU = string(member(p, "/path", "x"), "/path/x");
        src.yOfU = string(member(p, "/path", "y"), "/path/y");
        range();
    } else if (kind == "polyline") {
        src.kind = PathKind::Polyline;
        const json& pts = member(p, "/path", "points");
        if (!pts.is_array())
            bad("/path/points", "must be an array of [x, y] pairs");
        for (std::size_t i = 0; i < pts.size(); ++i) {
            std::string ptr = "/path/points/" + std::to_string(i);
            if (!pts[i].is_array() || pts[i].size() != 2)
                bad(ptr, "must be an [x, y] pair");
            src.points.emplace_back(number(pts[i][0], ptr + "/0"), number(pts[i][1], ptr + "/1"));
        }
        if (auto it = p.find("corners"); it != p.end()) {
            std::string c = string(*it, "/path/corners");
            if (c != "pivot" && c != "smooth")
                bad("/path/corners", "must be \"pivot\" or \"smooth\", got \"" + c + "\"");
            src.corners = cornerModeFromName(c);
        }
        if (auto it = p.find("smoothing"); it != p.end())
            src.smoothing = number(*it, "/path/smoothing");
    } else {
        bad("/path/kind",
            "must be \"graph\", \"parametric\" or \"polyline\", got \"" + kind + "\"");
    }
    return src;
}

} // namespace

std::string sceneToJson(const Scene& scene) {
    json j;
    j["format"] = kFormatName;
    j["version"] = kSceneFormatVersion;
    if (!scene.preset.empty())
        j["preset"] = scene.preset;
    json p;
    p["kind"] = kindName(scene.path.kind);
    switch (scene.path.kind) {
    case PathKind::Graph:
        p["y"] = scene.path.y;
        p["range"] = {scene.path.from, scene.path.to};
        break;
    case PathKind::Parametric:
        p["x"] = scene.path.xOfU;
        p["y"] = scene.path.yOfU;
        p["range"] = {scene.path.from, scene.path.to};
        break;
    case PathKind::Polyline:
        p["points"] = json::array();
        for (auto [x, y] : scene.path.points)
            p["points"].push_back({x, y});
        p["corners"] = cornerModeName(scene.path.corners);
        p["smoothing"] = scene.path.smoothing;
        break;
    }
    j["path"] = p;
    j["system"] = {{"kind", systemKindName(scene.system.kind)}, {"params", scene.system.params}};
    j["mode"] = speedModeName(scene.mode);
    j["speed"] = scene.speed;
    if (scene.tEnd)
        j["t_end"] = *scene.tEnd;
    return j.dump(2) + "\n";
}

Scene sceneFromJson(const std::string& text) {
    checkShape(text);
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        std::string msg = e.what();
        auto pos = msg.find("parse error");
        throw InputError("scene file, byte " + std::to_string(e.byte),
                         "not valid JSON (" + (pos == std::string::npos ? msg : msg.substr(pos)) +
                             ")");
    } catch (const json::exception& e) {
        // e.g. a number beyond double range (out_of_range.406), found by fuzz_scene
        std::string msg = e.what();
        auto pos = msg.find("] ");
        throw InputError("scene file", "not readable (" +
                                           (pos == std::string::npos ? msg : msg.substr(pos + 2)) +
                                           ")");
    }
    object(j, "");
    if (auto it = j.find("format"); it == j.end() || !it->is_string() || *it != kFormatName)
        bad("/format",
            std::string("must be \"") + kFormatName + "\" (is this a Chaplygin Lab scene?)");
    const json& version = member(j, "", "version");
    if (!version.is_number_integer())
        bad("/version", "must be an integer");
    if (version.get<long long>() > kSceneFormatVersion)
        bad("/version", "the file is version " + std::to_string(version.get<long long>()) +
                            "; this Chaplygin Lab reads up to version " +
                            std::to_string(kSceneFormatVersion) +
                            " (it was written by a newer release)");
    if (version.get<long long>() < 1)
        bad("/version", "must be >= 1");

    Scene s;
    if (auto it = j.find("preset"); it != j.end())
        s.preset = string(*it, "/preset");
    s.path = readPath(member(j, "", "path"));
    const json& sys = object(member(j, "", "system"), "/system");
    try {
        s.system.kind = systemKindFromName(string(member(sys, "/system", "kind"), "/system/kind"));
    } catch (const InputError& e) {
        bad("/system/kind", e.what());
    }
    const json& params = object(member(sys, "/system", "params"), "/system/params");
    s.system.params.clear();
    for (auto it = params.begin(); it != params.end(); ++it)
        s.system.params[it.key()] = number(it.value(), "/system/params/" + it.key());
    std::string mode = string(member(j, "", "mode"), "/mode");
    if (mode != "energy" && mode != "speed")
        bad("/mode", "must be \"energy\" or \"speed\", got \"" + mode + "\"");
    s.mode = speedModeFromName(mode);
    s.speed = number(member(j, "", "speed"), "/speed");
    if (auto it = j.find("t_end"); it != j.end() && !it->is_null())
        s.tEnd = number(*it, "/t_end");
    return s;
}

Scene loadSceneFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError("scene_file", "cannot open '" + path + "'");
    std::ostringstream buf;
    buf << in.rdbuf();
    if (in.bad())
        throw InputError("scene_file", "cannot read '" + path + "'");
    return sceneFromJson(buf.str());
}

} // namespace chaplygin
