// The canvas's arrows: each vector checked against finite differences of the motion itself
// (Newton's second law for the centre of mass, the couple from I phiddot), not the formulas.
#include "scene/body_vectors.h"
#include "scene/presets.h"
#include "scene/solution.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace chaplygin;

namespace {

struct Point {
    double x, y;
};

// centre of mass C = P + a s-hat of the controlled body at t
Point centreAt(const Solution& sol, double t) {
    MotionSample m = sol.at(t);
    double a = sol.system().a;
    return {m.x + a * std::cos(m.phi), m.y + a * std::sin(m.phi)};
}

} // namespace

TEST(BodyVectors, ControlledArrowsMatchTheMotionOnTheSinusoid) {
    Solution sol = Solution::compute(presetScene("sinusoid"));
    const DerivedSystem& sys = sol.system();
    const double h = 1e-3;
    for (double t : {1.3, 4.0, 7.7}) {
        MotionSample m = sol.at(t);
        BodyVectors v = bodyVectors(sys, controlledBodyState(m));
        // P's velocity from its positions
        MotionSample lo = sol.at(t - h), hi = sol.at(t + h);
        EXPECT_NEAR(v.knifeVelocity.vx, (hi.x - lo.x) / (2 * h), 1e-5) << t;
        EXPECT_NEAR(v.knifeVelocity.vy, (hi.y - lo.y) / (2 * h), 1e-5) << t;
        EXPECT_DOUBLE_EQ(v.knifeVelocity.x, m.x);
        // C's velocity and acceleration from its positions
        Point c0 = centreAt(sol, t - h), c1 = centreAt(sol, t), c2 = centreAt(sol, t + h);
        EXPECT_NEAR(v.cx, c1.x, 1e-12);
        EXPECT_NEAR(v.cmVelocity.vx, (c2.x - c0.x) / (2 * h), 1e-5) << t;
        EXPECT_NEAR(v.cmVelocity.vy, (c2.y - c0.y) / (2 * h), 1e-5) << t;
        // the total force on C is f_s s-hat + N n-hat = m d^2C/dt^2 (docs/physics.md §2)
        double ax = (c2.x - 2 * c1.x + c0.x) / (h * h), ay = (c2.y - 2 * c1.y + c0.y) / (h * h);
        double scale = sys.mass * std::hypot(ax, ay) + 1e-3;
        EXPECT_NEAR(v.axialForce.vx + v.lateralReaction.vx, sys.mass * ax, 2e-5 * scale) << t;
        EXPECT_NEAR(v.axialForce.vy + v.lateralReaction.vy, sys.mass * ay, 2e-5 * scale) << t;
        // the torque about C is I phiddot = tau - a N
        double phiddot = (hi.phi - 2 * m.phi + lo.phi) / (h * h);
        double n = v.lateralReaction.vx * -std::sin(m.phi) + v.lateralReaction.vy * std::cos(m.phi);
        EXPECT_NEAR(v.couple - sys.a * n, sys.inertia() * phiddot, 2e-5 * (1 + std::fabs(v.couple)))
            << t;
    }
}

TEST(BodyVectors, FreeBodyReactionIsNewtonsLaw) {
    // the free body has no control: m d^2C/dt^2 is the knife's reaction alone, along n-hat
    // (the catenary starts turning, so the free body turns too)
    Solution sol = Solution::compute(presetScene("catenary"));
    const DerivedSystem& sys = sol.system();
    const double h = 1e-3, a = sys.a;
    auto centre = [&](double t) {
        FreeState f = sol.freeAt(t);
        return Point{f.x + a * std::cos(f.phi), f.y + a * std::sin(f.phi)};
    };
    for (double t : {0.5, 2.0, 5.0}) {
        FreeState f = sol.freeAt(t);
        BodyState body = freeBodyState(sys, f);
        EXPECT_EQ(body.forceAxial, 0);
        EXPECT_EQ(body.controlCouple, 0);
        BodyVectors v = bodyVectors(sys, body);
        Point c0 = centre(t - h), c1 = centre(t), c2 = centre(t + h);
        double ax = (c2.x - 2 * c1.x + c0.x) / (h * h), ay = (c2.y - 2 * c1.y + c0.y) / (h * h);
        double scale = sys.mass * std::hypot(ax, ay) + 1e-3;
        EXPECT_GT(std::fabs(body.knifeReaction), 1e-3) << t;
        EXPECT_NEAR(v.lateralReaction.vx, sys.mass * ax, 2e-5 * scale) << t;
        EXPECT_NEAR(v.lateralReaction.vy, sys.mass * ay, 2e-5 * scale) << t;
        EXPECT_NEAR(v.cmVelocity.vx, (c2.x - c0.x) / (2 * h), 1e-5) << t;
    }
}

TEST(BodyVectors, PivotIsFlagged) {
    Scene s;
    s.path.kind = PathKind::Polyline;
    s.path.points = {{0, 0}, {1, 0}, {1, 1}};
    s.path.corners = CornerMode::Pivot;
    Solution sol = Solution::compute(s);
    // the corner is reached at t = 1 m / v_T = 1 s; the quarter turn takes b (pi/2)/v_T
    BodyState turning = controlledBodyState(sol.at(1.5));
    EXPECT_TRUE(turning.pivot);
    EXPECT_EQ(turning.sdot, 0);
    EXPECT_FALSE(controlledBodyState(sol.at(0.5)).pivot);
}
