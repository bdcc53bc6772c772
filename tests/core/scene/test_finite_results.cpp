// Nothing non-finite leaves the core: a scene whose path or motion has an inf or a NaN is refused
// with a message naming the place, the quantity and the time (docs/robustness.md, Non-finite
// results).
#include "common/input_error.h"
#include "paths/path.h"
#include "scene/finite_results.h"
#include "scene/presets.h"
#include "scene/scene_json.h"
#include "scene/solution.h"
#include "systems/system.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace chaplygin;

namespace {

// the scene the randomized GUI test met with seed 90210: a stroke drawn while the view was
// centred on a path at y = 1e308, smoothed, on the disk
const char* const kStrokeAt1e308 = R"({
  "format": "chaplygin-lab-scene", "version": 1, "mode": "energy", "speed": 1.8023,
  "path": {"kind": "polyline", "corners": "smooth", "smoothing": 18.0,
           "points": [[511419.63480199594, 1e308], [-68580.36519800406, 1e308],
                      [964419.6348019959, 1e308]]},
  "system": {"kind": "disk", "params": {"I1": 0.125, "I2": 0.586, "R": 0.5, "m": 9.0448}}
})";

std::string messageOf(const Scene& scene) {
    try {
        Solution::compute(scene);
    } catch (const InputError& e) {
        return e.what();
    }
    return {};
}

} // namespace

TEST(FiniteResults, StrokeAtTheEdgeOfDoublePrecisionIsRefusedNamingThePath) {
    const std::string message = messageOf(sceneFromJson(kStrokeAt1e308));
    ASSERT_FALSE(message.empty()) << "the scene solved, with a non-finite pose at t = 0";
    EXPECT_NE(message.find("path at ("), std::string::npos) << message;
    EXPECT_NE(message.find("overflow double precision"), std::string::npos) << message;
}

TEST(FiniteResults, PathBeyondReachIsRefused) {
    // the typed path y = 1e308 of seeds 271828, 161803 and 5551212: the free body's trail beside
    // it jumped by 2e292 m, and the body's pixel overflowed once the view was zoomed
    Scene scene;
    scene.path.y = "1e308";
    std::string message = messageOf(scene);
    EXPECT_NE(message.find("path at (0, 1e+308): lies 1e+308 m from the origin; a path must lie "
                           "within 1e+09 m of it"),
              std::string::npos)
        << message;
    // the edge itself is within reach; a drawn point just beyond it is not
    scene.path.y = "1e9";
    EXPECT_EQ(messageOf(scene), "");
    scene.path.kind = PathKind::Polyline;
    scene.path.points = {{0, 0}, {1, 0}, {-1.5e9, 1}};
    message = messageOf(scene);
    EXPECT_NE(message.find("lies 1.5e+09 m from the origin"), std::string::npos) << message;
}

// every way to solve checks: a tabulated path, and a tabulated path with the system the caller
// derived already (the document's slider edits)
TEST(FiniteResults, EveryComputeChecksTheSolution) {
    Scene scene;
    scene.path.y = "1e308";
    const std::shared_ptr<const Path> path = buildPath(scene.path);
    EXPECT_THROW(Solution::compute(scene, path), InputError);
    EXPECT_THROW(Solution::compute(scene, path, deriveSystem(scene.system)), InputError);
}

TEST(FiniteResults, SampleNamesTheColumnAndTheTime) {
    const Solution solution = Solution::compute(presetScene(presetNames().front()));
    MotionSample m = solution.at(1.5);
    EXPECT_NO_THROW(requireFiniteSample(m));
    m.free.x = std::numeric_limits<double>::quiet_NaN();
    try {
        requireFiniteSample(m, {}, " (context)");
        FAIL() << "a NaN in the free body's x passed";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("column free_x is not finite at t = 1.5 s"), std::string::npos) << what;
        EXPECT_NE(what.find("nan"), std::string::npos) << what;
        EXPECT_NE(what.find("(context)"), std::string::npos) << what;
    }
    // a body not asked for is not read
    EXPECT_NO_THROW(requireFiniteSample(m, MotionParts{true, false, true, true}));
    m.y = std::numeric_limits<double>::infinity();
    try {
        requireFiniteSample(m, MotionParts{true, false, false, false});
        FAIL() << "an inf in the controlled body's y passed";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("column y is not finite"), std::string::npos)
            << e.what();
    }
}

TEST(FiniteResults, EveryPresetAndItsPathAreFinite) {
    for (const std::string& name : presetNames()) {
        const Solution solution = Solution::compute(presetScene(name));
        EXPECT_NO_THROW(requireFinitePath(*solution.path())) << name;
        EXPECT_NO_THROW(requireFiniteSolution(solution)) << name;
    }
}
