// The curve of starts (docs/physics.md §10): a geodesic's own start lies on the curve of the pose
// it reaches, with a passage at its time that misses nothing, and the seeds lead back to it.
#include "planning/start_curve.h"

#include "planning/unit_geodesic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace chaplygin {
namespace {

using std::numbers::pi;

struct Case {
    double psi0, lambda0, t;
};
// libration about 0 and about pi, rotation both ways, a second passage
const Case cases[] = {
    {0.5, 0.4, 2.7}, {2.3, -0.6, 1.9}, {-0.9, 1.0, 3.3}, {2.8, -2.15, 1.1}, {0.3, 0.2, 9.5}};

UnitTarget reached(const Case& c) {
    const UnitGeodesicPoint p = UnitGeodesic(c.psi0, c.lambda0).at(c.t);
    return {p.x, p.y, wrapAngle(p.phi)};
}

TEST(StartCurve, WrapAngleIsInMinusPiToPi) {
    EXPECT_EQ(wrapAngle(pi), pi);
    EXPECT_EQ(wrapAngle(-pi), pi);
    EXPECT_NEAR(wrapAngle(3 * pi + 0.25), -pi + 0.25, 1e-15);
    EXPECT_NEAR(wrapAngle(-0.5), -0.5, 0);
}

TEST(StartCurve, AGeodesicsStartPassesItsEndAtItsTime) {
    for (const Case& c : cases) {
        const StartPoint p = startPoint(c.psi0, c.lambda0, reached(c));
        ASSERT_TRUE(p.valid) << c.psi0 << ", " << c.lambda0;
        EXPECT_NEAR(p.k, std::hypot(std::sin(c.psi0), c.lambda0), 1e-15);
        const double n = std::round((c.t - p.t) / p.period);
        EXPECT_NEAR(p.t + n * p.period, c.t, 1e-11);
        EXPECT_NEAR(p.along + n * p.drift, 0, 1e-11);
        // a period later the knife point has drifted along P: that passage misses
        EXPECT_GT(std::fabs(p.along + (n + 1) * p.drift), 1e-3);
    }
}

TEST(StartCurve, SeedsLeadBackToTheGeodesic) {
    for (const Case& c : cases) {
        const UnitTarget tg = reached(c);
        const double d = std::hypot(tg.X, tg.Y);
        bool found = false;
        for (const SeedPiece& piece : curveSeeds(tg, 12, std::max(1.2, 14 / d), GridSize{})) {
            const UnitSolution s = refineSeed(piece, tg);
            found =
                found || (std::fabs(wrapAngle(s.psi0 - c.psi0)) < 1e-8 &&
                          std::fabs(s.lambda0 - c.lambda0) < 1e-8 && std::fabs(s.t - c.t) < 1e-7);
        }
        EXPECT_TRUE(found) << c.psi0 << ", " << c.lambda0 << ", " << c.t;
    }
}

} // namespace
} // namespace chaplygin
