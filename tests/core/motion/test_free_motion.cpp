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
#include <numbers>

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
    // b/a = 2: G(th) = -cos(2th)/2 + ln cos th + i(th - sin(2th)/2) (docs/physics.md §4)
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

// The free body's Psi and chi (docs/physics.md §4) against their definitions, computed here from
// its own sdot, phidot, phi and from the path it starts on: (sdot, b phidot) = V (sin Psi, cos
// Psi), Psi(0) = atan2(1, b kappa0) of the control law, chi = Psi - (a/b) phi, constant (lambda =
// 0); and Psi against the closed form tan Psi = sigma sinh(kt + c), with V, k, c from the start.
TEST(FreeMotion, ControlAngleAndChiFollowTheirDefinitions) {
    Solution sol = Solution::compute(presetScene("catenary"));
    const DerivedSystem& sys = sol.system();
    MotionSample start = sol.at(0);
    const FreeState& f0 = start.free;
    double psi0 = std::atan2(1.0, sys.b * start.kappa);
    double chi0 = psi0 - sys.a / sys.b * start.phi;
    EXPECT_NEAR(f0.psi, psi0, 1e-14);
    EXPECT_NEAR(f0.psi, start.control.psi, 1e-14);
    EXPECT_NEAR(f0.chi, chi0, 1e-14);
    EXPECT_NEAR(f0.chi, start.control.chi, 1e-14);

    double v = std::hypot(f0.sdot, sys.b * f0.phidot), k = sys.a * v / (sys.b * sys.b);
    double c = std::asinh(f0.sdot / (sys.b * std::fabs(f0.phidot)));
    double sigma = f0.phidot > 0 ? 1 : -1;
    ASSERT_LT(sigma, 0); // the catenary turns clockwise: Psi in (pi/2, pi)
    ASSERT_GT(sol.tEnd(), 4);
    for (int i = 0; i <= 200; ++i) {
        double t = sol.tEnd() * i / 200;
        FreeState f = sol.freeAt(t);
        EXPECT_NEAR(v * std::sin(f.psi), f.sdot, 1e-14 * v) << "t = " << t;
        EXPECT_NEAR(v * std::cos(f.psi), sys.b * f.phidot, 1e-14 * v) << "t = " << t;
        EXPECT_NEAR(f.chi, f.psi - sys.a / sys.b * f.phi, 1e-14) << "t = " << t;
        EXPECT_NEAR(f.chi, chi0, 1e-12) << "t = " << t;
        double gd = 2 * std::atan(std::tanh(0.5 * (k * t + c)));
        EXPECT_NEAR(f.psi, sigma > 0 ? gd : std::numbers::pi - gd, 1e-13) << "t = " << t;
    }
}

// Where sdot changes sign (a < 0, or a start backing up), Psi follows the closed form's branch,
// gd(kt + c) turning left and pi - gd(kt + c) turning right, without a jump, and chi stays
// constant.
TEST(FreeMotion, ControlAngleContinuousWhileBackingUp) {
    struct Case {
        DerivedSystem sys;
        FreeInitial init;
    };
    const Case cases[] = {
        {{1.0, -0.4, 0.9}, {1, 1, 0.2, 0.5, -0.8}},  // right turn, ends backing up
        {{1.0, -0.4, 0.9}, {1, 1, 0.2, 0.5, 0.8}},   // left turn, ends backing up
        {{2.0, 0.3, 0.7}, {0, 0, -1.0, -0.4, -1.3}}, // right turn, starts backing up
    };
    for (const Case& k : cases) {
        const DerivedSystem& sys = k.sys;
        const FreeInitial& i0 = k.init;
        FreeMotion free(sys, i0, 40);
        double v = std::hypot(i0.sdot, sys.b * i0.phidot), rate = sys.a * v / (sys.b * sys.b);
        double c = std::asinh(i0.sdot / (sys.b * std::fabs(i0.phidot)));
        double sigma = i0.phidot > 0 ? 1 : -1;
        auto psi = [&](double t) {
            double gd = 2 * std::atan(std::tanh(0.5 * (rate * t + c)));
            return sigma > 0 ? gd : std::numbers::pi - gd;
        };
        double chi0 = psi(0) - sys.a / sys.b * i0.phi;
        ASSERT_LT(free.at(0).sdot * free.at(40).sdot, 0) << "sdot changes sign";
        double before = free.at(0).psi;
        for (int j = 0; j <= 400; ++j) {
            double t = 40.0 * j / 400;
            FreeState f = free.at(t);
            EXPECT_NEAR(f.psi, psi(t), 1e-12) << "t = " << t;
            EXPECT_NEAR(v * std::sin(f.psi), f.sdot, 1e-14 * v) << "t = " << t;
            EXPECT_NEAR(f.chi, chi0, 1e-11) << "t = " << t;
            EXPECT_LT(std::fabs(f.psi - before), 0.2) << "t = " << t;
            before = f.psi;
        }
    }
}

