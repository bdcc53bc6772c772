// The search for cusps (docs/physics.md §3): where r' vanishes inside the range, each point is a
// passable cusp with its limits, or refused naming the place.
#include "common/input_error.h"
#include "paths/cusp_finder.h"
#include "paths/expression_curve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace chaplygin;

namespace {

std::vector<Cusp> cuspsOf(const char* x, const char* y, double u0, double u1) {
    return findCusps(ParametricCurve(Expression::compile(x, "u", "x(u)"),
                                     Expression::compile(y, "u", "y(u)"), u0, u1));
}

std::string refusalOf(const char* x, const char* y, double u0, double u1) {
    try {
        cuspsOf(x, y, u0, u1);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(CuspFinder, SemicubicalCuspAndItsLimits) {
    // x = u^2, y = u^3 at u = 0: r'' = (2, 0), r''' = (0, 6): |r''| = 2, dphi/du = 12/8
    auto c = cuspsOf("u^2", "u^3", -1, 1);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].u, 0.0);
    EXPECT_DOUBLE_EQ(c[0].accel, 2.0);
    EXPECT_DOUBLE_EQ(c[0].turnRate, 1.5);
    // off a sample point: the cusp at u = 1/3 is found by Newton to rounding
    auto shifted = cuspsOf("(u-1/3)^2", "-(u-1/3)^3", -1, 1);
    ASSERT_EQ(shifted.size(), 1u);
    EXPECT_NEAR(shifted[0].u, 1.0 / 3, 1e-15);
    EXPECT_NEAR(shifted[0].turnRate, -1.5, 1e-12);
}

TEST(CuspFinder, AstroidOverManyTurnsHasACuspEveryQuarter) {
    // x = cos^3 u, y = sin^3 u: r' = 3 sin u cos u (-cos u, sin u), zero at k pi/2
    auto c = cuspsOf("cos(u)^3", "sin(u)^3", 0.1, 20);
    ASSERT_EQ(c.size(), 12u); // pi/2 ... 12 pi/2 = 18.85
    for (std::size_t k = 0; k < c.size(); ++k) {
        EXPECT_NEAR(c[k].u, (k + 1) * std::numbers::pi / 2, 1e-14) << k;
        EXPECT_NEAR(c[k].turnRate, -1.0, 1e-12) << k;
        EXPECT_NEAR(c[k].accel, 3.0, 1e-12) << k;
    }
}

TEST(CuspFinder, SmoothCurvesHaveNone) {
    EXPECT_TRUE(cuspsOf("2*cos(u)", "2*sin(u)", 0, 6.283185307179586).empty());
    EXPECT_TRUE(cuspsOf("u", "u^2", -1, 1).empty());
    // slow but moving: |r'| = 1e-6 at u = 0, not a stop
    EXPECT_TRUE(cuspsOf("u^3/3 + 1e-6*u", "u", -1, 1).empty());
    // a cusp at an end of the range is left to the path table
    EXPECT_TRUE(cuspsOf("u^2", "u^3", 0, 1).empty());
    // undefined stretches are left to the path table as well
    EXPECT_TRUE(cuspsOf("u", "sqrt(u)", -1, 1).empty());
}

TEST(CuspFinder, OtherStationaryPointsAreRefusedNamingThePlace) {
    EXPECT_NE(refusalOf("u^3", "u^3 + u^4", -1, 1).find("path at u = 0: the path stops here"),
              std::string::npos);
    EXPECT_NE(refusalOf("u^2", "u^4", -1, 1).find("path at u = 0: the path stops and retraces"),
              std::string::npos);
    // a straight retrace: x = u^2, y = 0 (r'' x r''' = 0)
    EXPECT_NE(refusalOf("u^2", "0", -1, 1).find("retraces"), std::string::npos);
}
