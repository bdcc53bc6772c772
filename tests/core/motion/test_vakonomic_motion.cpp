// The genuine vakonomic body: the elliptic closed form against an independent rk8pd integration
// of (19) (corrected), (20), (21) at rtol 1e-13 (VakonomicProblem), in every case of the
// pendulum in 2 Psi, and wired into the Solution from the tracking's initial state.
#include "lab/vakonomic_problem.h"
#include "motion/vakonomic_motion.h"
#include "scene/presets.h"
#include "scene/solution.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace chaplygin;

namespace {

int rhs(double t, const double y[], double f[], void* p) {
    static_cast<const VakonomicProblem*>(p)->rhs(t, y, f);
    return GSL_SUCCESS;
}

struct Reference {
    double x, y, phi, sdot, phidot, lambda;
};

// rk8pd with |err| <= 1e-13 (|y| + 1) from the body's initial state; y[5] = lambda_c/m
std::vector<Reference> reference(const DerivedSystem& sys, const VakonomicInitial& init,
                                 const std::vector<double>& times) {
    VakonomicProblem problem(sys);
    gsl_odeiv2_system ode{rhs, nullptr, 6, &problem};
    gsl_odeiv2_driver* d =
        gsl_odeiv2_driver_alloc_y_new(&ode, gsl_odeiv2_step_rk8pd, 1e-3, 1e-13, 1e-13);
    double y[6] = {init.x,    init.y,      init.phi,
                   init.sdot, init.phidot, init.lambda / sys.mass + sys.a * init.phidot};
    double t = 0;
    std::vector<Reference> out;
    for (double target : times) {
        if (target > t) {
            EXPECT_EQ(gsl_odeiv2_driver_apply(d, &t, target, y), GSL_SUCCESS);
        }
        out.push_back({y[0], y[1], y[2], y[3], y[4], sys.mass * (y[5] - sys.a * y[4])});
    }
    gsl_odeiv2_driver_free(d);
    return out;
}

std::vector<double> evenTimes(double horizon, int count = 60) {
    std::vector<double> t;
    for (int i = 0; i <= count; ++i)
        t.push_back(horizon * i / count);
    return t;
}

// max deviation from the reference over the times, positions scaled by 1 + v_T t
double checkAgainstReference(const DerivedSystem& sys, const VakonomicInitial& init, double horizon,
                             double tol) {
    VakonomicMotion vak(sys, init);
    std::vector<double> times = evenTimes(horizon);
    std::vector<Reference> ref = reference(sys, init, times);
    const double vT = std::hypot(init.sdot, sys.b * init.phidot);
    const double t0 = vak.at(0).energy;
    double worst = 0;
    for (std::size_t i = 0; i < times.size(); ++i) {
        VakonomicState s = vak.at(times[i]);
        const Reference& r = ref[i];
        double scale = 1 + vT * times[i];
        double lscale = sys.mass * (vT + std::fabs(init.lambda));
        double dev[] = {
            std::fabs(s.x - r.x) / scale,           std::fabs(s.y - r.y) / scale,
            std::fabs(s.phi - r.phi) / scale,       std::fabs(s.sdot - r.sdot),
            std::fabs(s.phidot - r.phidot) * sys.b, std::fabs(s.lambda - r.lambda) / lscale};
        for (double e : dev) {
            EXPECT_LE(e, tol) << "t = " << times[i];
            worst = std::max(worst, e);
        }
        // energy from the state, conserved (docs/physics.md §2)
        EXPECT_NEAR(s.energy, t0, 1e-12 * t0) << "t = " << times[i];
        // Psi, Psidot and chi are consistent with the state
        EXPECT_NEAR(std::sin(s.psi) * vT, s.sdot, 1e-13 * vT) << "t = " << times[i];
        EXPECT_NEAR(std::cos(s.psi) * vT, sys.b * s.phidot, 1e-13 * vT) << "t = " << times[i];
        EXPECT_NEAR(s.chi, s.psi - sys.a / sys.b * s.phi, 1e-12 * (1 + std::fabs(s.phi)));
        EXPECT_NEAR(s.lambda, sys.mass * (sys.b * s.psidot - sys.a * s.phidot), 1e-13 * lscale);
    }
    std::printf("worst scaled deviation from rk8pd over [0, %g]: %.3g\n", horizon, worst);
    return worst;
}

} // namespace

