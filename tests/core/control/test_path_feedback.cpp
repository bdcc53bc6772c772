// The chained form of the path error (docs/physics.md §9) at states where it is known in closed
// form, and its z4' = F + G kappa_b' against a difference quotient along an exact motion.
#include "control/path_feedback.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace chaplygin;

TEST(PathFeedback, OnThePathTheFeedforwardIsThePathsCurvatureRate) {
    PathError err;
    err.kappa = 0.7;
    err.kappaBody = 0.7;
    err.dkappa = -0.3;
    err.ddkappa = 2.0;
    const ChainedForm z = chainedForm(err);
    EXPECT_EQ(z.z2, 0);
    EXPECT_EQ(z.z3, 0);
    EXPECT_NEAR(z.z4, 0, 1e-16);
    EXPECT_EQ(triplePoleInput(z, 1.5), 0);
    EXPECT_NEAR(curvatureRate(z, 0), -0.3, 1e-16);
}

TEST(PathFeedback, OnALineTheChainedFormIsTheCurvatureOfTheBody) {
    PathError err;
    err.e = 0.2;
    err.theta = 0.3;
    err.kappaBody = 0.4;
    const ChainedForm z = chainedForm(err);
    const double sec = 1 / std::cos(0.3);
    EXPECT_NEAR(z.z3, std::tan(0.3), 1e-16);
    EXPECT_NEAR(z.z4, 0.4 * sec * sec * sec, 1e-15);
    EXPECT_NEAR(z.gain, sec * sec * sec, 1e-15);
    EXPECT_NEAR(z.drift, 3 * 0.16 * std::pow(sec, 4) * std::tan(0.3), 1e-15);
    const double p = 2;
    EXPECT_NEAR(triplePoleInput(z, p), -p * p * p * 0.2 - 3 * p * p * z.z3 - 3 * p * z.z4, 1e-15);
}

TEST(PathFeedback, AnOffsetOnACircleHasTheCurvatureDeficitAsZ4) {
    PathError err;
    err.e = 0.3;
    err.kappa = 0.5;
    err.kappaBody = 0.5;
    EXPECT_NEAR(chainedForm(err).z4, -0.25 * 0.3 * (1 - 0.15), 1e-16);
}

TEST(PathFeedback, PsidotRealisesTheCurvatureRate) {
    // kappa_b = cot(Psi)/b: d kappa_b/dt = -Psidot/(b sin^2 Psi)
    const double b = 0.8, psi = 1.1, kb = 1 / (std::tan(psi) * b), sdotPath = 0.9, rate = 0.37;
    const double psidot = psiRateForCurvatureRate(b, kb, sdotPath, rate);
    EXPECT_NEAR(-psidot / (b * std::sin(psi) * std::sin(psi)), sdotPath * rate, 1e-15);
}

// a body on the circle of radius 1.3 about (0.4, 0) beside the path x^2 + y^2 = 4 (kappa = 0.5):
// kappa_b is constant, so z4' along the motion is F; the difference quotient of z4 in s_p
TEST(PathFeedback, Z4PrimeIsTheDriftAlongAnExactMotion) {
    const double rb = 1.3, cx = 0.4;
    const auto at = [&](double alpha, double* sp) {
        const double x = cx + rb * std::cos(alpha), y = rb * std::sin(alpha);
        const double beta = std::atan2(y, x);
        *sp = 2 * beta;
        PathError err;
        err.e = 2 - std::hypot(x, y);
        err.theta = alpha - beta;
        err.kappaBody = 1 / rb;
        err.kappa = 0.5;
        return chainedForm(err);
    };
    for (double alpha : {0.3, 1.2, 2.5}) {
        const double h = 1e-3;
        double s[5];
        double z4[5];
        for (int i = 0; i < 5; ++i)
            z4[i] = at(alpha + (i - 2) * h, &s[i]).z4;
        // fourth-order differences in alpha, divided by ds_p/dalpha
        const double dz = (z4[0] - 8 * z4[1] + 8 * z4[3] - z4[4]) / (12 * h);
        const double ds = (s[0] - 8 * s[1] + 8 * s[3] - s[4]) / (12 * h);
        double unused;
        EXPECT_NEAR(dz / ds, at(alpha, &unused).drift, 1e-9) << alpha;
    }
}
