// The wheels' rolling angles against closed forms derived here, not the program's formulas: the
// disk on a line (theta = v t/R), the carriage on a circle of radius rho (its wheels at rho -+ a
// roll at rates in the ratio (rho - a)/(rho + a)), a cusp (the disk rolls back to where it
// started), a pivot (the wheels turn opposite ways by a dphi/R), and rates by finite differences
// against sdot = R thetadot (paper A5) and (B2)-(B3) on a curving path.
#include "scene/solution.h"
#include "scene/wheel_angles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace chaplygin;

namespace {

constexpr double kPi = std::numbers::pi;

Scene diskScene() {
    Scene s;
    s.system.kind = SystemKind::Disk;
    s.system.params = {{"m", 2.0}, {"R", 0.6}, {"I1", 0.36}, {"I2", 0.18}};
    return s;
}

// a carriage whose b (0.3186) is smaller than its half-axle
Scene carriageScene() {
    Scene s;
    s.system.kind = SystemKind::Carriage;
    s.system.params = {{"R", 0.3},   {"a", 0.4}, {"m", 0.5}, {"I1", 0.02},
                       {"I2", 0.01}, {"M", 3.0}, {"I", 0.2}};
    return s;
}

// b of the carriage above from App. B (B18): b^2 = J/m_eff
double carriageB() {
    const double mEff = 3.0 + 2 * (0.5 + 0.02 / (0.3 * 0.3));
    const double j = 0.2 + 2 * 0.01 + 2 * 0.4 * 0.4 * (0.5 + 0.02 / (0.3 * 0.3));
    return std::sqrt(j / mEff);
}

void parametric(Scene& s, const char* x, const char* y, double u0, double u1) {
    s.path.kind = PathKind::Parametric;
    s.path.xOfU = x;
    s.path.yOfU = y;
    s.path.from = u0;
    s.path.to = u1;
}

WheelAngles anglesAt(const Solution& sol, double t) {
    return wheelAnglesAt(sol, sol.at(t));
}

} // namespace

TEST(WheelAngles, DiskOnALineRollsAtSpeedOverRadius) {
    for (SpeedMode mode : {SpeedMode::Energy, SpeedMode::Speed}) {
        Scene scene = diskScene();
        parametric(scene, "0.6*u", "0.8*u", 0, 4); // a line of length 4 at 53 degrees
        scene.mode = mode;
        scene.speed = 1.7;
        Solution sol = Solution::compute(scene);
        // on a line sdot = v_T = v_s, so theta = v t/R
        for (double t : {0.0, 0.5, 1.3, sol.duration()}) {
            WheelAngles w = anglesAt(sol, t);
            EXPECT_EQ(w.wheels, 1);
            EXPECT_NEAR(w.theta1, 1.7 * t / 0.6, 1e-12) << t;
        }
    }
}

TEST(WheelAngles, CarriageOnACircleRollsItsOuterWheelFaster) {
    // a left turn of radius rho: wheel 1 (right, outside) on a circle of rho + a, wheel 2 (left,
    // inside) on rho - a; sdot = v_T/sqrt(1 + b^2/rho^2), phidot = sdot/rho (docs/physics.md §2)
    const double rho = 1.5, a = 0.4, r = 0.3, v = 1.2, b = carriageB();
    Scene scene = carriageScene();
    parametric(scene, "1.5*sin(u)", "1.5*(1-cos(u))", 0, 3);
    scene.speed = v;
    Solution sol = Solution::compute(scene);
    const double sdot = v / std::sqrt(1 + b * b / (rho * rho));
    for (double t : {0.4, 1.1, 2.5, sol.duration()}) {
        WheelAngles w = anglesAt(sol, t);
        EXPECT_EQ(w.wheels, 2);
        EXPECT_NEAR(w.theta1, sdot * t * (rho + a) / (rho * r), 1e-11) << t;
        EXPECT_NEAR(w.theta2, sdot * t * (rho - a) / (rho * r), 1e-11) << t;
        EXPECT_NEAR(w.theta2 / w.theta1, (rho - a) / (rho + a), 1e-12) << t;
    }
    // turning right swaps them
    parametric(scene, "1.5*sin(u)", "-1.5*(1-cos(u))", 0, 3);
    Solution right = Solution::compute(scene);
    WheelAngles w = anglesAt(right, 2.0);
    EXPECT_NEAR(w.theta1, sdot * 2.0 * (rho - a) / (rho * r), 1e-11);
    EXPECT_NEAR(w.theta2, sdot * 2.0 * (rho + a) / (rho * r), 1e-11);
}

