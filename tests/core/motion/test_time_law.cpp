// The time law against independent GSL quadrature (QAGS at 1e-13), the inflection of
// y = -sin x, corners, and constant-speed mode.
#include "common/input_error.h"
#include "gsl_quadrature.h"
#include "scene/presets.h"
#include "scene/solution.h"

#include <gsl/gsl_errno.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

using namespace chaplygin;

namespace {

double integrate(const std::function<double(double)>& f, double a, double b) {
    return test::gslIntegral(f, a, b, 1e-14, 1e-13, test::GslRule::Extrapolating, 1000);
}

} // namespace

TEST(TimeLaw, CatenaryAgainstQuadratureOfEq103) {
    Scene scene = presetScene("catenary"); // x0 = 1, b = 1, v_T = 1, s in [0, 5]
    scene.system.params = {{"m", 1.0}, {"a", 0.5}, {"b", 1.4}};
    scene.speed = 0.8;
    Solution sol = Solution::compute(scene);
    const double x0 = 1, b = 1.4, vT = 0.8;
    // (103), corrected: t(s) = (1/v_T) \int_0^s sqrt(1 + (b x0)^2/(s^2 + x0^2)^2) ds
    auto tOfS = [&](double s) {
        return integrate(
            [&](double u) { return std::sqrt(1 + std::pow(b * x0 / (u * u + x0 * x0), 2)) / vT; },
            0, s);
    };
    EXPECT_NEAR(sol.duration(), tOfS(5.0), 1e-12);
    for (double t : {0.1, 0.5, 1.0, 2.5, 4.0, 6.0}) {
        MotionSample m = sol.at(t);
        EXPECT_NEAR(tOfS(m.s), t, 1e-11) << t;
        // the body is on the path at that arc length, paper (97)-(98)
        EXPECT_NEAR(m.x, std::sqrt(m.s * m.s + x0 * x0), 1e-12);
        EXPECT_NEAR(m.y, x0 * std::asinh(m.s / x0), 1e-12);
        // (102) as corrected: sdot = v_T (s^2 + x0^2)/sqrt((s^2 + x0^2)^2 + (b x0)^2)
        double q = m.s * m.s + x0 * x0;
        EXPECT_NEAR(m.control.sdot, vT * q / std::sqrt(q * q + b * b * x0 * x0), 1e-13);
        // the catenary turns clockwise: Psi in (pi/2, pi)
        EXPECT_GT(m.control.psi, std::numbers::pi / 2);
        EXPECT_LT(m.control.psi, std::numbers::pi);
        // (106) corrected: dPsi/ds = -2 b x0 s/((x0^2 + s^2)^2 + (b x0)^2)
        double dpsids = -2 * b * x0 * m.s / (q * q + b * b * x0 * x0);
        EXPECT_NEAR(m.control.psidot, m.control.sdot * dpsids, 1e-12);
    }
}

TEST(TimeLaw, SinusoidInflectionIsSmoothAndMatchesEq112) {
    Solution sol = Solution::compute(presetScene("sinusoid")); // y = -sin x, b = 1, v_T = 1
    const double b = 1, vT = 1;
    // (112): xdot = v_T (1 + cos^2 x)/sqrt(b^2 sin^2 x + (1 + cos^2 x)^3); t(x) = \int dx/xdot
    auto xdot = [&](double x) {
        double c2 = 1 + std::cos(x) * std::cos(x);
        return vT * c2 / std::sqrt(b * b * std::sin(x) * std::sin(x) + c2 * c2 * c2);
    };
    EXPECT_NEAR(sol.duration(),
                integrate([&](double x) { return 1 / xdot(x); }, 0, 4 * std::numbers::pi), 1e-11);
    double previousPsi = std::numbers::pi / 2;
    for (double t = 0; t <= sol.duration(); t += 0.05) {
        MotionSample m = sol.at(t);
        EXPECT_NEAR(integrate([&](double x) { return 1 / xdot(x); }, 0, m.x), t, 1e-10);
        EXPECT_NEAR(m.y, -std::sin(m.x), 1e-12);
        EXPECT_NEAR(m.control.sdot * std::cos(m.phi), xdot(m.x), 1e-12);
        EXPECT_GT(m.control.sdot, 0) << "the sleigh never reverses";
        EXPECT_GT(m.control.psi, 0);
        EXPECT_LT(m.control.psi, std::numbers::pi);
        EXPECT_LT(std::fabs(m.control.psi - previousPsi), 0.05) << "Psi is continuous at t = " << t;
        previousPsi = m.control.psi;
    }
    // at the inflection x = pi, Psi passes pi/2 exactly
    double tPi = integrate([&](double x) { return 1 / xdot(x); }, 0, std::numbers::pi);
    MotionSample inflection = sol.at(tPi);
    EXPECT_NEAR(inflection.x, std::numbers::pi, 1e-10);
    EXPECT_NEAR(inflection.control.psi, std::numbers::pi / 2, 1e-10);
}

