#include "scene/scene_json.h"

#include "common/input_error.h"
#include "scene/annotations_json.h"
#include "scene/json_file_shape.h"
#include "scene/lecture.h"
#include "scene/perturbation.h"
#include "scene/pinned_runs.h"

#include <nlohmann/json.hpp>

#include <algorithm>
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
    case PathKind::Geodesic:
        return "geodesic";
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
    checkJsonFileShape(text, "scene file", "a scene", kMaxFileBytes, kMaxNesting);
}

PathSource readPath(const json& p, const std::string& at) {
    object(p, at);
    PathSource src;
    std::string kind = string(member(p, at, "kind"), at + "/kind");
    auto range = [&]() {
        const json& r = member(p, at, "range");
        if (!r.is_array() || r.size() != 2)
            bad(at + "/range", "must be an array of two numbers [from, to]");
        src.from = number(r[0], at + "/range/0");
        src.to = number(r[1], at + "/range/1");
    };
    if (kind == "graph") {
        src.kind = PathKind::Graph;
        src.y = string(member(p, at, "y"), at + "/y");
        range();
    } else if (kind == "parametric") {
        src.kind = PathKind::Parametric;
        src.xOfU = string(member(p, at, "x"), at + "/x");
        src.yOfU = string(member(p, at, "y"), at + "/y");
        range();
    } else if (kind == "polyline") {
        src.kind = PathKind::Polyline;
        const json& pts = member(p, at, "points");
        if (!pts.is_array())
            bad(at + "/points", "must be an array of [x, y] pairs");
        for (std::size_t i = 0; i < pts.size(); ++i) {
            std::string ptr = at + "/points/" + std::to_string(i);
            if (!pts[i].is_array() || pts[i].size() != 2)
                bad(ptr, "must be an [x, y] pair");
            src.points.emplace_back(number(pts[i][0], ptr + "/0"), number(pts[i][1], ptr + "/1"));
        }
        if (auto it = p.find("corners"); it != p.end()) {
            std::string c = string(*it, at + "/corners");
            if (c != "pivot" && c != "smooth")
                bad(at + "/corners", "must be \"pivot\" or \"smooth\", got \"" + c + "\"");
            src.corners = cornerModeFromName(c);
        }
        if (auto it = p.find("smoothing"); it != p.end())
            src.smoothing = number(*it, at + "/smoothing");
        if (auto it = p.find("corner_angle"); it != p.end())
            src.cornerAngle = number(*it, at + "/corner_angle");
    } else if (kind == "geodesic") {
        src.kind = PathKind::Geodesic;
        GeodesicTrack& g = src.geodesic;
        const json& from = member(p, at, "from");
        if (!from.is_array() || from.size() != 3)
            bad(at + "/from", "must be an array of three numbers [x, y, phi]");
        g.x = number(from[0], at + "/from/0");
        g.y = number(from[1], at + "/from/1");
        g.phi = number(from[2], at + "/from/2");
        g.b = number(member(p, at, "b"), at + "/b");
        g.psi0 = number(member(p, at, "psi0"), at + "/psi0");
        g.lambda0 = number(member(p, at, "lambda0"), at + "/lambda0");
        g.length = number(member(p, at, "length"), at + "/length");
    } else {
        bad(at + "/kind", "must be \"graph\", \"parametric\", \"polyline\" or \"geodesic\", "
                          "got \"" +
                              kind + "\"");
    }
    return src;
}

// the fields that define a run, at the top level (at = "") or in a pin (at = "/pins/N")
PinnedRun readRun(const json& j, const std::string& at) {
    PinnedRun r;
    r.path = readPath(member(j, at, "path"), at + "/path");
    const json& sys = object(member(j, at, "system"), at + "/system");
    try {
        r.system.kind =
            systemKindFromName(string(member(sys, at + "/system", "kind"), at + "/system/kind"));
    } catch (const InputError& e) {
        bad(at + "/system/kind", e.what());
    }
    const json& params = object(member(sys, at + "/system", "params"), at + "/system/params");
    r.system.params.clear();
    for (auto it = params.begin(); it != params.end(); ++it)
        r.system.params[it.key()] = number(it.value(), at + "/system/params/" + it.key());
    std::string mode = string(member(j, at, "mode"), at + "/mode");
    if (mode != "energy" && mode != "speed")
        bad(at + "/mode", "must be \"energy\" or \"speed\", got \"" + mode + "\"");
    r.mode = speedModeFromName(mode);
    r.speed = number(member(j, at, "speed"), at + "/speed");
    if (auto it = j.find("t_end"); it != j.end() && !it->is_null())
        r.tEnd = number(*it, at + "/t_end");
    return r;
}