TEST(WheelAngles, RatesAreTheRollingConstraintsOnTheSinusoid) {
    // central differences of the angles against sdot = R thetadot (A5) and (B2)-(B3)
    const double h = 1e-4;
    Scene disk = diskScene();
    Solution diskSol = Solution::compute(disk); // the default path y = -sin(x)
    for (double t : {0.7, 3.1, 8.2}) {
        const MotionSample m = diskSol.at(t);
        const double rate =
            (anglesAt(diskSol, t + h).theta1 - anglesAt(diskSol, t - h).theta1) / (2 * h);
        EXPECT_NEAR(rate, m.control.sdot / 0.6, 1e-7) << t;
    }
    Scene carriage = carriageScene();
    Solution sol = Solution::compute(carriage);
    for (double t : {0.7, 3.1, 8.2}) {
        const MotionSample m = sol.at(t);
        const WheelAngles lo = anglesAt(sol, t - h), hi = anglesAt(sol, t + h);
        const double sdot = m.control.sdot, phidot = m.control.phidot;
        EXPECT_NEAR((hi.theta1 - lo.theta1) / (2 * h), (sdot + 0.4 * phidot) / 0.3, 1e-7) << t;
        EXPECT_NEAR((hi.theta2 - lo.theta2) / (2 * h), (sdot - 0.4 * phidot) / 0.3, 1e-7) << t;
        // and from the positions alone: sdot = |dP/dt| along the heading
        const MotionSample mlo = sol.at(t - h), mhi = sol.at(t + h);
        const double speed = std::hypot(mhi.x - mlo.x, mhi.y - mlo.y) / (2 * h);
        EXPECT_NEAR((hi.theta1 + hi.theta2 - lo.theta1 - lo.theta2) / (4 * h), speed / 0.3, 1e-6)
            << t;
    }
}

TEST(WheelAngles, DiskBacksUpThroughACuspAndRollsBack) {
    // x = u^2, y = u^3 on [-1, 1]: |r'| = |u| sqrt(4 + 9u^2) is even in u, so the time law is
    // symmetric about the cusp at u = 0, reached at half the duration after an arc of
    // L = integral_0^1 u sqrt(4 + 9u^2) du = (13^(3/2) - 8)/27; then the disk backs up the same
    // length and its angle returns to 0
    Scene scene = diskScene();
    parametric(scene, "u^2", "u^3", -1, 1);
    Solution sol = Solution::compute(scene);
    const double arc = (std::pow(13.0, 1.5) - 8) / 27;
    ASSERT_NEAR(sol.path()->length(), 2 * arc, 1e-12);
    EXPECT_NEAR(anglesAt(sol, sol.duration() / 2).theta1, arc / 0.6, 1e-9);
    EXPECT_NEAR(anglesAt(sol, sol.duration()).theta1, 0, 1e-12);
    // backing up, it rolls backwards: thetadot = sdot/R < 0
    const double h = 1e-4, t = 0.75 * sol.duration();
    const MotionSample m = sol.at(t);
    ASSERT_LT(m.control.sdot, 0);
    EXPECT_NEAR((anglesAt(sol, t + h).theta1 - anglesAt(sol, t - h).theta1) / (2 * h),
                m.control.sdot / 0.6, 1e-7);
}

TEST(WheelAngles, CarriagePivotsWithItsWheelsTurningOppositeWays) {
    // the polyline (0,0) (1,0) (1,1) with a pivot: 1 m ahead, a quarter turn left about P, 1 m
    // ahead; in the pivot sdot = 0, so R thetadot1 = a phidot = -R thetadot2
    const double a = 0.4, r = 0.3;
    Scene scene = carriageScene();
    scene.path.kind = PathKind::Polyline;
    scene.path.points = {{0, 0}, {1, 0}, {1, 1}};
    scene.path.corners = CornerMode::Pivot;
    Solution sol = Solution::compute(scene);
    ASSERT_EQ(sol.path()->pivotCount(), 1);
    ASSERT_NEAR(sol.path()->length(), 2, 1e-12);
    // v_T = 1: 1 s along the first segment, then the pivot at |phidot| = v_T/b
    const double pivot = (kPi / 2) * carriageB();
    const double mid = 1 + pivot / 2;
    WheelAngles w = anglesAt(sol, mid);
    EXPECT_NEAR(w.theta1, (1 + a * kPi / 4) / r, 1e-9);
    EXPECT_NEAR(w.theta2, (1 - a * kPi / 4) / r, 1e-9);
    w = anglesAt(sol, sol.duration());
    EXPECT_NEAR(w.theta1, (2 + a * kPi / 2) / r, 1e-9);
    EXPECT_NEAR(w.theta2, (2 - a * kPi / 2) / r, 1e-9);
}

TEST(WheelAngles, SleighHasNoWheels) {
    Solution sol = Solution::compute(Scene{});
    const WheelAngles w = anglesAt(sol, 2.0);
    EXPECT_EQ(w.wheels, 0);
    EXPECT_EQ(w.theta1, 0);
    EXPECT_EQ(w.theta2, 0);
}

TEST(WheelAngles, SignedTravelCountsBackingUpNegative) {
    Scene scene = diskScene();
    parametric(scene, "u^2", "u^3", -1, 1);
    Solution sol = Solution::compute(scene);
    const double arc = (std::pow(13.0, 1.5) - 8) / 27;
    EXPECT_NEAR(signedTravel(*sol.path(), 0), 0, 1e-15);
    EXPECT_NEAR(signedTravel(*sol.path(), arc), arc, 1e-12);
    EXPECT_NEAR(signedTravel(*sol.path(), 1.5 * arc), 0.5 * arc, 1e-12);
}
