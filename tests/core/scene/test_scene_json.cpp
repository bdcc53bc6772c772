// Scene files: round trip, and rejection of broken files with the JSON path named.
#include "common/atomic_file.h"
#include "common/input_error.h"
#include "scene/pinned_runs.h"
#include "scene/presets.h"
#include "scene/scene_json.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <sys/stat.h>
#include <sys/sysmacros.h>

using namespace chaplygin;

namespace {

std::string errorOf(const std::string& text) {
    try {
        sceneFromJson(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(SceneJson, RoundTripsEveryPreset) {
    for (const std::string& name : presetNames()) {
        Scene s = presetScene(name);
        s.tEnd = 2.5;
        EXPECT_EQ(sceneFromJson(sceneToJson(s)), s) << name;
    }
    Scene drawn;
    drawn.path.kind = PathKind::Polyline;
    drawn.path.points = {{0, 0}, {1, 0.1}, {2, -0.3}};
    drawn.path.corners = CornerMode::Smooth;
    drawn.path.cornerAngle = 50;
    drawn.system.kind = SystemKind::Disk;
    drawn.system.params = {{"m", 1}, {"R", 0.5}, {"I1", 0.1}, {"I2", 0.05}};
    drawn.mode = SpeedMode::Speed;
    EXPECT_EQ(sceneFromJson(sceneToJson(drawn)), drawn);
}

TEST(SceneJson, BrokenFilesAreRejectedWithTheirPlace) {
    std::string good = sceneToJson(presetScene("catenary"));
    EXPECT_NE(errorOf("").find("empty"), std::string::npos);
    EXPECT_NE(errorOf(good.substr(0, good.size() / 2)).find("not valid JSON"), std::string::npos);
    EXPECT_NE(errorOf("\xEF\xBB\xBF" + good).find("byte-order mark"), std::string::npos);
    EXPECT_NE(errorOf(std::string("{\"a\":\0}", 7)).find("NUL"), std::string::npos);
    EXPECT_NE(errorOf(std::string(100, '[') + std::string(100, ']')).find("nested deeper"),
              std::string::npos);
    EXPECT_NE(errorOf("[1,2]").find("scene file /: must be an object"), std::string::npos)
        << errorOf("[1,2]");
    std::string s = good;
    s.replace(s.find("\"speed\": 1.0"), 12, "\"speed\": \"fast\"");
    EXPECT_NE(errorOf(s).find("scene file /speed: must be a number"), std::string::npos)
        << errorOf(s);
    s = good;
    s.replace(s.find("\"version\": 1"), 12, "\"version\": 7");
    EXPECT_NE(errorOf(s).find("newer release"), std::string::npos) << errorOf(s);
    s = good;
    s.replace(s.find("\"m\": 1.0"), 8, "\"m\": NaN");
    EXPECT_NE(errorOf(s).find("not valid JSON"), std::string::npos) << errorOf(s);
    s = good;
    s.replace(s.find("\"range\": ["), 10, "\"range\": [\"a\", ");
    EXPECT_NE(errorOf(s).find("/path/range"), std::string::npos) << errorOf(s);
    s = good;
    s.replace(s.find("\"parametric\""), 12, "\"spiral\"");
    EXPECT_NE(errorOf(s).find("/path/kind"), std::string::npos) << errorOf(s);
    // found by fuzz_scene: a number beyond double range is out_of_range, not a parse_error
    EXPECT_NE(errorOf("{\"version\": 1e400}").find("scene file"), std::string::npos)
        << errorOf("{\"version\": 1e400}");
    EXPECT_NE(errorOf("{\"format\": \"chaplygin-lab-scene\", \"version\": 1, \"path\": \"\xff\"}")
                  .find("not valid JSON"),
              std::string::npos);
}

TEST(SceneJson, AtomicWriteKeepsTheOldFileOnFailure) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / "chaplygin-atomic-test";
    fs::create_directories(dir);
    fs::path file = dir / "scene.json";
    writeFileAtomically(file.string(), "old contents\n");
    // a directory in the way of the rename: the write fails and the old file stays
    EXPECT_THROW(writeFileAtomically((dir / "missing-dir" / "x.json").string(), "new"), IoError);
    EXPECT_THROW(writeFileAtomically(dir.string(), "new"), IoError);
    EXPECT_THROW(writeFileAtomically("", "new"), IoError);
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "old contents");
    // a full device (a private copy of /dev/full, made where mknod is allowed): every write
    // fails with ENOSPC, the writer says so, and the device is written in place, not replaced
    fs::path full = dir / "full";
    if (::mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)) == 0) {
        EXPECT_THROW(writeFileAtomically(full.string(), "data"), IoError);
        EXPECT_TRUE(fs::is_character_file(full));
        fs::remove(full);
    }
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
            << entry.path();
    fs::remove_all(dir);
}

