// A planned motion sampled for the plots (docs/physics.md §10): the times even over [0, t], the
// genuine vakonomic body against an rk8pd integration of (19)-(21) from the planned start at each
// checked sample, and the free ghost from the same start: its pose at t = 0, its chi constant (its
// lambda is 0, docs/physics.md §4) and its energy the body's, for motions of every family with
// a != 0, b != 1, v_T != 1 and a start away from the origin.
#include "planning/planned_samples.h"

#include "free_knife_rk4.h"
#include "planning_reference.h"
#include "systems/system_parameters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

namespace chaplygin {
namespace {

TEST(PlannedSamples, TheBodyFollowsItsIntegrationAndTheGhostStartsWithIt) {
    PlanRequest r;
    r.system.mass = r.system.translatingMass = 2;
    r.system.a = 0.4;
    r.system.b = 0.8;
    r.vT = 1.5;
    r.from = {0.3, -0.2, 0.7};
    const double b = r.system.b, T0 = 0.5 * r.system.mass * r.vT * r.vT;
    std::set<GeodesicFamily> families;
    for (const Pose to : {Pose{2.0, 1.5, -1.0}, Pose{0.3, -0.2 + 0.8, 0.7}, Pose{0.3, -0.2, 2.5},
                          Pose{0.3 + 2 * std::cos(0.7), -0.2 + 2 * std::sin(0.7), 0.7}}) {
        r.to = to;
        for (const PlannedGeodesic& g : planVakonomic(r).geodesics) {
            families.insert(g.family);
            const int count = 201;
            const auto samples = samplePlannedMotion(r, g, count);
            ASSERT_EQ(samples.size(), std::size_t(count));
            EXPECT_EQ(samples.back().t, g.t);
            for (int i = 0; i < count; i += 20) {
                const PlannedSample& s = samples[std::size_t(i)];
                EXPECT_NEAR(s.t, g.t * i / (count - 1), 1e-14 * g.t);
                const Pose exact =
                    test::integratedEnd(r.system, r.vT, r.from, g.psi0, g.lambda0, s.t);
                EXPECT_LT(
                    test::poseError({s.vakonomic.x, s.vakonomic.y, s.vakonomic.phi}, exact, b),
                    1e-9)
                    << geodesicFamilyName(g.family) << " t = " << s.t;
                EXPECT_NEAR(s.vakonomic.chi, s.vakonomic.psi - r.system.a / b * s.vakonomic.phi,
                            1e-12);
                EXPECT_NEAR(s.vakonomic.energy, T0, 1e-12 * T0);
                const reference::FreeKnife ghost =
                    reference::integrateFree({r.from.x, r.from.y, r.from.phi,
                                              r.vT * std::sin(g.psi0), r.vT * std::cos(g.psi0) / b},
                                             r.system.a, b, s.t, 20000)
                        .back();
                EXPECT_LT(test::poseError({s.free.x, s.free.y, s.free.phi},
                                          {ghost.x, ghost.y, ghost.phi}, b),
                          1e-10)
                    << "ghost at t = " << s.t;
                EXPECT_NEAR(s.free.chi, samples[0].free.chi, 1e-12);
                EXPECT_NEAR(s.free.energy, T0, 1e-12 * T0);
            }
            // both start where the plan starts, with the planned Psi0 and lambda(0)
            const PlannedSample& first = samples.front();
            EXPECT_LT(test::poseError({first.free.x, first.free.y, first.free.phi}, r.from, b),
                      1e-15);
            EXPECT_NEAR(std::remainder(first.vakonomic.psi - g.psi0, 2 * std::numbers::pi), 0,
                        1e-14);
            EXPECT_NEAR(std::remainder(first.free.psi - g.psi0, 2 * std::numbers::pi), 0, 1e-14);
            EXPECT_NEAR(first.vakonomic.lambda, g.lambda0, 1e-12 * r.system.mass * r.vT);
            // and the body ends on the target
            const PlannedSample& last = samples.back();
            EXPECT_LT(
                test::poseError({last.vakonomic.x, last.vakonomic.y, last.vakonomic.phi}, to, b),
                1e-10);
        }
    }
    for (GeodesicFamily f : {GeodesicFamily::Libration, GeodesicFamily::Rotation,
                             GeodesicFamily::Pivot, GeodesicFamily::Line})
        EXPECT_TRUE(families.count(f)) << geodesicFamilyName(f);
}

} // namespace
} // namespace chaplygin
