// resources/scenes: every file is compiled in, loads as a scene file, and the presets carry the
// parameters of the paper's examples (docs/physics.md §6).
#include "common/input_error.h"
#include "scene/presets.h"
#include "scene/scene_json.h"
#include "scene/scene_resources.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

using namespace chaplygin;

namespace {

const std::filesystem::path kSceneDir = CHAPLYGIN_SCENE_DIR;

std::string readFile(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream buf;
    buf << in.rdbuf();
    return buf.str();
}

} // namespace

TEST(SceneResources, EveryFileOnDiskIsCompiledInVerbatim) {
    std::set<std::string> onDisk;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kSceneDir))
        if (entry.is_regular_file() && entry.path().extension() == ".json")
            onDisk.insert(entry.path().lexically_relative(kSceneDir).generic_string());
    std::set<std::string> embedded;
    for (const SceneResource& r : sceneResources()) {
        EXPECT_TRUE(embedded.insert(std::string(r.path)).second) << "twice: " << r.path;
        EXPECT_EQ(std::string(r.text), readFile(kSceneDir / r.path)) << r.path;
    }
    EXPECT_EQ(embedded, onDisk);
    EXPECT_GE(embedded.size(), 12u);
}

TEST(SceneResources, EveryFileLoadsAsASceneFile) {
    for (const SceneResource& r : sceneResources()) {
        SCOPED_TRACE(std::string(r.path));
        Scene fromDisk;
        ASSERT_NO_THROW(fromDisk = loadSceneFile((kSceneDir / r.path).string()));
        // writing and reading again gives the same scene: nothing in the file is lost
        EXPECT_EQ(sceneFromJson(sceneToJson(fromDisk)), fromDisk);
    }
}

TEST(SceneResources, PresetsAreThePapersExamples) {
    ASSERT_EQ(presetNames(), (std::vector<std::string>{"line", "circle", "catenary", "sinusoid"}));
    for (const std::string& name : presetNames()) {
        Scene s = presetScene(name);
        EXPECT_EQ(s.preset, name);
        EXPECT_EQ(s, loadSceneFile((kSceneDir / "presets" / (name + ".json")).string()));
        EXPECT_EQ(s.system.kind, SystemKind::Sleigh);
        EXPECT_EQ(s.system.params, (std::map<std::string, double>{{"m", 1}, {"a", 0.5}, {"b", 1}}));
        EXPECT_EQ(s.mode, SpeedMode::Energy);
        EXPECT_EQ(s.speed, 1.0);
        EXPECT_FALSE(s.tEnd.has_value());
        EXPECT_FALSE(presetDescription(name).empty());
    }
    Scene line = presetScene("line");
    EXPECT_EQ(line.path.kind, PathKind::Graph);
    EXPECT_EQ(line.path.y, "0.5*x + 1");
    EXPECT_EQ(line.path.to, 8.0);
    Scene circle = presetScene("circle");
    EXPECT_EQ(circle.path.xOfU, "2*cos(u)");
    EXPECT_EQ(circle.path.to, 2 * std::numbers::pi); // exactly one lap, to the last bit
    Scene catenary = presetScene("catenary");
    EXPECT_EQ(catenary.path.yOfU, "ln(u + sqrt(u^2 + 1))");
    EXPECT_EQ(catenary.path.to, 5.0);
    Scene sinusoid = presetScene("sinusoid");
    EXPECT_EQ(sinusoid.path.y, "-sin(x)");
    EXPECT_EQ(sinusoid.path.to, 4 * std::numbers::pi);
}

TEST(SceneResources, UnknownPresetNamesTheKnownOnes) {
    try {
        presetScene("spiral");
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.where(), "preset"); // the command line maps it to --preset
        EXPECT_NE(std::string(e.what()).find("use line, circle, catenary or sinusoid"),
                  std::string::npos)
            << e.what();
    }
}