namespace {

Scene instrumentedScene() {
    Scene s = presetScene("catenary");
    s.vectors.knifeVelocity = {true, 0};
    s.vectors.controlCouple = {true, 0.25};
    s.vectors.lateralReaction = {false, 2.0}; // a scale kept while hidden
    s.note = "## The catenary\n\nThe sleigh turns *clockwise*: \u03ba < 0.\n";
    PinnedRun pin = pinOf(s);
    pin.system.params["b"] = 0.5;
    s.pins.push_back(pin);
    pin.mode = SpeedMode::Speed;
    pin.tEnd = 1.5;
    s.pins.push_back(pin);
    return s;
}

} // namespace

TEST(SceneJson, VectorsNotesAndPinsRoundTrip) {
    Scene s = instrumentedScene();
    Scene back = sceneFromJson(sceneToJson(s));
    EXPECT_EQ(back, s);
    EXPECT_EQ(back.pins.size(), 2u);
    EXPECT_EQ(back.pins[0].system.params.at("b"), 0.5);
    EXPECT_TRUE(back.vectors.knifeVelocity.shown);
    EXPECT_EQ(back.vectors.controlCouple.scale, 0.25);
    EXPECT_EQ(back.note, s.note);
    // a plain scene writes none of the new keys, so older readers see the same file
    std::string plain = sceneToJson(presetScene("catenary"));
    for (const char* key : {"\"vectors\"", "\"note\"", "\"pins\""})
        EXPECT_EQ(plain.find(key), std::string::npos) << key;
}

TEST(SceneJson, BadVectorsNotesAndPinsNameTheirPlace) {
    const std::string good = sceneToJson(instrumentedScene());
    auto withReplaced = [&](const std::string& from, const std::string& to) {
        std::string s = good;
        auto at = s.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return at == std::string::npos ? s : s.replace(at, from.size(), to);
    };
    auto expectError = [&](const std::string& text, const std::string& words) {
        std::string e = errorOf(text);
        EXPECT_NE(e.find(words), std::string::npos) << "got: " << e;
    };
    expectError(withReplaced("\"shown\": true", "\"shown\": 1"),
                "scene file /vectors/control_couple/shown: must be true or false");
    expectError(withReplaced("\"scale\": 0.25", "\"scale\": -1"),
                "scene file /vectors/control_couple/scale: must be >= 0");
    expectError(withReplaced("\"control_couple\"", "\"torque\""),
                "scene file /vectors/torque: unknown arrow");
    expectError(withReplaced("\"note\": \"##", "\"note\": [\"##\"], \"x\": \""),
                "scene file /note: must be a string");
    expectError(withReplaced("\"b\": 0.5", "\"b\": \"half\""),
                "scene file /pins/0/system/params/b: must be a number");
    expectError(withReplaced("\"mode\": \"speed\"", "\"mode\": \"fast\""),
                "scene file /pins/1/mode: must be \"energy\" or \"speed\"");
    expectError(withReplaced("\"pins\": [", "\"pins\": [1, "),
                "scene file /pins/0: must be an object");
    // more than five pins
    Scene many = instrumentedScene();
    while (many.pins.size() <= kMaxPinnedRuns)
        many.pins.push_back(many.pins.front());
    expectError(sceneToJson(many), "scene file /pins: has 6 pinned runs; at most 5");
    // an oversized note
    Scene longNote = instrumentedScene();
    longNote.note = std::string(200000, 'x');
    expectError(sceneToJson(longNote), "scene file /note: is 200000 bytes");
}

// docs/physics.md §9: the optional "perturbation" object
TEST(SceneJson, PerturbationRoundTripsAndOldFilesLoadWithout) {
    Scene s = presetScene("circle");
    const std::string old = sceneToJson(s);
    EXPECT_EQ(old.find("perturbation"), std::string::npos);
    EXPECT_EQ(sceneFromJson(old).perturbation, std::nullopt);
    Perturbation p;
    p.dy = 0.3;
    p.dphi = -0.1;
    p.dpsi = 0.05;
    p.tPush = 4;
    p.pushPsi = 0.2;
    p.pushDy = -0.05;
    p.feedbackRate = 2.5;
    p.feedbackLimit = 0.4;
    p.controllerB = 0.7;
    s.perturbation = p;
    EXPECT_EQ(sceneFromJson(sceneToJson(s)), s);
    s.perturbation = Perturbation{};
    s.perturbation->dy = 1e-5;
    EXPECT_EQ(sceneFromJson(sceneToJson(s)), s);
}

