// The pen's marks in the scene file: the round trip (exact doubles), a scene without marks
// written as before, a link without them, every bad "annotations" member refused with its JSON
// path (non-finite numbers, too many marks or points, an unknown colour or kind, an arrow without
// two points), the crash-recovery copy's reader that a bad member costs the marks only, the rule
// of unsaved marks, and the simplification of a freehand stroke against the distances it
// promises.
#include "common/input_error.h"
#include "scene/annotations.h"
#include "scene/annotations_json.h"
#include "scene/presets.h"
#include "scene/scene_json.h"
#include "scene/scene_link.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <numbers>

using namespace chaplygin;
using nlohmann::json;

namespace {

Scene sceneWithMarks() {
    Scene s = presetScene("sinusoid");
    s.annotations = {
        {0, MarkKind::Freehand, {{0.1, 0.2}, {0.30000000000000004, -1.0 / 3}, {1e-9, 7}}},
        {1, MarkKind::Arrow, {{-2, 0.5}, {3.25, 1.75}}},
        {2, MarkKind::Freehand, {{5, 5}}},
        {3, MarkKind::Freehand, {{0, 0}, {1, 1}}},
    };
    return s;
}

// the where() and the message of the refusal of a scene whose "annotations" member is `marks`
std::pair<std::string, std::string> refusal(const json& marks) {
    json scene = json::parse(sceneToJson(presetScene("sinusoid")));
    scene["annotations"] = marks;
    try {
        sceneFromJson(scene.dump());
    } catch (const InputError& e) {
        return {e.where(), e.what()};
    }
    return {};
}

json mark(const std::string& colour, const std::string& kind, json points) {
    return json::object({{"colour", colour}, {"kind", kind}, {"points", std::move(points)}});
}

// the distance from p to the segment ab
double toSegment(std::pair<double, double> p, std::pair<double, double> a,
                 std::pair<double, double> b) {
    const double abx = b.first - a.first, aby = b.second - a.second;
    const double len2 = abx * abx + aby * aby;
    double u = len2 > 0 ? ((p.first - a.first) * abx + (p.second - a.second) * aby) / len2 : 0;
    u = std::clamp(u, 0.0, 1.0);
    return std::hypot(p.first - a.first - u * abx, p.second - a.second - u * aby);
}

} // namespace

TEST(Annotations, RoundTripThroughTheSceneFile) {
    const Scene s = sceneWithMarks();
    const Scene back = sceneFromJson(sceneToJson(s));
    EXPECT_EQ(back.annotations, s.annotations);
    EXPECT_EQ(back, s);
    const json written = json::parse(sceneToJson(s));
    EXPECT_EQ(written["annotations"][0]["colour"], "red");
    EXPECT_EQ(written["annotations"][1]["colour"], "blue");
    EXPECT_EQ(written["annotations"][1]["kind"], "arrow");
    EXPECT_EQ(written["annotations"][2]["colour"], "green");
    EXPECT_EQ(written["annotations"][3]["colour"], "black");
}

TEST(Annotations, ASceneWithoutMarksIsWrittenAsBefore) {
    Scene s = presetScene("sinusoid");
    const std::string text = sceneToJson(s);
    EXPECT_EQ(text.find("annotations"), std::string::npos);
    // an older file, without the member, loads with no marks
    EXPECT_TRUE(sceneFromJson(text).annotations.empty());
    // and the marks change nothing else in the file
    s.annotations = sceneWithMarks().annotations;
    json with = json::parse(sceneToJson(s));
    with.erase("annotations");
    EXPECT_EQ(with, json::parse(text));
    // an empty list is read as none
    EXPECT_EQ(refusal(json::array()).first, "");
}

TEST(Annotations, ALinkHoldsTheSceneWithoutTheMarks) {
    const Scene marked = sceneWithMarks();
    Scene plain = marked;
    plain.annotations.clear();
    EXPECT_EQ(sceneToLink(marked), sceneToLink(plain));
    EXPECT_EQ(sceneFromLink(sceneToLink(marked)), plain);
}

TEST(Annotations, NonFiniteNumbersAreNamed) {
    for (double bad :
         {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()}) {
        const json marks = json::array({mark("red", "freehand", {{0, 0}, {bad, 1}})});
        try {
            annotationsFromJson(marks, "/annotations");
            ADD_FAILURE() << bad << " was read";
        } catch (const InputError& e) {
            EXPECT_EQ(e.where(), "scene file /annotations/0/points/1/0");
            EXPECT_NE(std::string(e.what()).find("must be finite"), std::string::npos);
        }
    }
    // in a file's text a number beyond the doubles is refused before any member is read
    json scene = json::parse(sceneToJson(presetScene("sinusoid")));
    scene["annotations"] = json::array({mark("red", "freehand", {{0, 0}, {1, 2}})});
    std::string text = scene.dump();
    text.replace(text.find("[1,2]"), 5, "[1e999,2]");
    EXPECT_THROW(sceneFromJson(text), InputError);
    // the writer leaves a mark with a non-finite point out: the file stays readable
    Scene s = presetScene("sinusoid");
    s.annotations = {{0, MarkKind::Freehand, {{0, 0}, {std::nan(""), 1}}},
                     {1, MarkKind::Freehand, {{2, 3}}}};
    const Scene back = sceneFromJson(sceneToJson(s));
    ASSERT_EQ(back.annotations.size(), 1u);
    EXPECT_EQ(back.annotations[0], s.annotations[1]);
}