json writePath(const PathSource& path) {
    json p;
    p["kind"] = kindName(path.kind);
    switch (path.kind) {
    case PathKind::Graph:
        p["y"] = path.y;
        p["range"] = {path.from, path.to};
        break;
    case PathKind::Parametric:
        p["x"] = path.xOfU;
        p["y"] = path.yOfU;
        p["range"] = {path.from, path.to};
        break;
    case PathKind::Polyline:
        p["points"] = json::array();
        for (auto [x, y] : path.points)
            p["points"].push_back({x, y});
        p["corners"] = cornerModeName(path.corners);
        p["smoothing"] = path.smoothing;
        p["corner_angle"] = path.cornerAngle;
        break;
    case PathKind::Geodesic:
        p["from"] = {path.geodesic.x, path.geodesic.y, path.geodesic.phi};
        p["b"] = path.geodesic.b;
        p["psi0"] = path.geodesic.psi0;
        p["lambda0"] = path.geodesic.lambda0;
        p["length"] = path.geodesic.length;
        break;
    }
    return p;
}

void writeRun(json& j, const PinnedRun& r) {
    j["path"] = writePath(r.path);
    j["system"] = {{"kind", systemKindName(r.system.kind)}, {"params", r.system.params}};
    j["mode"] = speedModeName(r.mode);
    j["speed"] = r.speed;
    if (r.tEnd)
        j["t_end"] = *r.tEnd;
}

// the vector overlay's keys in the file, in the order of View > Vectors
struct VectorKey {
    const char* key;
    VectorToggle VectorOverlay::*toggle;
};
constexpr VectorKey kVectorKeys[] = {
    {"knife_velocity", &VectorOverlay::knifeVelocity},
    {"axial_force", &VectorOverlay::axialForce},
    {"lateral_reaction", &VectorOverlay::lateralReaction},
    {"control_couple", &VectorOverlay::controlCouple},
    {"cm_velocity", &VectorOverlay::cmVelocity},
};

VectorOverlay readVectors(const json& v) {
    object(v, "/vectors");
    VectorOverlay o;
    for (auto it = v.begin(); it != v.end(); ++it) {
        const std::string at = "/vectors/" + it.key();
        const VectorKey* k = nullptr;
        for (const VectorKey& c : kVectorKeys)
            if (it.key() == c.key)
                k = &c;
        if (!k)
            bad(at, "unknown arrow (use knife_velocity, axial_force, lateral_reaction, "
                    "control_couple or cm_velocity)");
        object(it.value(), at);
        VectorToggle& t = o.*(k->toggle);
        if (auto s = it->find("shown"); s != it->end()) {
            if (!s->is_boolean())
                bad(at + "/shown", std::string("must be true or false, got ") + s->type_name());
            t.shown = s->get<bool>();
        }
        if (auto s = it->find("scale"); s != it->end()) {
            t.scale = number(*s, at + "/scale");
            if (!(t.scale >= 0))
                bad(at + "/scale", "must be >= 0 (0 scales automatically)");
        }
    }
    return o;
}

// "perturbation": {NAME: VALUE} (docs/physics.md §9); a bad field is named by its JSON path
Perturbation readPerturbation(const json& v) {
    object(v, "/perturbation");
    Perturbation p;
    for (auto it = v.begin(); it != v.end(); ++it) {
        const std::string at = "/perturbation/" + it.key();
        const double value = number(it.value(), at);
        try {
            setPerturbationField(p, it.key(), value);
        } catch (const InputError& e) {
            const std::string message = e.what();
            bad(e.where() == "perturbation" ? std::string("/perturbation") : at,
                message.substr(std::min(message.size(), e.where().size() + 2)));
        }
    }
    try {
        checkPerturbation(p);
    } catch (const InputError& e) {
        const std::string message = e.what();
        bad("/perturbation/" + e.where().substr(std::string("perturbation ").size()),
            message.substr(std::min(message.size(), e.where().size() + 2)));
    }
    return p;
}

json writePose(const Pose& pose) {
    return json::array({pose.x, pose.y, pose.phi});
}

// a pose as [x, y, phi]: metres and radians
Pose readPose(const json& v, const std::string& at) {
    if (!v.is_array() || v.size() != 3)
        bad(at, "must be [x, y, phi] (metres and radians)");
    return {number(v[0], at + "/0"), number(v[1], at + "/1"), number(v[2], at + "/2")};
}

