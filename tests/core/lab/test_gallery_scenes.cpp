// The gallery (resources/scenes/gallery): each scene's failure is detected (a refusal that names
// the place) or handled (the app's answer stays exact), and the paper's printed branch fails as
// described.
#include "common/input_error.h"
#include "control/printed_branch.h"
#include "gsl_quadrature.h"
#include "lab/gallery.h"
#include "scene/solution.h"

#include <gsl/gsl_errno.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

using namespace chaplygin;

TEST(GalleryScenes, EveryEntryIsExplainedAndBehavesAsDescribed) {
    ASSERT_GE(galleryEntries().size(), 8u);
    for (const GalleryEntry& e : galleryEntries()) {
        EXPECT_GT(e.scene.note.size(), 200u) << e.name;
        if (e.rejected) {
            try {
                Solution::compute(e.scene);
                ADD_FAILURE() << e.name << " was accepted";
            } catch (const InputError& err) {
                EXPECT_NE(std::string(err.what()).find(e.message), std::string::npos) << err.what();
            }
        } else {
            Solution s = Solution::compute(e.scene);
            MotionSample end = s.at(s.tEnd());
            EXPECT_TRUE(std::isfinite(end.x) && std::isfinite(end.free.x)) << e.name;
        }
    }
    EXPECT_THROW(galleryEntry("no-such-scene"), InputError);
}

TEST(GalleryScenes, PrintedBranchReversesAtTheInflectionOursDoesNot) {
    Solution s = Solution::compute(galleryEntry("printed-branch").scene);
    const double b = s.system().b, vT = s.scene().speed;
    int printedReversals = 0;
    double previousPrinted = NAN, largestJump = 0;
    for (double t = 0; t <= s.duration(); t += 0.01) {
        MotionSample m = s.at(t);
        double printed = printedBranchPsi(b, m.kappa);
        double sdotPrinted = vT * std::sin(printed);
        if (std::isfinite(previousPrinted)) {
            largestJump = std::max(largestJump, std::fabs(printed - previousPrinted));
            printedReversals += (sdotPrinted < 0) != (vT * std::sin(previousPrinted) < 0);
        }
        previousPrinted = printed;
        EXPECT_GT(m.control.sdot, 0); // ours never reverses
    }
    // y = -sin x on [0, 4 pi] turns right on (0, pi) and (2 pi, 3 pi): four sign changes of sdot
    EXPECT_GE(printedReversals, 3);
    EXPECT_GT(largestJump, 3.0); // a jump of about pi at the inflections
}

TEST(GalleryScenes, CornerPivotTakesBTimesTheTurn) {
    Solution s = Solution::compute(galleryEntry("corner-pivot").scene);
    // three sides of 2 m and two left quarter turns, b = 1, v_T = 1
    EXPECT_NEAR(s.duration(), 6 + 2 * (std::numbers::pi / 2), 1e-13);
}

TEST(GalleryScenes, HighCurvatureTimeLawStaysExact) {
    gsl_set_error_handler_off();
    Solution s = Solution::compute(galleryEntry("high-curvature").scene);
    const double A = 0.001, b = s.system().b;
    // y = -A sin(x/A): t = \int sqrt(1 + y'^2) sqrt(1 + b^2 kappa^2) dx
    auto rate = [A, b](double x) {
        double d1 = -std::cos(x / A), d2 = std::sin(x / A) / A;
        double g = 1 + d1 * d1, kappa = d2 / std::pow(g, 1.5);
        return std::sqrt(g) * std::sqrt(1 + b * b * kappa * kappa);
    };
    double end = 4 * std::numbers::pi * A;
    double sum = 0;
    for (int k = 0; k < 4; ++k) // one panel per half period: the integrand kinks at inflections
        sum += test::gslIntegral(rate, k * end / 4, (k + 1) * end / 4, 0, 1e-13,
                                 test::GslRule::Extrapolating, 2000);
    EXPECT_NEAR(s.duration(), sum, 1e-10 * sum);
}

TEST(GalleryScenes, LongHorizonStaysFiniteAndOnTheEnergyLevel) {
    Solution s = Solution::compute(galleryEntry("long-horizon").scene);
    EXPECT_NEAR(s.tEnd(), 5000, 0);
    for (double t : {0.0, 1000.0, 4999.0, 5000.0}) {
        MotionSample m = s.at(t);
        EXPECT_NEAR(std::hypot(m.x, m.y), 1, 1e-12) << t;
        EXPECT_NEAR(m.control.energy, 0.5, 1e-13);
        EXPECT_NEAR(m.free.energy, 0.5, 1e-13);
        EXPECT_TRUE(std::isfinite(m.free.x) && std::isfinite(m.free.y));
        EXPECT_NE(std::fpclassify(m.free.phidot), FP_SUBNORMAL);
    }
}