TEST(Annotations, TooManyMarksOrPointsAreNamed) {
    json points = json::array();
    for (std::size_t i = 0; i <= kMaxMarkPoints; ++i)
        points.push_back({double(i), 0.0});
    auto [where, what] = refusal(json::array({mark("red", "freehand", points)}));
    EXPECT_EQ(where, "scene file /annotations/0/points");
    EXPECT_NE(what.find(std::to_string(kMaxMarkPoints + 1) + " points"), std::string::npos) << what;
    points.erase(points.size() - 1);
    EXPECT_EQ(refusal(json::array({mark("red", "freehand", points)})).first, "");

    json marks = json::array();
    for (std::size_t i = 0; i <= kMaxMarks; ++i)
        marks.push_back(mark("blue", "freehand", {{0.0, double(i)}}));
    std::tie(where, what) = refusal(marks);
    EXPECT_EQ(where, "scene file /annotations");
    EXPECT_NE(what.find(std::to_string(kMaxMarks + 1) + " marks"), std::string::npos) << what;
    marks.erase(marks.size() - 1);
    EXPECT_EQ(refusal(marks).first, "");
}

TEST(Annotations, BadMarksAreNamedByTheirPath) {
    struct Case {
        json marks;
        std::string where, words;
    };
    const json pair = {{0, 0}, {1, 1}};
    const std::vector<Case> cases{
        {json::array({mark("purple", "freehand", pair)}), "scene file /annotations/0/colour",
         "unknown colour \"purple\""},
        {json::array({mark("red", "freehand", pair), mark("RED", "arrow", pair)}),
         "scene file /annotations/1/colour", "unknown colour"},
        {json::array({json::object({{"colour", 2}, {"kind", "arrow"}, {"points", pair}})}),
         "scene file /annotations/0/colour", "must be a string"},
        {json::array({mark("red", "circle", pair)}), "scene file /annotations/0/kind",
         "\"freehand\" or \"arrow\""},
        {json::array({mark("red", "arrow", {{0, 0}, {1, 1}, {2, 2}})}),
         "scene file /annotations/0/points", "an arrow has two points"},
        {json::array({mark("red", "freehand", json::array())}), "scene file /annotations/0/points",
         "at least one point"},
        {json::array({mark("red", "freehand", {{0, 0}, {1, 2, 3}})}),
         "scene file /annotations/0/points/1", "[x, y] pair"},
        {json::array({mark("red", "freehand", {{0, 0}, {"1", 2}})}),
         "scene file /annotations/0/points/1/0", "must be a number"},
        {json::array({json::object({{"colour", "red"}, {"kind", "arrow"}})}),
         "scene file /annotations/0", "missing \"points\""},
        {json::array({json::object(
             {{"colour", "red"}, {"kind", "arrow"}, {"points", pair}, {"width", 3}})}),
         "scene file /annotations/0/width", "unknown field"},
        {json::object({{"colour", "red"}}), "scene file /annotations", "must be an array"},
        {json::array({json::array({1, 2})}), "scene file /annotations/0", "must be an object"},
    };
    for (const Case& c : cases) {
        const auto [where, what] = refusal(c.marks);
        EXPECT_EQ(where, c.where) << c.marks.dump();
        EXPECT_NE(what.find(c.words), std::string::npos) << what;
    }
}

TEST(Annotations, TheWriterLeavesOutWhatTheReaderRefuses) {
    Scene s = presetScene("sinusoid");
    s.annotations = {{kMarkColours, MarkKind::Freehand, {{0, 0}}},
                     {-1, MarkKind::Freehand, {{0, 0}}},
                     {0, MarkKind::Arrow, {{0, 0}, {1, 1}, {2, 2}}},
                     {0, MarkKind::Freehand, {}},
                     {1, MarkKind::Arrow, {{0, 0}, {1, 1}}}};
    const Scene back = sceneFromJson(sceneToJson(s));
    ASSERT_EQ(back.annotations.size(), 1u);
    EXPECT_EQ(back.annotations[0], s.annotations[4]);
    EXPECT_EQ(markColourFromName("green"), 2);
    EXPECT_EQ(markColourFromName("Green"), -1);
    EXPECT_EQ(markColourName(4), "");
}