// A straight start whose multiplier is rounding (Lambda0/omega = 1e-17, so k^2 rounds to 1):
// every state finite and the straight line's (the separatrix's tau0 would be infinite)
TEST(VakonomicMotion, StraightStartWithARoundingMultiplierIsTheLine) {
    DerivedSystem sys{1.0, 0.5, 1.0};
    const double vT = 1.0, lambda = 1e-17 * sys.mass * sys.b * (vT / sys.b);
    VakonomicMotion vak(sys, {0.78, -2.5, 0.0, vT, 0.0, lambda});
    for (double t : {0.0, 0.5, 1.0, 2.0, 5.0}) {
        VakonomicState s = vak.at(t);
        for (double v : {s.x, s.y, s.phi, s.sdot, s.phidot, s.lambda, s.psi})
            ASSERT_TRUE(std::isfinite(v)) << "t = " << t;
        EXPECT_NEAR(s.x, 0.78 + vT * t, 1e-12);
        EXPECT_NEAR(s.y, -2.5, 1e-12);
        EXPECT_NEAR(s.phi, 0.0, 1e-12);
    }
}

TEST(VakonomicMotion, StartsFromTheGivenState) {
    DerivedSystem sys{1.3, 0.4, 0.9};
    VakonomicInitial init{0.3, -0.2, 0.7, 0.6, -0.8, 0.25};
    VakonomicState s = VakonomicMotion(sys, init).at(0);
    EXPECT_NEAR(s.x, init.x, 1e-15);
    EXPECT_NEAR(s.y, init.y, 1e-15);
    EXPECT_NEAR(s.phi, init.phi, 1e-15);
    EXPECT_NEAR(s.sdot, init.sdot, 1e-15);
    EXPECT_NEAR(s.phidot, init.phidot, 1e-15);
    EXPECT_NEAR(s.lambda, init.lambda, 1e-15);
}

TEST(VakonomicMotion, LibrationTurningLeftMatchesRk8pd) {
    DerivedSystem sys{1.0, 0.5, 1.0};
    VakonomicInitial init{0.3, -0.2, 0.4, 0.6, 0.9, 0.1};
    ASSERT_EQ(VakonomicMotion(sys, init).kind(), VakonomicMotion::Case::Libration);
    EXPECT_LE(checkAgainstReference(sys, init, 40, 1e-9), 1e-9);
}

TEST(VakonomicMotion, LibrationTurningRightMatchesRk8pd) {
    DerivedSystem sys{2.0, 0.3, 0.7};
    VakonomicInitial init{1, 2, -0.5, 0.5, -1.1, -0.3};
    ASSERT_EQ(VakonomicMotion(sys, init).kind(), VakonomicMotion::Case::Libration);
    EXPECT_LE(checkAgainstReference(sys, init, 40, 1e-9), 1e-9);
}

TEST(VakonomicMotion, SpinInPlaceMatchesRk8pd) {
    // sdot0 = 0 and lambda_c = 0: k = 0, the body pivots about P at v_T/b
    DerivedSystem sys{1.0, 0.5, 1.0};
    VakonomicInitial init{0, 0, 0.2, 0, 0.7, -0.5 * 0.7};
    VakonomicMotion vak(sys, init);
    ASSERT_EQ(vak.kind(), VakonomicMotion::Case::Libration);
    EXPECT_EQ(vak.modulus(), 0.0);
    EXPECT_LE(checkAgainstReference(sys, init, 30, 1e-12), 1e-12);
}

TEST(VakonomicMotion, RotationBothWaysMatchesRk8pd) {
    DerivedSystem sys{1.0, 0.5, 1.0};
    for (double lambda : {2.0, -2.5}) {
        VakonomicInitial init{0.3, -0.2, 0.4, 0.6, 0.9, lambda};
        ASSERT_EQ(VakonomicMotion(sys, init).kind(), VakonomicMotion::Case::Rotation);
        EXPECT_LE(checkAgainstReference(sys, init, 40, 1e-9), 1e-9) << "lambda = " << lambda;
    }
    // fast rotation (k = 30): Psi turns over many times, phi stays within asin(1/k)
    VakonomicInitial init{0, 0, 0, -0.3, 0.5, 17.0};
    VakonomicMotion vak(sys, init);
    ASSERT_EQ(vak.kind(), VakonomicMotion::Case::Rotation);
    EXPECT_GT(vak.modulus(), 20);
    EXPECT_LE(checkAgainstReference(sys, init, 20, 1e-9), 1e-9);
}