// "plan": {"to": [x, y, phi], "from": [x, y, phi], "horizon": T, "choice": N} (docs/physics.md
// §10); only "to" is required
ScenePlan readPlan(const json& v) {
    object(v, "/plan");
    ScenePlan plan;
    for (auto it = v.begin(); it != v.end(); ++it) {
        const std::string at = "/plan/" + it.key();
        if (it.key() == "to") {
            plan.to = readPose(it.value(), at);
        } else if (it.key() == "from") {
            plan.from = readPose(it.value(), at);
        } else if (it.key() == "horizon") {
            plan.horizon = number(it.value(), at);
            if (!(*plan.horizon > 0))
                bad(at, "must be > 0 [s]");
        } else if (it.key() == "choice") {
            if (!it->is_number_integer() || it->get<long long>() < 0 ||
                it->get<long long>() > 1000000)
                bad(at, "must be a whole number >= 0 (the motion's place in the list)");
            plan.choice = int(it->get<long long>());
        } else {
            bad(at, "unknown field (use to, from, horizon or choice)");
        }
    }
    member(v, "/plan", "to");
    return plan;
}

} // namespace

std::string sceneToJson(const Scene& scene) {
    json j;
    j["format"] = kFormatName;
    j["version"] = kSceneFormatVersion;
    if (!scene.preset.empty())
        j["preset"] = scene.preset;
    writeRun(j, pinOf(scene));
    if (scene.perturbation) {
        json p = json::object();
        for (const auto& [name, value] : perturbationFields(*scene.perturbation))
            p[name] = value;
        j["perturbation"] = p;
    }
    if (scene.vectors != VectorOverlay{}) {
        json v = json::object();
        for (const VectorKey& k : kVectorKeys) {
            const VectorToggle& t = scene.vectors.*(k.toggle);
            if (t != VectorToggle{})
                v[k.key] = {{"shown", t.shown}, {"scale", t.scale}};
        }
        j["vectors"] = v;
    }
    if (!scene.note.empty())
        j["note"] = scene.note;
    if (!scene.pins.empty()) {
        j["pins"] = json::array();
        for (const PinnedRun& pin : scene.pins) {
            json p;
            writeRun(p, pin);
            j["pins"].push_back(p);
        }
    }
    if (scene.plan) {
        json p = json::object();
        p["to"] = writePose(scene.plan->to);
        if (scene.plan->from)
            p["from"] = writePose(*scene.plan->from);
        if (scene.plan->horizon)
            p["horizon"] = *scene.plan->horizon;
        p["choice"] = scene.plan->choice;
        j["plan"] = p;
    }
    if (!scene.annotations.empty())
        j["annotations"] = annotationsToJson(scene.annotations);
    return j.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

namespace {

// the text as JSON, after its shape is checked
json parseSceneText(const std::string& text) {
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
    return j;
}

Scene readScene(const json& j) {
    object(j, "");
    if (auto it = j.find("format"); it != j.end() && *it == kLectureFormatName)
        bad("/format", "the file is a lecture (\"" + std::string(kLectureFormatName) +
                           "\"), not a scene: open it in the window, or save one of its scenes "
                           "from there");
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
    PinnedRun run = readRun(j, "");
    s.path = run.path;
    s.system = run.system;
    s.mode = run.mode;
    s.speed = run.speed;
    s.tEnd = run.tEnd;
    if (auto it = j.find("perturbation"); it != j.end())
        s.perturbation = readPerturbation(*it);
    if (auto it = j.find("vectors"); it != j.end())
        s.vectors = readVectors(*it);
    if (auto it = j.find("note"); it != j.end()) {
        s.note = string(*it, "/note");
        if (s.note.size() > kMaxNoteBytes)
            bad("/note", "is " + std::to_string(s.note.size()) + " bytes; a note is at most " +
                             std::to_string(kMaxNoteBytes) + " bytes");
    }
    if (auto it = j.find("pins"); it != j.end()) {
        if (!it->is_array())
            bad("/pins", std::string("must be an array, got ") + it->type_name());
        if (it->size() > kMaxPinnedRuns)
            bad("/pins", "has " + std::to_string(it->size()) + " pinned runs; at most " +
                             std::to_string(kMaxPinnedRuns) + " are kept");
        for (std::size_t i = 0; i < it->size(); ++i) {
            std::string at = "/pins/" + std::to_string(i);
            s.pins.push_back(readRun(object((*it)[i], at), at));
        }
    }
    if (auto it = j.find("plan"); it != j.end())
        s.plan = readPlan(*it);
    if (auto it = j.find("annotations"); it != j.end())
        s.annotations = annotationsFromJson(*it, "/annotations");
    return s;
}

} // namespace

Scene sceneFromJson(const std::string& text) {
    return readScene(parseSceneText(text));
}

SceneSparingMarks sceneFromJsonSparingMarks(const std::string& text) {
    json j = parseSceneText(text);
    const auto marks = j.find("annotations");
    if (marks == j.end())
        return {readScene(j), std::nullopt};
    const json member = *marks;
    j.erase(marks);
    SceneSparingMarks read{readScene(j), std::nullopt};
    try {
        read.scene.annotations = annotationsFromJson(member, "/annotations");
    } catch (const InputError& e) {
        read.marksError = e;
    }
    return read;
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