TEST(Annotations, ACopyReadSparingItsMarksKeepsTheSceneOfABadMember) {
    // the crash-recovery copy's reader: the same scene as sceneFromJson's and the same marks,
    // or, for a bad member, the scene alone and the refusal sceneFromJson would have thrown
    const Scene s = sceneWithMarks();
    const SceneSparingMarks good = sceneFromJsonSparingMarks(sceneToJson(s));
    EXPECT_EQ(good.scene, s);
    EXPECT_FALSE(good.marksError.has_value());
    Scene plain = s;
    plain.annotations.clear();
    const SceneSparingMarks none = sceneFromJsonSparingMarks(sceneToJson(plain));
    EXPECT_EQ(none.scene, plain);
    EXPECT_FALSE(none.marksError.has_value());
    const json pair = json::array({json::array({0, 0}), json::array({1, 1})});
    json tooMany = json::array();
    for (std::size_t i = 0; i <= kMaxMarks; ++i)
        tooMany.push_back(mark("red", "freehand", pair));
    for (const json& bad :
         {json::array({mark("purple", "freehand", pair)}), tooMany,
          json::object({{"colour", "red"}}),
          json::array({mark("red", "freehand", json::array({json::array({0, "x"})}))})}) {
        json scene = json::parse(sceneToJson(plain));
        scene["annotations"] = bad;
        const auto [where, what] = refusal(bad);
        ASSERT_FALSE(where.empty());
        const SceneSparingMarks read = sceneFromJsonSparingMarks(scene.dump());
        EXPECT_EQ(read.scene, plain) << where;
        ASSERT_TRUE(read.marksError.has_value()) << where;
        EXPECT_EQ(read.marksError->where(), where);
        EXPECT_EQ(std::string(read.marksError->what()), what);
    }
    // the rest of the file is read as strictly as ever
    json badScene = json::parse(sceneToJson(s));
    badScene["speed"] = "fast";
    EXPECT_THROW(sceneFromJsonSparingMarks(badScene.dump()), InputError);
    EXPECT_THROW(sceneFromJsonSparingMarks(""), InputError);
}

TEST(Annotations, MarksBesideTheFileAreUnsavedOnlyWhenSavedWithTheScene) {
    const std::vector<AnnotationMark> a{{0, MarkKind::Freehand, {{0, 0}, {1, 1}}}};
    const std::vector<AnnotationMark> b{{1, MarkKind::Arrow, {{0, 0}, {1, 1}}}};
    EXPECT_FALSE((PenMarks{a, a, true}).unsaved());
    EXPECT_TRUE((PenMarks{b, a, true}).unsaved());
    EXPECT_FALSE((PenMarks{b, a, false}).unsaved());
    EXPECT_TRUE((PenMarks{b, a, false}).outsideFile());
    EXPECT_TRUE((PenMarks{a, {}, false}).outsideFile());
    EXPECT_FALSE((PenMarks{{}, {}, true}).outsideFile());
    // a file's marks: shown as they are, the option ticked by marks and never unticked
    EXPECT_EQ(PenMarks::ofFile(a, false), (PenMarks{a, a, true}));
    EXPECT_EQ(PenMarks::ofFile({}, false), (PenMarks{{}, {}, false}));
    EXPECT_EQ(PenMarks::ofFile({}, true), (PenMarks{{}, {}, true}));
}

TEST(Annotations, ASimplifiedStrokeKeepsItsEndsAndItsShape) {
    // a circle of radius 1 m drawn as 20,000 points, simplified at 1 cm
    std::vector<std::pair<double, double>> drawn;
    const int n = 20000;
    for (int i = 0; i <= n; ++i) {
        const double a = 2 * std::numbers::pi * i / n * 0.9; // nine tenths of the circle
        drawn.emplace_back(std::cos(a), std::sin(a));
    }
    const double d = 0.01;
    const auto kept = simplifyStroke(drawn, d);
    EXPECT_EQ(kept.front(), drawn.front());
    EXPECT_EQ(kept.back(), drawn.back());
    // the points kept are at least d apart (the last one excepted) ...
    for (std::size_t i = 1; i + 1 < kept.size(); ++i)
        EXPECT_GE(
            std::hypot(kept[i].first - kept[i - 1].first, kept[i].second - kept[i - 1].second), d);
    // ... which on an arc of 0.9 * 2 pi m leaves at most its length / d + 2 of them: the drawn
    // points are 0.28 mm apart, so the kept ones are at most d + 0.28 mm apart, and so at least
    // length / (d + 0.28 mm) of them
    const double length = 0.9 * 2 * std::numbers::pi, step = length / n;
    EXPECT_LE(double(kept.size()), length / d + 2);
    EXPECT_GE(double(kept.size()), length / (d + step));
    // every drawn point lies within d of the kept polyline
    double worst = 0;
    for (const auto& p : drawn) {
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i + 1 < kept.size(); ++i)
            nearest = std::min(nearest, toSegment(p, kept[i], kept[i + 1]));
        worst = std::max(worst, nearest);
    }
    EXPECT_LE(worst, d);
    // a dot and a dash are kept whole
    EXPECT_EQ(simplifyStroke({{1, 2}}, d), (std::vector<std::pair<double, double>>{{1, 2}}));
    EXPECT_EQ(simplifyStroke({{1, 2}, {1, 2.001}}, d).size(), 2u);
}