TEST(VakonomicMotion, SeparatrixMatchesRk8pd) {
    // sin Psi0 = 0.6, b Psidot0/v_T = 0.8: k^2 = 1 exactly; Psi creeps to pi/2
    DerivedSystem sys{1.0, 0.0, 1.0};
    for (double sign : {1.0, -1.0}) {
        VakonomicInitial init{0, 0, 0, 0.6, 0.8 * sign, 0.8 * sign};
        VakonomicMotion vak(sys, init);
        ASSERT_EQ(vak.kind(), VakonomicMotion::Case::Separatrix);
        // the saddle amplifies rounding like e^{omega t}: a short horizon
        EXPECT_LE(checkAgainstReference(sys, init, 12, 1e-9), 1e-9);
        EXPECT_NEAR(vak.at(40).sdot, 1.0, 1e-12); // mirror images: both run straight ahead
    }
}

TEST(VakonomicMotion, StraightLineIsAnEquilibrium) {
    DerivedSystem sys{1.0, 0.5, 1.0};
    VakonomicInitial init{1, 2, 0.3, 0.8, 0, 0};
    VakonomicMotion vak(sys, init);
    ASSERT_EQ(vak.kind(), VakonomicMotion::Case::Line);
    VakonomicState s = vak.at(5);
    EXPECT_NEAR(s.x, 1 + 4 * std::cos(0.3), 1e-14);
    EXPECT_NEAR(s.y, 2 + 4 * std::sin(0.3), 1e-14);
    EXPECT_NEAR(s.psi, std::numbers::pi / 2, 1e-15);
    EXPECT_EQ(s.lambda, 0.0);
    EXPECT_LE(checkAgainstReference(sys, init, 10, 1e-14), 1e-14);
}

TEST(VakonomicMotion, RestStaysAtRest) {
    DerivedSystem sys{1.0, 0.5, 1.0};
    VakonomicState s = VakonomicMotion(sys, {1, 2, 0.3, 0, 0, 0.4}).at(3);
    EXPECT_EQ(s.x, 1.0);
    EXPECT_EQ(s.y, 2.0);
    EXPECT_EQ(s.phi, 0.3);
    EXPECT_EQ(s.energy, 0.0);
    EXPECT_EQ(s.lambda, 0.4); // lambda_c_dot = -m sdot phidot = 0
}

namespace {

// the Solution's vakonomic body against rk8pd from the tracking's state and lambda(0)
void checkSolution(const Scene& scene, double tol) {
    Solution sol = Solution::compute(scene);
    MotionSample s0 = sol.at(0);
    VakonomicInitial init{
        s0.x, s0.y, s0.phi, s0.control.sdot, s0.control.phidot, s0.control.lambda};
    // lambda(0) reproduced to rounding of m b Psidot - m a phidot
    EXPECT_NEAR(s0.vak.lambda, s0.control.lambda, 1e-13 * sol.system().mass * s0.control.vT);
    std::vector<double> times = evenTimes(sol.tEnd());
    std::vector<Reference> ref = reference(sol.system(), init, times);
    double worst = 0;
    for (std::size_t i = 0; i < times.size(); ++i) {
        VakonomicState v = sol.at(times[i]).vak;
        const Reference& r = ref[i];
        for (double e : {v.x - r.x, v.y - r.y, v.phi - r.phi, v.sdot - r.sdot, v.phidot - r.phidot,
                         v.lambda - r.lambda})
            worst = std::max(worst, std::fabs(e));
        EXPECT_NEAR(v.x, r.x, tol) << "t = " << times[i];
        EXPECT_NEAR(v.y, r.y, tol) << "t = " << times[i];
        EXPECT_NEAR(v.phi, r.phi, tol) << "t = " << times[i];
        EXPECT_NEAR(v.sdot, r.sdot, tol) << "t = " << times[i];
        EXPECT_NEAR(v.phidot, r.phidot, tol) << "t = " << times[i];
        EXPECT_NEAR(v.lambda, r.lambda, tol) << "t = " << times[i];
        EXPECT_NEAR(v.energy, s0.control.energy, 1e-12 * s0.control.energy);
    }
    ::testing::Test::RecordProperty("worst_deviation", std::to_string(worst));
    std::printf("worst deviation from rk8pd over [0, %g]: %.3g\n", sol.tEnd(), worst);
}

} // namespace

