#include "numerics/safeguarded_newton.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace chaplygin {
namespace {

// the Dottie number, the root of cos x - x, to 66 digits
constexpr double kDottie = 0.739085133215160641655312087673873404013411758900757464965680635773;
// 2^(1/3), the real root of x^3 - 2
constexpr double kCubeRootOfTwo = 1.25992104989487316476721060727822835057025146470150798008;

constexpr NewtonCaps kTight{.maxIterations = 60,
                            .newtonStep = {.value = 1e-15, .relativeToX = true, .scale = 1}};

// x - cos x: cos x - x with its sign turned, so that it increases through the root
NewtonValue xMinusCos(double x) {
    return {x - std::cos(x), 1 + std::sin(x)};
}

TEST(SafeguardedNewton, FindsTheDottieNumber) {
    const NewtonResult r = safeguardedNewton(xMinusCos, 0.5, {0, 1}, kTight);
    EXPECT_EQ(r.end, NewtonEnd::NewtonStep);
    EXPECT_NEAR(r.x, kDottie, 1e-15);
    EXPECT_LE(r.evaluations, 6); // quadratic convergence from 0.5
}

// x^3 - 2 on [0.1, 2] from 0.1: f' = 0.03 there, so the plain Newton step lands near 66.7
TEST(SafeguardedNewton, BisectsWhereNewtonWouldLeaveTheBracket) {
    const double x0 = 0.1;
    ASSERT_GT(x0 - (x0 * x0 * x0 - 2) / (3 * x0 * x0), 60.0);
    std::vector<double> at;
    auto cubic = [&](double x) {
        at.push_back(x);
        return NewtonValue{x * x * x - 2, 3 * x * x};
    };
    const NewtonResult r = safeguardedNewton(cubic, x0, {0.1, 2}, kTight);
    EXPECT_EQ(r.end, NewtonEnd::NewtonStep);
    EXPECT_NEAR(r.x, kCubeRootOfTwo, 1e-15);
    ASSERT_GE(at.size(), 2u);
    EXPECT_EQ(at[1], 0.5 * (0.1 + 2)); // the bracket's midpoint instead of the Newton point
    for (double x : at) {
        EXPECT_GE(x, 0.1);
        EXPECT_LE(x, 2.0);
    }
    EXPECT_EQ(r.evaluations, static_cast<int>(at.size()));
}

// two iterations of x - cos x from 0.5 stay inside [0, 1]: exactly the plain Newton iterates
TEST(SafeguardedNewton, StopsAtTheIterationCap) {
    const NewtonResult r =
        safeguardedNewton(xMinusCos, 0.5, {0, 1}, {.maxIterations = 2, .newtonStep = {.value = 0}});
    double x = 0.5;
    for (int i = 0; i < 2; ++i)
        x -= xMinusCos(x).f / xMinusCos(x).df;
    EXPECT_EQ(r.end, NewtonEnd::IterationCap);
    EXPECT_EQ(r.evaluations, 2);
    EXPECT_EQ(r.x, x);
    EXPECT_GT(std::fabs(r.x - kDottie), 1e-6);
}

// x - 1 on [0, 1]: the first Newton point is the bracket's end
TEST(SafeguardedNewton, FindsARootAtTheBracketsEnd) {
    auto line = [](double x) { return NewtonValue{x - 1, 1}; };
    // taken on a closed bracket: the next evaluation is at the root
    NewtonCaps closed = kTight;
    closed.closedBracket = true;
    const NewtonResult c = safeguardedNewton(line, 0.5, {0, 1}, closed);
    EXPECT_EQ(c.x, 1.0);
    EXPECT_EQ(c.evaluations, 2);
    // refused on an open one: bisection towards the end until the Newton step is small
    const NewtonResult o = safeguardedNewton(line, 0.5, {0, 1}, kTight);
    EXPECT_EQ(o.end, NewtonEnd::NewtonStep);
    EXPECT_EQ(o.x, 1.0);
    EXPECT_GT(o.evaluations, 40);
    // started on the root at the lower end
    auto square = [](double x) { return NewtonValue{x * x - 1, 2 * x}; };
    const NewtonResult s = safeguardedNewton(square, 1, {1, 3}, kTight);
    EXPECT_EQ(s.x, 1.0);
    EXPECT_EQ(s.evaluations, 1);
}

// without a step test the bracket's width ends the iteration (the cusp search's rule)
TEST(SafeguardedNewton, StopsWhenTheBracketIsSmall) {
    constexpr NewtonCaps caps{
        .maxIterations = 100,
        .bracket = {.value = 4 * std::numeric_limits<double>::epsilon(), .relativeToX = true}};
    double lo = 0.1, hi = 2;
    auto cubic = [&](double x) {
        const NewtonValue v{x * x * x - 2, 3 * x * x};
        (v.f > 0 ? hi : lo) = x;
        return v;
    };
    const NewtonResult r = safeguardedNewton(cubic, 0.1, {0.1, 2}, caps);
    EXPECT_TRUE(r.end == NewtonEnd::Bracket || r.end == NewtonEnd::Stalled);
    EXPECT_NEAR(r.x, kCubeRootOfTwo, 4 * std::numeric_limits<double>::epsilon() * kCubeRootOfTwo);
    EXPECT_LE(hi - lo, 4 * std::numeric_limits<double>::epsilon() * kCubeRootOfTwo * 1.01);
}

// the step actually taken, Newton or bisection, as the test (the quadrature time law's rule)
TEST(SafeguardedNewton, StopsOnASmallTakenStep) {
    constexpr NewtonCaps caps{.maxIterations = 100,
                              .takenStep = {.value = 1e-15, .relativeToX = true, .scale = 1},
                              .closedBracket = true};
    const NewtonResult r = safeguardedNewton(xMinusCos, 0.5, {0, 1}, caps);
    // a last Newton step below rounding leaves x where it was: a taken step of 0
    EXPECT_TRUE(r.end == NewtonEnd::TakenStep || r.end == NewtonEnd::Stalled);
    EXPECT_NEAR(r.x, kDottie, 1e-15);
}

// x^3 at 0: f = f' = 0, so the Newton step is 0/0; stopAtRoot takes the exact zero at once
TEST(SafeguardedNewton, AnExactZeroEndsTheIteration) {
    auto cube = [](double x) { return NewtonValue{x * x * x, 3 * x * x}; };
    const NewtonResult r =
        safeguardedNewton(cube, 0, {-1, 1}, {.maxIterations = 10, .stopAtRoot = true});
    EXPECT_EQ(r.end, NewtonEnd::Root);
    EXPECT_EQ(r.x, 0.0);
    EXPECT_EQ(r.evaluations, 1);
}

} // namespace
} // namespace chaplygin