TEST(TimeLaw, PivotCornerTakesBTimesTurnOverVT) {
    Scene scene;
    scene.path.kind = PathKind::Polyline;
    scene.path.points = {{0, 0}, {1, 0}, {1, 2}};
    scene.path.corners = CornerMode::Pivot;
    scene.system.params = {{"m", 1.0}, {"a", 0.3}, {"b", 0.8}};
    scene.speed = 2.0;
    Solution sol = Solution::compute(scene);
    const double b = 0.8, vT = 2.0, turn = std::numbers::pi / 2;
    const double t1 = 1 / vT, t2 = t1 + b * turn / vT;
    EXPECT_NEAR(sol.duration(), 3 / vT + b * turn / vT, 1e-13);
    EXPECT_EQ(sol.path()->pivotCount(), 1);
    MotionSample mid = sol.at(0.5 * (t1 + t2));
    EXPECT_NEAR(mid.x, 1, 1e-14);
    EXPECT_NEAR(mid.y, 0, 1e-14);
    EXPECT_NEAR(mid.phi, turn / 2, 1e-13);  // turning at v_T/b about P
    EXPECT_NEAR(mid.control.psi, 0, 1e-15); // left turn: Psi -> 0
    EXPECT_NEAR(mid.control.sdot, 0, 1e-15);
    EXPECT_NEAR(mid.control.phidot, vT / b, 1e-14);
    EXPECT_NEAR(mid.control.energy, 0.5 * vT * vT, 1e-13);
    MotionSample after = sol.at(t2 + 0.25);
    EXPECT_NEAR(after.x, 1, 1e-13);
    EXPECT_NEAR(after.y, 0.25 * vT, 1e-13);
    EXPECT_NEAR(after.phi, turn, 1e-13);
}

TEST(TimeLaw, ConstantSpeedModeOnTheCatenary) {
    Scene scene = presetScene("catenary");
    scene.mode = SpeedMode::Speed;
    scene.speed = 0.7;
    Solution sol = Solution::compute(scene);
    EXPECT_NEAR(sol.duration(), 5.0 / 0.7, 1e-12);
    for (double t : {0.0, 1.0, 3.3, 7.0}) {
        MotionSample m = sol.at(t);
        EXPECT_NEAR(m.s, 0.7 * t, 1e-12); // App. C: t = s/v_s
        EXPECT_NEAR(m.x, std::sqrt(m.s * m.s + 1), 1e-12);
        double kappa = -1 / (m.s * m.s + 1);
        EXPECT_NEAR(m.kappa, kappa, 1e-12);
        // T = (m/2) v_s^2 (1 + b^2 kappa^2) varies (C15)
        EXPECT_NEAR(m.control.energy, 0.5 * 0.49 * (1 + kappa * kappa), 1e-13);
    }
}

TEST(TimeLaw, ConstantSpeedModeCannotTurnACorner) {
    Scene scene;
    scene.path.kind = PathKind::Polyline;
    scene.path.points = {{0, 0}, {1, 0}, {1, 1}};
    scene.mode = SpeedMode::Speed;
    try {
        Solution::compute(scene);
        FAIL() << "a corner in constant-speed mode was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("corner at (1, 0)"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("cannot turn"), std::string::npos) << e.what();
    }
}

TEST(TimeLaw, ParameterChangeReusesTheTabulatedPath) {
    Scene scene = presetScene("sinusoid");
    Solution first = Solution::compute(scene);
    scene.system.params["b"] = 1.7;
    scene.speed = 1.3;
    Solution reused = Solution::compute(scene, first.path());
    Solution fresh = Solution::compute(scene);
    EXPECT_EQ(reused.path().get(), first.path().get());
    EXPECT_NEAR(reused.duration(), fresh.duration(), 1e-13);
    for (double t : {0.5, 3.0, 9.0}) {
        EXPECT_NEAR(reused.at(t).x, fresh.at(t).x, 1e-13);
        EXPECT_NEAR(reused.at(t).control.lambda, fresh.at(t).control.lambda, 1e-12);
    }
}

TEST(TimeLaw, HorizonBeyondThePathIsRejected) {
    Scene scene = presetScene("line");
    scene.tEnd = 100;
    EXPECT_THROW(Solution::compute(scene), InputError);
}

TEST(TimeLaw, SmallAndLargeGyrationRadiiStayAccurate) {
    gsl_set_error_handler_off();
    Scene scene = presetScene("sinusoid");
    Solution base = Solution::compute(scene);
    for (double b : {0.01, 0.5, 10.0, 100.0}) {
        scene.system.params = {{"m", 1.0}, {"a", 0.0}, {"b", b}};
        Solution sol = Solution::compute(scene, base.path());
        // t(x) = \int sqrt(b^2 sin^2 x + (1 + cos^2 x)^3)/(1 + cos^2 x) dx, from paper (112)
        double exact = integrate(
            [&](double x) {
                double c2 = 1 + std::cos(x) * std::cos(x);
                return std::sqrt(b * b * std::sin(x) * std::sin(x) + c2 * c2 * c2) / c2;
            },
            0, 4 * std::numbers::pi);
        EXPECT_NEAR(sol.duration(), exact, 1e-11 * exact) << "b = " << b;
    }
}

TEST(TimeLaw, NodeSeriesHoldsThePivotStateThroughTheTurn) {
    Scene scene;
    scene.path.kind = PathKind::Polyline;
    scene.path.points = {{0, 0}, {1, 0}, {1, 1}};
    Solution sol = Solution::compute(scene);
    const double t1 = 1.0, t2 = 1.0 + std::numbers::pi / 2; // b = 1, v_T = 1
    int inTurn = 0;
    for (const MotionSample& m : sol.controlledAtNodes()) {
        if (m.t > t1 + 1e-12 && m.t < t2 - 1e-12)
            ADD_FAILURE() << "a node inside the turn at t = " << m.t;
        bool pivoting = std::isinf(m.kappa);
        if (pivoting) {
            ++inTurn;
            EXPECT_NEAR(m.control.psi, 0, 1e-15); // a left turn: Psi = 0 at both ends of the turn
            EXPECT_NEAR(m.control.lambda, -0.5, 1e-15); // -m a phidot, phidot = v_T/b
        }
    }
    EXPECT_EQ(inTurn, 2);
}
