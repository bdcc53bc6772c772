// A planned motion's knife track as the scene's path (docs/physics.md §10): the track's
// derivatives against differences of its positions, and the controlled body tracking it against
// the genuine vakonomic body's closed form from the planned start, for every motion listed to
// several targets (libration, rotation, through cusps, backing first, the line, pivoting).
#include "planning/plan_track.h"

#include "common/input_error.h"
#include "planning/geodesic_track_curve.h"
#include "planning/scene_path.h"
#include "planning_reference.h"
#include "scene/scene_json.h"
#include "scene/solution.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

namespace chaplygin {
namespace {

using std::numbers::pi;

Scene sceneOf(const SystemSpec& spec, double vT) {
    Scene s;
    s.system = spec;
    s.speed = vT;
    return s;
}

PlanRequest requestOf(const Scene& scene, Pose to, Pose from = {}) {
    PlanRequest r;
    r.from = from;
    r.to = to;
    r.system = deriveSystem(scene.system);
    r.vT = scene.speed;
    return r;
}

struct TrackCheck {
    double worstBody = 0; ///< controlled body against the closed form, over the motion
    double worstEnd = 0;  ///< controlled body's end against the target
    int cusps = 0;        ///< backing stretches seen over all motions
    int backingFirst = 0;
    int pivots = 0;
    std::set<GeodesicFamily> families;
};

// (x, y)/b, phi and lambda/(m v_T) of the controlled body and of the Solution's vakonomic body
// against VakonomicMotion from plannedStart, at 61 times over each motion
void checkTracking(const Scene& base, const PlanRequest& r, const PlannedGeodesic& g,
                   TrackCheck& check) {
    Scene scene = base;
    scene.path = planTrack(r, g);
    const Solution sol = Solution::compute(scene);
    const std::shared_ptr<const Path> path = buildScenePath(scene.path);
    for (const PathPiece& p : path->pieces()) {
        check.cusps += p.kind == PathPiece::Kind::Curve && p.direction < 0;
        check.pivots += p.kind == PathPiece::Kind::Pivot;
    }
    check.backingFirst += path->pieces().front().direction < 0;
    check.families.insert(g.family);
    const VakonomicMotion truth(r.system, plannedStart(r, g));
    const double b = r.system.b, lambdaScale = r.system.mass * r.vT;
    for (int i = 0; i <= 60; ++i) {
        const double t = g.t * i / 60;
        const MotionSample m = sol.at(t, MotionParts{});
        const VakonomicState v = truth.at(t);
        const double e =
            std::max({std::fabs(m.x - v.x) / b, std::fabs(m.y - v.y) / b, std::fabs(m.phi - v.phi),
                      std::fabs(m.control.lambda - v.lambda) / lambdaScale});
        const double ev = std::max({std::fabs(m.vak.x - v.x) / b, std::fabs(m.vak.y - v.y) / b,
                                    std::fabs(m.vak.phi - v.phi),
                                    std::fabs(m.vak.lambda - v.lambda) / lambdaScale});
        EXPECT_LE(e, 1e-8) << geodesicFamilyName(g.family) << " t = " << t << " of " << g.t;
        EXPECT_LE(ev, 1e-8) << geodesicFamilyName(g.family) << " t = " << t << " of " << g.t;
        check.worstBody = std::max({check.worstBody, e, ev});
    }
    EXPECT_NEAR(sol.tEnd(), g.t, 1e-9 * g.t);
    const MotionSample end = sol.at(g.t, MotionParts{});
    const double e = test::poseError({end.x, end.y, end.phi}, r.to, b);
    EXPECT_LE(e, 1e-8) << geodesicFamilyName(g.family);
    check.worstEnd = std::max(check.worstEnd, e);
}

TrackCheck checkAll(const Scene& scene, Pose to, Pose from = {}) {
    const PlanRequest r = requestOf(scene, to, from);
    const Plan plan = planVakonomic(r);
    EXPECT_FALSE(plan.geodesics.empty());
    TrackCheck check;
    for (const PlannedGeodesic& g : plan.geodesics)
        checkTracking(scene, r, g, check);
    return check;
}

TEST(PlanTrack, DerivativesAreThoseOfThePositions) {
    GeodesicTrack g;
    g.x = 0.3;
    g.y = -1.1;
    g.phi = 2.2;
    g.b = 0.7;
    g.length = 9;
    const double h = 1e-3;
    for (auto [psi0, lambda0] : {std::pair{0.4, 0.6}, {-2.5, 1.3}, {1.9, -0.2}}) {
        g.psi0 = psi0;
        g.lambda0 = lambda0;
        const GeodesicTrackCurve c(g);
        const CurvePoint p0 = c.eval(0);
        EXPECT_NEAR(p0.x, g.x, 1e-15);
        EXPECT_NEAR(p0.y, g.y, 1e-15);
        // r'(0) = b sin Psi0 (cos phi0, sin phi0)
        EXPECT_NEAR(p0.dx, g.b * std::sin(psi0) * std::cos(g.phi), 1e-15);
        EXPECT_NEAR(p0.dy, g.b * std::sin(psi0) * std::sin(g.phi), 1e-15);
        for (double u : {0.5, 3.0, 7.7}) {
            // fourth-order central differences of the positions and of the derivatives
            auto d = [&](auto f) {
                return (f(c.eval(u - 2 * h)) - 8 * f(c.eval(u - h)) + 8 * f(c.eval(u + h)) -
                        f(c.eval(u + 2 * h))) /
                       (12 * h);
            };
            const CurvePoint p = c.eval(u);
            EXPECT_NEAR(p.dx, d([](const CurvePoint& q) { return q.x; }), 1e-10);
            EXPECT_NEAR(p.dy, d([](const CurvePoint& q) { return q.y; }), 1e-10);
            EXPECT_NEAR(p.ddx, d([](const CurvePoint& q) { return q.dx; }), 1e-10);
            EXPECT_NEAR(p.ddy, d([](const CurvePoint& q) { return q.dy; }), 1e-10);
            EXPECT_NEAR(p.dddx, d([](const CurvePoint& q) { return q.ddx; }), 1e-10);
            EXPECT_NEAR(p.dddy, d([](const CurvePoint& q) { return q.ddy; }), 1e-10);
        }
    }
}

TEST(PlanTrack, TrackingIsTheGenuineVakonomicMotion) {
    const Scene scene = sceneOf(SystemSpec{}, 1.0);
    TrackCheck all;
    // librations and rotations through cusps, some backing first
    for (Pose to :
         {Pose{1.5, 0.8, 1.0}, Pose{-0.7, 1.9, -2.4}, Pose{2.5, -1.0, 0.3}, Pose{0.4, -0.3, 2.8}}) {
        const TrackCheck c = checkAll(scene, to);
        all.worstBody = std::max(all.worstBody, c.worstBody);
        all.worstEnd = std::max(all.worstEnd, c.worstEnd);
        all.cusps += c.cusps;
        all.backingFirst += c.backingFirst;
        all.families.insert(c.families.begin(), c.families.end());
    }
    EXPECT_TRUE(all.families.count(GeodesicFamily::Libration));
    EXPECT_TRUE(all.families.count(GeodesicFamily::Rotation));
    EXPECT_GT(all.cusps, 0);
    EXPECT_GT(all.backingFirst, 0);
    std::printf("tracked vs closed form: %.2e, end %.2e, %d backing stretches\n", all.worstBody,
                all.worstEnd, all.cusps);
}

TEST(PlanTrack, SidewaysShiftBothOptima) {
    const Scene scene = sceneOf(SystemSpec{}, 1.0);
    const PlanRequest r = requestOf(scene, {0, 1, 0});
    const Plan plan = planVakonomic(r);
    int optimal = 0, backingFirst = 0;
    TrackCheck check;
    for (const PlannedGeodesic& g : plan.geodesics) {
        if (!g.optimal)
            continue;
        ++optimal;
        backingFirst += g.psi0 < 0;
        checkTracking(scene, r, g, check);
    }
    EXPECT_EQ(optimal, 2);
    EXPECT_EQ(backingFirst, 1);
    EXPECT_GT(check.cusps, 0);
}

TEST(PlanTrack, PivotByPiEitherWay) {
    const Scene scene = sceneOf(SystemSpec{}, 1.0);
    const TrackCheck c = checkAll(scene, {0, 0, pi});
    EXPECT_GE(c.pivots, 2);
}

TEST(PlanTrack, LineAheadAndBackingUp) {
    const Scene scene = sceneOf(SystemSpec{}, 1.0);
    TrackCheck ahead = checkAll(scene, {2, 0, 0});
    TrackCheck back = checkAll(scene, {-1.5, 0, 0});
    EXPECT_GT(back.backingFirst, 0);
    (void)ahead;
}

TEST(PlanTrack, ScaledMovedAndTheDisk) {
    Scene sleigh =
        sceneOf(SystemSpec{SystemKind::Sleigh, {{"m", 2.0}, {"a", 0.2}, {"b", 0.35}}}, 2.5);
    checkAll(sleigh, {0.9, 0.2, -1.3}, {0.4, -0.2, 0.7});
    Scene disk = sceneOf(
        SystemSpec{SystemKind::Disk, {{"m", 1.0}, {"R", 0.5}, {"I1", 0.05}, {"I2", 0.1}}}, 1.0);
    checkAll(disk, {1.2, 0.6, 1.0}, {1, 1, 4.0});
}

TEST(PlanTrack, RestAndBadTracksAreRefused) {
    const Scene scene = sceneOf(SystemSpec{}, 1.0);
    const PlanRequest r = requestOf(scene, {0, 0, 0});
    const Plan plan = planVakonomic(r);
    ASSERT_FALSE(plan.geodesics.empty());
    EXPECT_THROW(planTrack(r, plan.geodesics.front()), InputError);
    GeodesicTrack g;
    g.psi0 = 1;
    g.length = 0;
    EXPECT_THROW(buildGeodesicTrack(g), InputError);
    g.length = 1;
    g.b = std::nan("");
    EXPECT_THROW(buildGeodesicTrack(g), InputError);
}

TEST(PlanTrack, SavedAndLoadedWithTheScene) {
    Scene scene = sceneOf(SystemSpec{}, 1.0);
    const PlanRequest r = requestOf(scene, {-0.7, 1.9, -2.4}, {0.1, 0.2, 0.3});
    const Plan plan = planVakonomic(r);
    ASSERT_FALSE(plan.geodesics.empty());
    scene.path = planTrack(r, plan.geodesics.front());
    EXPECT_EQ(scene.path.kind, PathKind::Geodesic);
    EXPECT_DOUBLE_EQ(scene.path.geodesic.length, plan.geodesics.front().t);
    const Scene back = sceneFromJson(sceneToJson(scene));
    EXPECT_EQ(back.path, scene.path);
    // the typed-path builder does not take it: the scene's builder does
    EXPECT_THROW(buildPath(scene.path), InputError);
}

} // namespace
} // namespace chaplygin
