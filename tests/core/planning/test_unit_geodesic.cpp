// The unit geodesic (docs/physics.md §10): the integrals of the motion the planner relies on,
// checked along an independent rk8pd integration, and the pendulum's passage time and drift.
#include "planning/unit_geodesic.h"

#include "planning_reference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace chaplygin {
namespace {

using std::numbers::pi;

DerivedSystem unitSystem() {
    DerivedSystem s;
    s.mass = s.translatingMass = 1;
    s.a = 0;
    s.b = 1;
    return s;
}

struct Case {
    double psi0, lambda0;
};
const Case cases[] = {{0.5, 0.4}, {2.3, -0.6}, {-0.9, 1.0}, {2.8, -2.15}, {-2.0, 0.05}};

// P = (sin Psi0, Lambda0) constant in the plane: sin Psi = P.(cos phi, sin phi),
// Lambda = P_y cos phi - P_x sin phi, and cos Psi + x P_y - y P_x = cos Psi0 (rk8pd)
TEST(UnitGeodesic, IntegralsHoldAlongAnRk8pdIntegration) {
    for (const Case c : cases) {
        const double Px = std::sin(c.psi0), Py = c.lambda0;
        for (double t : {0.7, 2.9, 6.1}) {
            const Pose p = test::integratedEnd(unitSystem(), 1, {}, c.psi0, c.lambda0, t);
            const UnitGeodesicPoint g = UnitGeodesic(c.psi0, c.lambda0).at(t);
            EXPECT_NEAR(g.x, p.x, 1e-11);
            EXPECT_NEAR(g.y, p.y, 1e-11);
            EXPECT_NEAR(g.sinPsi, Px * std::cos(p.phi) + Py * std::sin(p.phi), 1e-11);
            EXPECT_NEAR(g.cosPsi + p.x * Py - p.y * Px, std::cos(c.psi0), 1e-11);
        }
    }
}

TEST(UnitGeodesic, PassageTimeAndDriftPerPeriod) {
    for (const Case c : cases) {
        const UnitGeodesic g(c.psi0, c.lambda0);
        const double Px = std::sin(c.psi0), Py = c.lambda0;
        for (double t1 : {0.3, 1.7, 4.4}) {
            const UnitGeodesicPoint p = g.at(t1);
            const double lambda1 = Py * std::cos(p.phi) - Px * std::sin(p.phi);
            const auto pass = g.passage(p.sinPsi, p.cosPsi, lambda1);
            ASSERT_TRUE(pass.has_value());
            EXPECT_GT(pass->period, 0);
            const double n = std::round((t1 - pass->t) / pass->period);
            EXPECT_NEAR(pass->t + n * pass->period, t1, 1e-11);
            EXPECT_GE(pass->t, 0);
            EXPECT_LT(pass->t, pass->period);
            const UnitGeodesicPoint q = g.at(pass->t + pass->period);
            const UnitGeodesicPoint r = g.at(pass->t);
            EXPECT_NEAR(pass->x, r.x, 1e-12);
            EXPECT_NEAR(pass->y, r.y, 1e-12);
            EXPECT_NEAR(q.x - r.x, pass->driftX, 1e-11);
            EXPECT_NEAR(q.y - r.y, pass->driftY, 1e-11);
            EXPECT_NEAR(std::remainder(q.phi - r.phi, 2 * pi), 0, 1e-11);
        }
    }
}

TEST(UnitGeodesic, NoPassageOffItsOrbit) {
    // a libration about Psi = 0 never has cos Psi < 0; a rotation keeps the sign of Psidot
    EXPECT_FALSE(UnitGeodesic(0.5, 0.4).passage(std::sin(2.6), std::cos(2.6), 0.4).has_value());
    EXPECT_FALSE(UnitGeodesic(-0.9, 1.0).passage(std::sin(0.2), std::cos(0.2), -1.3).has_value());
    EXPECT_FALSE(UnitGeodesic(pi / 2, 0).passage(1, 0, 0).has_value()); // the line
}

} // namespace
} // namespace chaplygin
