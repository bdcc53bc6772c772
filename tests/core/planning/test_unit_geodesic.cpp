// The unit geodesic (docs/physics.md §10): the integrals of the motion the planner relies on,
// checked along an independent rk8pd integration, and the pendulum's passage time and drift.
#include "planning/unit_geodesic.h"

#include "planning/complementary_elliptic.h"

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

// Jacobi's functions and the complete integrals of parameter 1 - mc against mpmath at 40 digits
// (ellipfun, ellipk, ellipe), next to the separatrix (mc = 2.6e-11, K = 13.57) and away from it;
// next to the saddle cn and dn are small, and they keep their relative accuracy
TEST(ComplementaryElliptic, AgreesWithMpmath) {
    struct Row {
        double mc, u, sn, cn, dn;
    };
    const Row rows[] = {
        {2.6e-11, 0.3, 0.29131261245169992072, 0.95662791190021509235, 0.95662791190136833018},
        {2.6e-11, 3, 0.9950547536930059195, 0.099327927356566352549, 0.099327927486154695436},
        {2.6e-11, 10, 0.99999999588419020078, 0.000090728273330332135981,
         0.000090871445357105635881},
        {2.6e-11, 13.1, 0.99999999999687150302, 2.5013984020057733624e-6, 5.679524096735073693e-6},
        {2.6e-11, -7.5, -0.99999938820204606786, 0.0011061625258376576005,
         0.0011061742781025660039},
        {0.3, 0.3, 0.29257180189920454821, 0.95624355722454549248, 0.96957785582871931994},
        {0.3, 3, 0.84960556461823214057, -0.52741860468676583335, 0.7033628289857337062},
        {0.3, 10, 0.97807328035751235345, 0.20826103392304341363, 0.57477026782488195059},
        {0.3, -7.5, 0.68110124672500692783, 0.73218924583036675441, 0.82174860157882159171},
    };
    for (const Row& r : rows) {
        const JacobiValues v = jacobiComplementary(r.u, r.mc);
        EXPECT_NEAR(v.sn, r.sn, 1e-15) << r.mc << " " << r.u;
        EXPECT_NEAR(v.cn, r.cn, 1e-13 * std::fabs(r.cn)) << r.mc << " " << r.u;
        EXPECT_NEAR(v.dn, r.dn, 1e-13 * std::fabs(r.dn)) << r.mc << " " << r.u;
    }
    EXPECT_NEAR(completeKComplementary(2.6e-11), 13.572756650155146618, 4e-15);
    EXPECT_NEAR(completeDComplementary(2.6e-11), 12.572756650312092455, 4e-15);
    EXPECT_NEAR(completeKComplementary(0.3), 2.0753631352924691439, 1e-15);
    EXPECT_NEAR(completeDComplementary(0.3), 1.1909893819237805614, 1e-15);
}

// The geodesic of a 40-digit reference (tests/core/planning/far_target_reference.py: Psi0,
// 1 - k^2 and t reaching a target 20 b away, found with mpmath's elliptic functions and checked
// by mpmath.odefun) ends on its target: the closed form in the complementary parameter.
TEST(UnitGeodesic, FarGeodesicsEndOnTheirTargetsWithTheirGapCarried) {
    struct Row {
        double x, y, phi, t, psi0, gap, lambda0;
    };
    const Row rows[] = {
        {20, 0.5, 0.3, 20.045822042983626841, 1.5594649399204376824, 2.5941070643728894849e-11,
         0.011331143239036088941},
        {-20, 3, 0, 20.248287590806546483, -1.7359450036221062319, -1.7622516735702094208e-10,
         0.1643989872619004302},
        {3, -20, -1, 21.214056087671032053, 3.0655490813052294134, -2.2922455215757624126e-9,
         -0.99711008171928642872},
        {14, -14, -2, 20.744585615138090629, 2.3439173672166413527, 4.4885077425353427195e-9,
         -0.69837246950845378532},
    };
    for (const Row& r : rows) {
        const UnitGeodesicPoint p = UnitGeodesic(r.psi0, r.lambda0, r.gap).at(r.t);
        const double e = std::fabs(p.x - r.x) + std::fabs(p.y - r.y) +
                         std::fabs(std::remainder(p.phi - r.phi, 2 * pi));
        EXPECT_LE(e, 1e-12) << r.x << ", " << r.y;
        EXPECT_NEAR(UnitGeodesic(r.psi0, r.lambda0, r.gap).modulus(), std::sqrt(1 - r.gap), 1e-16);
    }
}

} // namespace
} // namespace chaplygin
