// The free (Lagrange-d'Alembert) sleigh: closed form against an independent high-order ODE
// solve of (D12)-(D15), and against the hypergeometric closed form for b/a = 2.
#include "motion/free_motion.h"
#include "scene/presets.h"
#include "scene/solution.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

using namespace chaplygin;

namespace {

struct Lda {
    double a, b;
};

// y = (x, y, phi, sdot, phidot): sddot = a phidot^2, phiddot = -a sdot phidot/b^2
int rhs(double, const double y[], double f[], void* p) {
    const Lda& s = *static_cast<Lda*>(p);
    f[0] = y[3] * std::cos(y[2]);
    f[1] = y[3] * std::sin(y[2]);
    f[2] = y[4];
    f[3] = s.a * y[4] * y[4];
    f[4] = -s.a * y[3] * y[4] / (s.b * s.b);
    return GSL_SUCCESS;
}

void checkAgainstOde(const DerivedSystem& sys, const FreeInitial& init, double horizon) {
    FreeMotion free(sys, init, horizon);
    Lda params{sys.a, sys.b};
    gsl_odeiv2_system ode{rhs, nullptr, 5, &params};
    gsl_odeiv2_driver* d =
        gsl_odeiv2_driver_alloc_y_new(&ode, gsl_odeiv2_step_rk8pd, 1e-3, 1e-14, 1e-14);
    double y[5] = {init.x, init.y, init.phi, init.sdot, init.phidot};
    double t = 0;
    for (double target = 1; target <= horizon; target += 1) {
        ASSERT_EQ(gsl_odeiv2_driver_apply(d, &t, target, y), GSL_SUCCESS);
        FreeState s = free.at(target);
        double scale = 1 + std::fabs(target) * std::hypot(init.sdot, sys.b * init.phidot);
        EXPECT_NEAR(s.x, y[0], 2e-11 * scale) << "t = " << target;
        EXPECT_NEAR(s.y, y[1], 2e-11 * scale) << "t = " << target;
        EXPECT_NEAR(s.phi, y[2], 1e-11) << "t = " << target;
        EXPECT_NEAR(s.sdot, y[3], 1e-12) << "t = " << target;
        EXPECT_NEAR(s.phidot, y[4], 1e-12) << "t = " << target;
        EXPECT_NEAR(s.energy, free.at(0).energy, 1e-14);
    }
    gsl_odeiv2_driver_free(d);
}

} // namespace

TEST(FreeMotion, MatchesOdeOverLongTimesTurningLeft) {
    checkAgainstOde({1.0, 0.5, 1.0}, {0.3, -0.2, 0.4, 0.6, 0.9}, 60);
}

TEST(FreeMotion, MatchesOdeTurningRightAndBackwards) {
    checkAgainstOde({2.0, 0.3, 0.7}, {0, 0, -1.0, -0.4, -1.3}, 40);
}

TEST(FreeMotion, NegativeOffsetEndsMovingBackwards) {
    checkAgainstOde({1.0, -0.4, 0.9}, {1, 1, 0.2, 0.5, 0.8}, 40);
    FreeMotion free({1.0, -0.4, 0.9}, {1, 1, 0.2, 0.5, 0.8}, 200);
    EXPECT_LT(free.at(200).sdot, 0);
}

TEST(FreeMotion, HypergeometricClosedFormForBetaTwo) {
    // b/a = 2: G(th) = -cos(2th)/2 + ln cos th + i(th - sin(2th)/2) (physics.md sec. 1)
    const double a = 0.5, b = 1.0, beta = 2;
    FreeInitial init{0, 0, 0.3, 0.2, 0.8};
    FreeMotion free({1.0, a, b}, init, 30);
    double V = std::hypot(init.sdot, b * init.phidot);
    double psi0 = std::asin(init.sdot / V);
    auto G = [](double th) {
        return std::complex<double>(-std::cos(2 * th) / 2 + std::log(std::cos(th)),
                                    th - std::sin(2 * th) / 2);
    };
    for (double t : {0.5, 2.0, 7.0, 15.0, 30.0}) {
        FreeState s = free.at(t);
        double psi =
            2 * std::atan(std::tanh(0.5 * (a * V / (b * b) * t + std::atanh(init.sdot / V))));
        std::complex<double> z =
            (b * b / a) * std::polar(1.0, init.phi - beta * psi0) * (G(psi) - G(psi0));
        EXPECT_NEAR(s.x, z.real(), 1e-11 * (1 + t)) << t;
        EXPECT_NEAR(s.y, z.imag(), 1e-11 * (1 + t)) << t;
        EXPECT_NEAR(s.phi, init.phi + beta * (psi - psi0), 1e-12);
    }
}