TEST(SceneJson, BadPerturbationsNameTheirField) {
    std::string base = sceneToJson(presetScene("line"));
    base.resize(base.rfind('}'));
    const auto with = [&](const std::string& p) { return base + ", \"perturbation\": " + p + "}"; };
    EXPECT_NE(
        errorOf(with("{\"dy\": \"1\"}")).find("scene file /perturbation/dy: must be a number"),
        std::string::npos)
        << errorOf(with("{\"dy\": \"1\"}"));
    EXPECT_NE(errorOf(with("[1]")).find("scene file /perturbation: must be an object"),
              std::string::npos);
    EXPECT_NE(errorOf(with("{\"dz\": 1}")).find("scene file /perturbation: unknown field 'dz'"),
              std::string::npos)
        << errorOf(with("{\"dz\": 1}"));
    EXPECT_NE(errorOf(with("{\"feedback_rate\": 0}"))
                  .find("scene file /perturbation/feedback_rate: must be > 0 1/m, got 0"),
              std::string::npos)
        << errorOf(with("{\"feedback_rate\": 0}"));
    EXPECT_NE(errorOf(with("{\"feedback_limit\": -1}")).find("/perturbation/feedback_limit"),
              std::string::npos);
    EXPECT_NE(errorOf(with("{\"controller_b\": 0}")).find("/perturbation/controller_b"),
              std::string::npos);
    EXPECT_NE(errorOf(with("{\"dphi\": 2}")).find("/perturbation/dphi: must be less than pi/2"),
              std::string::npos);
    EXPECT_NE(errorOf(with("{\"t_push\": -1, \"push_psi\": 0.1}")).find("/perturbation/t_push"),
              std::string::npos);
    EXPECT_NE(errorOf(with("{\"push_dy\": 0.1}"))
                  .find("/perturbation/push_dy: a push needs its time t_push"),
              std::string::npos)
        << errorOf(with("{\"push_dy\": 0.1}"));
    EXPECT_NE(errorOf(with("{\"t_push\": 1}")).find("/perturbation/t_push: needs a push"),
              std::string::npos);
}

TEST(SceneJson, PlanRoundTripsAndOldFilesLoadWithout) {
    Scene s = presetScene("line");
    EXPECT_EQ(sceneToJson(s).find("\"plan\""), std::string::npos);
    EXPECT_EQ(sceneFromJson(sceneToJson(s)).plan, std::nullopt);
    ScenePlan plan;
    plan.to = {0.1, 1.0 / 3.0, -2.75};
    plan.choice = 2;
    s.plan = plan;
    EXPECT_EQ(sceneFromJson(sceneToJson(s)), s);
    plan.from = Pose{-1.5, 0.25, 3.0};
    plan.horizon = 12.5;
    s.plan = plan;
    const Scene back = sceneFromJson(sceneToJson(s));
    EXPECT_EQ(back, s);
    ASSERT_TRUE(back.plan && back.plan->from);
    EXPECT_EQ(back.plan->from->phi, 3.0);
    EXPECT_EQ(back.plan->to.y, 1.0 / 3.0);
    // the comparison sees every field
    Scene other = s;
    other.plan->from->y = 0.5;
    EXPECT_FALSE(other == s);
    other = s;
    other.plan->horizon.reset();
    EXPECT_FALSE(other == s);
}

TEST(SceneJson, BadPlansNameTheirField) {
    std::string base = sceneToJson(presetScene("line"));
    base.resize(base.rfind('}'));
    const auto with = [&](const std::string& p) { return base + ", \"plan\": " + p + "}"; };
    const auto expectError = [&](const std::string& plan, const std::string& message) {
        EXPECT_NE(errorOf(with(plan)).find(message), std::string::npos) << errorOf(with(plan));
    };
    expectError("[1, 2, 3]", "scene file /plan: must be an object");
    expectError("{}", "scene file /plan: missing \"to\"");
    expectError("{\"to\": [1, 2]}", "scene file /plan/to: must be [x, y, phi]");
    expectError("{\"to\": [1, \"2\", 0]}", "scene file /plan/to/1: must be a number");
    expectError("{\"to\": [1, 2, null]}", "scene file /plan/to/2: must be a number");
    expectError("{\"to\": [1, 2, 0], \"from\": 3}", "scene file /plan/from: must be [x, y, phi]");
    expectError("{\"to\": [1, 2, 0], \"horizon\": 0}", "scene file /plan/horizon: must be > 0");
    expectError("{\"to\": [1, 2, 0], \"horizon\": -3}", "scene file /plan/horizon: must be > 0");
    expectError("{\"to\": [1, 2, 0], \"choice\": -1}", "scene file /plan/choice: must be a whole");
    expectError("{\"to\": [1, 2, 0], \"choice\": 0.5}", "scene file /plan/choice: must be a whole");
    expectError("{\"to\": [1, 2, 0], \"target\": 1}", "scene file /plan/target: unknown field");
}
