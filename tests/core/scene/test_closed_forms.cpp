// The controlled motion against the paper's closed forms: line (72)-(81), circle (82)-(96).
#include "scene/presets.h"
#include "scene/solution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace chaplygin;

TEST(ClosedForms, LineFollowsEqs80And81) {
    Scene scene = presetScene("line"); // y = 0.5 x + 1, b = 1, a = 0.5, v_T = 1
    scene.speed = 1.7;
    Solution sol = Solution::compute(scene);
    const double A = 0.5, B = 1, vT = 1.7, a = 0.5, b = 1;
    EXPECT_NEAR(sol.duration(), 8 * std::sqrt(1 + A * A) / vT, 1e-12);
    EXPECT_NE(sol.models().timeLaw.find("closed form"), std::string::npos);
    for (double t : {0.0, 0.3, 1.1, 2.9, 4.0, sol.duration()}) {
        MotionSample m = sol.at(t);
        EXPECT_NEAR(m.x, vT * t / std::sqrt(1 + A * A), 1e-12) << t;
        EXPECT_NEAR(m.y, A * vT * t / std::sqrt(1 + A * A) + B, 1e-12) << t;
        EXPECT_NEAR(m.control.psi, std::numbers::pi / 2, 1e-15);
        EXPECT_NEAR(m.control.chi, std::numbers::pi / 2 - (a / b) * std::atan(A), 1e-14); // (76)
        EXPECT_NEAR(m.control.lambda, 0, 1e-14);
        EXPECT_NEAR(m.control.energy, 0.5 * vT * vT, 1e-14);
    }
}

TEST(ClosedForms, CircleFollowsEqs89To96) {
    Scene scene = presetScene("circle"); // R = 2 from (R, 0) counter-clockwise
    scene.system.params = {{"m", 1.3}, {"a", 0.4}, {"b", 0.9}};
    scene.speed = 1.2;
    Solution sol = Solution::compute(scene);
    const double R = 2, vT = 1.2, b = 0.9, a = 0.4, m = 1.3;
    const double omega = vT / std::sqrt(b * b + R * R); // (95)
    // period 2 pi sqrt(b^2 + R^2)/v_T, paper (85) as corrected
    EXPECT_NEAR(sol.duration(), 2 * std::numbers::pi * std::sqrt(b * b + R * R) / vT, 1e-12);
    for (double t : {0.0, 0.77, 3.3, 7.9, sol.duration()}) {
        MotionSample s = sol.at(t);
        EXPECT_NEAR(s.x, R * std::cos(omega * t), 1e-12) << t;          // (93)
        EXPECT_NEAR(s.y, R * std::sin(omega * t), 1e-12) << t;          // (94)
        EXPECT_NEAR(s.s, vT * R / std::sqrt(b * b + R * R) * t, 1e-12); // (90)
        EXPECT_NEAR(s.phi, std::numbers::pi / 2 + omega * t, 1e-12);    // (87)
        EXPECT_NEAR(s.control.psi, std::atan(R / b), 1e-14);            // (84)
        EXPECT_NEAR(s.control.chi, std::atan(R / b) - (a / b) * (std::numbers::pi / 2 + omega * t),
                    1e-12);                                   // (96)
        EXPECT_NEAR(s.control.lambda, -m * a * omega, 1e-14); // lambda = -m a phidot on a circle
        EXPECT_NEAR(s.control.energy, 0.5 * m * vT * vT, 1e-13);
        // workless control: f_s sdot + tau phidot = 0 (docs/physics.md §2)
        EXPECT_NEAR(s.control.forceAxial * s.control.sdot +
                        s.control.controlCouple * s.control.phidot,
                    0, 1e-13);
    }
}

TEST(ClosedForms, EnergyModeControlIsWorklessOnTheSinusoid) {
    Solution sol = Solution::compute(presetScene("sinusoid"));
    for (double t = 0; t <= sol.duration(); t += 0.37) {
        MotionSample s = sol.at(t);
        const ControlState& c = s.control;
        EXPECT_NEAR(c.energy, 0.5, 1e-14);
        EXPECT_NEAR(c.forceAxial, c.lambda * c.phidot, 1e-13);   // F_cs = lambda phidot
        EXPECT_NEAR(c.controlCouple, -c.lambda * c.sdot, 1e-13); // tau = -lambda sdot
    }
}