TEST(FreeMotion, LongHorizonHasNoNaNAndStaysOnTheEnergyLevel) {
    FreeMotion free({1.0, 0.5, 1.0}, {0, 0, 0, 0.1, 1.0}, 5000);
    FreeState end = free.at(5000);
    EXPECT_TRUE(std::isfinite(end.x) && std::isfinite(end.y) && std::isfinite(end.phi));
    EXPECT_NEAR(end.energy, free.at(0).energy, 1e-15);
    EXPECT_NEAR(end.sdot, std::hypot(0.1, 1.0), 1e-14);
    // beyond the transient the path is a straight line at speed V
    FreeState before = free.at(4000);
    EXPECT_NEAR(std::hypot(end.x - before.x, end.y - before.y), 1000 * std::hypot(0.1, 1.0), 1e-9);
}

TEST(FreeMotion, DegenerateCasesAreClosedForm) {
    // a = 0: uniform circle of radius sdot/phidot
    FreeMotion circle({1.0, 0.0, 1.0}, {1, 0, std::acos(-1) / 2, 0.5, 0.5}, 20);
    for (double t : {1.0, 5.0, 12.0}) {
        FreeState s = circle.at(t);
        EXPECT_NEAR(s.x, std::cos(0.5 * t), 1e-14);
        EXPECT_NEAR(s.y, std::sin(0.5 * t), 1e-14);
    }
    // phidot0 = 0: a straight line
    FreeMotion line({1.0, 0.5, 1.0}, {0, 0, 0.25, 2.0, 0.0}, 10);
    EXPECT_NEAR(line.at(3).x, 6 * std::cos(0.25), 1e-14);
    EXPECT_NEAR(line.at(3).y, 6 * std::sin(0.25), 1e-14);
}

TEST(FreeMotion, StartsFromTheControlledState) {
    Solution sol = Solution::compute(presetScene("catenary"));
    MotionSample start = sol.at(0);
    EXPECT_NEAR(start.free.x, start.x, 1e-15);
    EXPECT_NEAR(start.free.y, start.y, 1e-15);
    EXPECT_NEAR(start.free.phi, start.phi, 1e-15);
    EXPECT_NEAR(start.free.sdot, start.control.sdot, 1e-15);
    EXPECT_NEAR(start.free.phidot, start.control.phidot, 1e-15);
    EXPECT_NEAR(start.free.energy, start.control.energy, 1e-15);
}

TEST(FreeMotion, ConstantsAreThoseOfTheClosedForm) {
    // the Equations panel shows V, k and c: they reproduce the motion's velocities
    DerivedSystem sys{1.0, 0.5, 1.0};
    FreeInitial init{0, 0, 0.3, 0.8, -0.6};
    FreeMotion free(sys, init, 10);
    FreeMotion::Constants k = free.constants();
    ASSERT_TRUE(k.general);
    EXPECT_NEAR(k.v, std::hypot(0.8, 1.0 * 0.6), 1e-15);
    EXPECT_NEAR(k.k, 0.5 * k.v, 1e-15);
    EXPECT_EQ(k.sigma, -1.0);
    for (double t : {0.0, 1.5, 7.0}) {
        FreeState f = free.at(t);
        EXPECT_NEAR(f.sdot, k.v * std::tanh(k.k * t + k.c), 1e-13) << t;
        EXPECT_NEAR(f.phidot, k.sigma * (k.v / sys.b) / std::cosh(k.k * t + k.c), 1e-13) << t;
    }
    EXPECT_FALSE(FreeMotion({1.0, 0.0, 1.0}, init, 10).constants().general); // a = 0: a circle
}
