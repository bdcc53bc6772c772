// Solution::trackingErrors (docs/physics.md §9): the perturbed bodies' lateral and heading error
// against the closest path point, which the GUI's error plot draws.
#include "scene/presets.h"
#include "scene/solution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace chaplygin;

namespace {

// the line y = 0 for 20 m, both bodies started dy to the left with heading error dphi
Solution lineWithOffset(double dy, double dphi) {
    Scene s = presetScene("line");
    s.preset.clear();
    s.path.y = "0*x";
    s.path.to = 20;
    Perturbation p;
    p.dy = dy;
    p.dphi = dphi;
    s.perturbation = p;
    return Solution::compute(s);
}

std::vector<double> times(const Solution& s, int n) {
    std::vector<double> t;
    for (int i = 0; i < n; ++i)
        t.push_back(s.tEnd() * i / (n - 1));
    return t;
}

} // namespace

TEST(TrackingErrors, EmptyWithoutAPerturbation) {
    const Solution s = Solution::compute(presetScene("circle"));
    EXPECT_TRUE(s.trackingErrors({0, 1}).empty());
}

TEST(TrackingErrors, OnTheLineTheErrorIsYAndTheHeadingPhi) {
    const Solution s = lineWithOffset(0.2, 0.05);
    const std::vector<double> t = times(s, 101);
    const std::vector<TrackingError> errors = s.trackingErrors(t);
    ASSERT_EQ(errors.size(), t.size());
    EXPECT_NEAR(errors.front().openE, 0.2, 1e-12);
    EXPECT_NEAR(errors.front().openTheta, 0.05, 1e-12);
    for (const TrackingError& r : errors) {
        const MotionSample m = s.at(r.t);
        // the line y = 0: e is y and theta the heading itself
        EXPECT_NEAR(r.openE, m.pert.y, 1e-10);
        EXPECT_NEAR(r.openTheta, m.pert.phi, 1e-10);
        EXPECT_NEAR(r.fbE, m.fb.y, 1e-10);
        EXPECT_NEAR(r.fbTheta, m.fb.phi, 1e-10);
        // the feedback body's own error is the same projection
        EXPECT_NEAR(r.fbE, m.fb.error, 1e-9);
    }
    // the open loop's heading error persists (e grows), the feedback's decays
    EXPECT_GT(errors.back().openE, 0.2 + 0.5 * 0.05 * 10);
    EXPECT_LT(std::fabs(errors.back().fbE), 1e-3);
}

TEST(TrackingErrors, TheFeedbackBodysErrorOnTheCurvedGalleryScene) {
    Scene s = presetScene("circle");
    s.preset.clear();
    Perturbation p;
    p.tPush = 1;
    p.pushDy = 0.1;
    s.perturbation = p;
    const Solution sol = Solution::compute(s);
    const std::vector<double> t = times(sol, 201);
    for (const TrackingError& r : sol.trackingErrors(t)) {
        EXPECT_NEAR(r.fbE, sol.at(r.t).fb.error, 1e-9) << "t = " << r.t;
        ASSERT_TRUE(std::isfinite(r.openE) && std::isfinite(r.openTheta));
        if (r.t < 1) {
            EXPECT_NEAR(r.openE, 0, 1e-9);
            EXPECT_NEAR(r.fbTheta, 0, 1e-9);
        }
    }
}