// The two ill-conditioned cases, tiny offset (b/a = 1e9) and tiny initial curvature (kappa0 = 1e-7
// and 1e-9, below where c = atanh(sdot0/V) is lost), against a 60-digit mpmath reference:
// tests/core/motion/free_motion_reference.py prints these rows (t, x, y, phi - phi0, sdot, phidot).
namespace {

struct PrecisionCase {
    double a, b;
    FreeInitial init;
    double totalTurn;
    double rows[4][6];
};

const PrecisionCase kPrecisionCases[] = {
    // tiny offset: a = 1e-09, b = 1.0, initial (0.3, -0.2, 0.4, 0.6, 0.9)
    {1e-9,
     1.0,
     {0.3, -0.2, 0.4, 0.6, 0.9},
     982793723.24732903524,
     {
         {0.5, 0.54124137530261535688, -0.025948101194838419412, 0.44999999993250001109,
          0.60000000040499997767, 0.89999999973000002215},
         {2.0, 0.57938537468595924408, 0.80637474239214095531, 1.7999999989200000439,
          0.60000000161999997585, 0.89999999892000002139},
         {10.0, 0.056904737638604746609, 1.0805027027154062196, 8.9999999730000001545,
          0.6000000080999999292, 0.89999999460000000195},
         {30.0, 0.5517988051360324868, 0.84171255744168564206, 26.999999756999998844,
          0.6000000242999995404, 0.89999998379999983995},
     }},
    // tiny offset backwards: a = -1e-09, b = 0.8, initial (0.0, 0.0, -1.0, -0.4, -1.3)
    {-1e-9,
     0.8,
     {0.0, 0.0, -1.0, -0.4, -1.3},
     -962897994.38134193128,
     {
         {0.5, -0.047813551926317157066, 0.19059175241391909925, -0.64999999989843752214,
          -0.40000000084500002194, -1.299999999593750044},
         {2.0, 0.39507428809209439614, 0.44217253133220411385, -2.5999999983750000849,
          -0.40000000338000001798, -1.2999999983750000386},
         {10.0, -0.045888126729499097718, 0.12417385887431345496, -12.999999959374999957,
          -0.40000001689999991658, -1.2999999918749998982},
         {30.0, 0.029648454329013474385, 0.37145852054409548878, -38.99999963437498817,
          -0.40000005069999907158, -1.2999999756249987282},
     }},
    // curvature 1e-7: a = 0.5, b = 1.0, initial (0.0, 0.0, 0.1, 1.0, 1e-07)
    {0.5,
     1.0,
     {0.0, 0.0, 0.1, 1.0, 1e-7},
     1.9999999999999932428e-7,
     {
         {0.5, 0.49750208148890100973, 0.049916719786173762502, 4.4239843385719020511e-8,
          1.0000000000000019673, 7.7880078307140462559e-8},
         {2.0, 1.9900083158653858788, 0.19966697971028672543, 1.2642411176571142341e-7,
          1.0000000000000043233, 3.6787944117144126078e-8},
         {10.0, 9.9500414927776270518, 0.99833576115665061707, 1.9865241060018226798e-7,
          1.0000000000000049998, 6.7379469990853151872e-10},
         {30.0, 29.850124399273234502, 2.9950080714282526073, 1.9999993881953522392e-7,
          1.000000000000005, 3.0590232050180359661e-14},
     }},
    // curvature 1e-9: a = 0.5, b = 1.0, initial (1.0, 2.0, -0.3, 1.0, -1e-09)
    {0.5,
     1.0,
     {1.0, 2.0, -0.3, 1.0, -1e-9},
     -2.0000000000000001239e-9,
     {
         {0.5, 1.477668244528758158, 1.8522398965592724618, -4.4239843385719029106e-10,
          1.0000000000000000002, -7.7880078307140491673e-10},
         {2.0, 2.9106729778163488118, 1.408959585271526256, -1.2642411176571154354e-9,
          1.0000000000000000004, -3.678794411714423444e-10},
         {10.0, 10.553364886519772116, -0.9552020819245274947, -1.9865241060018291889e-9,
          1.0000000000000000005, -6.7379469990854675011e-12},
         {30.0, 29.660094657219048715, -6.8656062533390314833, -1.9999993881953591202e-9,
          1.0000000000000000005, -3.0590232050182580521e-16},
     }},
};

void checkPrecisionCase(const PrecisionCase& pc) {
    FreeMotion free({1.0, pc.a, pc.b}, pc.init, 30);
    EXPECT_NEAR(free.totalTurn(), pc.totalTurn, 1e-12 * std::fabs(pc.totalTurn));
    for (const auto& row : pc.rows) {
        FreeState s = free.at(row[0]);
        EXPECT_NEAR(s.x, row[1], 1e-12) << "t = " << row[0];
        EXPECT_NEAR(s.y, row[2], 1e-12) << "t = " << row[0];
        EXPECT_NEAR(free.turn(row[0]), row[3], 1e-12 * std::fabs(row[3])) << "t = " << row[0];
        EXPECT_NEAR(s.phi, pc.init.phi + row[3], 1e-15 * (1 + std::fabs(s.phi))) << row[0];
        EXPECT_NEAR(s.sdot, row[4], 1e-12 * std::fabs(row[4])) << "t = " << row[0];
        EXPECT_NEAR(s.phidot, row[5], 1e-12 * std::fabs(row[5])) << "t = " << row[0];
    }
}

} // namespace

TEST(FreeMotion, TinyOffsetHasNoCancellation) {
    checkPrecisionCase(kPrecisionCases[0]);
    checkPrecisionCase(kPrecisionCases[1]);
}

TEST(FreeMotion, TinyInitialCurvatureKeepsItsTurn) {
    checkPrecisionCase(kPrecisionCases[2]);
    checkPrecisionCase(kPrecisionCases[3]);
}

TEST(FreeMotion, LongHorizonWithLargeRatioStaysFinite) {
    // sinh(kt/2) and cosh(c + kt/2) both overflow here; the heading must not become NaN
    FreeMotion free({1.0, 0.5, 1.0}, {0, 0, 0, 0.1, 1.0}, 10);
    FreeState far = free.at(3000);
    EXPECT_TRUE(std::isfinite(far.phi) && std::isfinite(far.x));
    EXPECT_NEAR(far.phi, free.totalTurn(), 1e-14);
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