namespace {

// the distance from (x, y) to y = -sin x, by a scan and golden refinement near x
double distanceToSinusoid(double x, double y) {
    double best = 1e300, at = x;
    for (double u = x - 6; u <= x + 6; u += 1e-3) {
        const double d = std::hypot(x - u, y + std::sin(u));
        if (d < best) {
            best = d;
            at = u;
        }
    }
    double lo = at - 1e-3, hi = at + 1e-3;
    const auto d = [&](double u) { return std::hypot(x - u, y + std::sin(u)); };
    for (int i = 0; i < 100; ++i) {
        const double c = lo + (hi - lo) / 3, e = hi - (hi - lo) / 3;
        (d(c) < d(e) ? hi : lo) = d(c) < d(e) ? e : c;
    }
    return d(0.5 * (lo + hi));
}

} // namespace

// docs/physics.md §9: the push leaves the open loop's chi off by push_psi for ever, so it drifts;
// the feedback brings the body back
TEST(GalleryScenes, PushedOffThePathOpenLoopDriftsFeedbackReturns) {
    const Solution s = Solution::compute(galleryEntry("pushed-off-path").scene);
    const MotionSample end = s.at(s.tEnd());
    EXPECT_GT(distanceToSinusoid(end.pert.x, end.pert.y), 2.0);
    EXPECT_LT(std::fabs(end.fb.error), 1e-3);
    // before the end (beyond it the frame continues along the osculating line, not the sinusoid)
    const MotionSample before = s.at(0.9 * s.tEnd());
    EXPECT_NEAR(distanceToSinusoid(before.fb.x, before.fb.y), std::fabs(before.fb.error), 1e-9);
    EXPECT_NEAR(s.at(2.9).fb.error, 0, 1e-12); // nothing before the push at t = 3
}

// a controller b below the plant's scales the body's turning, the feedforward included: the error
// never settles on the sinusoid, while the right b corrects it
TEST(GalleryScenes, WrongControllerBNeverSettles) {
    Scene scene = galleryEntry("wrong-controller-b").scene;
    const Solution wrong = Solution::compute(scene);
    double late = 0;
    for (const MotionSample& m : wrong.sample(401))
        if (m.t > 0.75 * wrong.tEnd())
            late = std::max(late, std::fabs(m.fb.error));
    EXPECT_GT(late, 0.1);
    scene.perturbation->controllerB.reset();
    EXPECT_LT(std::fabs(Solution::compute(scene).at(wrong.tEnd()).fb.error), 1e-3);
}

// the |Psidot| bound makes the triple pole overshoot; a little more rate and it is lost
TEST(GalleryScenes, AggressiveFeedbackOvershootsAndAtP3IsLost) {
    Scene scene = galleryEntry("aggressive-feedback").scene;
    const Solution s = Solution::compute(scene);
    double lowest = 0;
    for (const MotionSample& m : s.sample(801))
        lowest = std::min(lowest, m.fb.error);
    EXPECT_LT(lowest, -0.15);
    EXPECT_LT(std::fabs(s.at(s.tEnd()).fb.error), 1e-6);
    scene.perturbation->feedbackRate = 3;
    try {
        Solution::compute(scene);
        ADD_FAILURE() << "P = 3 with |Psidot| <= 0.4 was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("leaves the chained form's domain"), std::string::npos)
            << e.what();
    }
}

// The pose-to-pose scenes (docs/physics.md §10): each tracks a planned motion's knife track, its
// controlled body ends on the target and moves as the genuine vakonomic body
TEST(GalleryScenes, ParkingScenesEndOnTheirTargets) {
    struct Case {
        const char* name;
        double x, y, phi, duration;
    };
    for (const Case& c : {Case{"park-sideways", 0, 1, 0, 3.340383019231},
                          Case{"pivot-by-pi", 0, 0, std::numbers::pi, std::numbers::pi},
                          Case{"past-cut-time", 2, 0, 0, 6.877058802592}}) {
        const Solution s = Solution::compute(galleryEntry(c.name).scene);
        EXPECT_NEAR(s.duration(), c.duration, 1e-11) << c.name;
        const MotionSample end = s.at(s.tEnd());
        const double error = std::fabs(end.x - c.x) + std::fabs(end.y - c.y) +
                             std::fabs(std::remainder(end.phi - c.phi, 2 * std::numbers::pi));
        EXPECT_LE(error, 1e-8) << c.name;
        for (double t = 0; t <= s.tEnd(); t += s.tEnd() / 50) {
            const MotionSample m = s.at(t);
            EXPECT_LE(std::fabs(m.x - m.vak.x) + std::fabs(m.y - m.vak.y) +
                          std::fabs(m.phi - m.vak.phi) + std::fabs(m.control.lambda - m.vak.lambda),
                      1e-8)
                << c.name << " t = " << t;
        }
        std::printf("%s: end error %.2e\n", c.name, error);
    }
}