TEST(VakonomicMotion, SolutionOnTheCircleMatchesRk8pdAndLeavesIt) {
    Scene scene = presetScene("circle");
    checkSolution(scene, 1e-8);
    Solution sol = Solution::compute(scene);
    // lambda_c(0) = 0 on the circle, yet (21) drives it away: off the circle within a few seconds
    double off = 0;
    for (double t = 0; t <= 3; t += 0.1) {
        VakonomicState v = sol.at(t).vak;
        off = std::max(off, std::fabs(std::hypot(v.x, v.y) - 2));
    }
    EXPECT_GT(off, 0.1);
    EXPECT_NE(sol.models().vakonomic.find("libration"), std::string::npos);
}

TEST(VakonomicMotion, SolutionOnAParabolaMatchesRk8pd) {
    Scene scene = presetScene("line");
    scene.preset.clear();
    scene.path.kind = PathKind::Graph;
    scene.path.y = "0.3*x^2";
    scene.path.from = -2;
    scene.path.to = 3;
    checkSolution(scene, 1e-8);
}

TEST(VakonomicMotion, SolutionForTheDiskAndTheCarriageMatchesRk8pd) {
    for (SystemKind kind : {SystemKind::Disk, SystemKind::Carriage}) {
        Scene scene = presetScene("sinusoid");
        scene.system.kind = kind;
        scene.system.params = defaultSystemParams(kind);
        checkSolution(scene, 1e-8);
    }
}

TEST(VakonomicMotion, CircleAgreesWithAnMpmathTaylorReference) {
    // mpmath.odefun (Taylor series, 30 digits) of (19) corrected, (20), (21) from the circle
    // R = 2 (m = 1, a = 0.5, b = 1, v_T = 1): (x, y, phi, sdot, phidot, lambda) at t = 1, 2, 3, 5
    const double ref[4][7] = {{1, 1.8033883089176463, 0.82820446590019877, 2.0772100047608542,
                               0.78216732319747718, 0.62306843807249078, -0.7453709147203395},
                              {2, 1.4107865665211125, 1.2010854905009278, 2.8866206158319359,
                               0.22559095075668825, 0.97422211170589505, -1.3526217276165564},
                              {3, 1.5832661726533946, 1.3079961075165383, 3.83608999376306,
                               -0.57243276621692034, 0.81995166208822617, -1.0972317718414587},
                              {5, 1.952883231159542, 2.8393874329488581, 4.9363759935369996,
                               -0.87208405157006599, 0.48935611470292112, -0.046008968167615734}};
    Solution sol = Solution::compute(presetScene("circle"));
    for (const auto& r : ref) {
        VakonomicState v = sol.vakonomicAt(r[0]);
        const double got[6] = {v.x, v.y, v.phi, v.sdot, v.phidot, v.lambda};
        for (int i = 0; i < 6; ++i)
            EXPECT_NEAR(got[i], r[i + 1], 1e-13) << "t = " << r[0] << ", column " << i;
    }
    // sdot changes sign between t = 2 and 3: the vakonomic body backs up
    EXPECT_LT(sol.vakonomicAt(3).sdot, 0);
}

TEST(VakonomicMotion, ModulusNextToOneStaysFinite) {
    // k^2 one ulp from 1 on either side: sqrt(1 + 2^-52) rounds to 1, yet K(1/k) must stay finite
    DerivedSystem sys{1.0, 0.0, 1.0};
    for (double k2 : {1 - 0x1p-53, 1 + 0x1p-52}) {
        // sin Psi0 = 0.6, (b Psidot0/v_T)^2 = k2 - 0.36, v_T = 1
        const double L0 = std::sqrt(k2 - 0.36);
        VakonomicMotion vak(sys, {0, 0, 0, 0.6, 0.8, L0});
        EXPECT_NE(vak.kind(), VakonomicMotion::Case::Line);
        for (double t : {0.0, 1.0, 7.5}) {
            VakonomicState s = vak.at(t);
            for (double v : {s.x, s.y, s.phi, s.sdot, s.phidot, s.lambda, s.psi})
                EXPECT_TRUE(std::isfinite(v)) << "k^2 - 1 = " << k2 - 1 << ", t = " << t;
        }
    }
}
