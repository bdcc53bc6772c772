#include "lab/sleigh_problems.h"
#include "numerics/fixed_step.h"
#include "numerics/gsl_ode.h"
#include "numerics_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace chaplygin {
namespace {

using test::evenTimes;
using test::maxDistance;
using test::methodNamed;

// observed order from errors at step counts n and 2n
double observedOrder(double coarse, double fine) {
    return std::log2(coarse / fine);
}

TEST(NumericsConvergence, ClassicalRk4IsFourthOrderOnCatenaryTimeLaw) {
    MethodCase c(presetScene("catenary"));
    const std::vector<double> times = evenTimes(c.controlledEnd);
    const MethodOutput ref = test::controlledReference(c, times);
    const std::vector<Method> methods = methodRegistry(c);
    const Method& rk4 = methodNamed(methods, MotionProblem::Controlled, "rk4_classical");
    double e1 = maxDistance(rk4.solve(c, c.controlledEnd / 64, times), ref);
    double e2 = maxDistance(rk4.solve(c, c.controlledEnd / 128, times), ref);
    EXPECT_NEAR(observedOrder(e1, e2), 4.0, 0.3) << e1 << " " << e2;
    // and it reaches the exact reference's accuracy
    EXPECT_LE(maxDistance(rk4.solve(c, c.controlledEnd / 4096, times), ref), 1e-12);
}

TEST(NumericsConvergence, ClassicalRk4IsFourthOrderOnFreeSleigh) {
    MethodCase c(test::sceneWith("catenary", 5));
    c.freeEnd = 10; // the free motion runs past the path's end
    const std::vector<double> times = evenTimes(c.freeEnd);
    const std::vector<Method> methods = methodRegistry(c);
    const MethodOutput ref =
        methodNamed(methods, MotionProblem::Free, "closed_form").solve(c, 0, times);
    const Method& rk4 = methodNamed(methods, MotionProblem::Free, "rk4_classical");
    double e1 = maxDistance(rk4.solve(c, c.freeEnd / 128, times), ref);
    double e2 = maxDistance(rk4.solve(c, c.freeEnd / 256, times), ref);
    EXPECT_NEAR(observedOrder(e1, e2), 4.0, 0.3) << e1 << " " << e2;
    EXPECT_LE(maxDistance(rk4.solve(c, c.freeEnd / 8192, times), ref), 1e-12);
}

TEST(NumericsConvergence, EnergyProjectionKeepsFourthOrderAndTheEnergyLevel) {
    MethodCase c(presetScene("catenary"));
    c.freeEnd = 10;
    // output at the step nodes (65 times, h = t_end/64), where the projection acts
    const std::vector<double> times = evenTimes(c.freeEnd, 65);
    const std::vector<Method> methods = methodRegistry(c);
    const MethodOutput ref =
        methodNamed(methods, MotionProblem::Free, "closed_form").solve(c, 0, times);
    const Method& proj = methodNamed(methods, MotionProblem::Free, "rk4_energy_projection");
    const Method& plain = methodNamed(methods, MotionProblem::Free, "rk4_classical");
    MethodOutput p1 = proj.solve(c, c.freeEnd / 64, times),
                 p2 = proj.solve(c, c.freeEnd / 128, times);
    EXPECT_NEAR(observedOrder(maxDistance(p1, ref), maxDistance(p2, ref)), 4.0, 0.3);
    // the projected method keeps T to rounding; plain RK4 drifts at its truncation error
    EXPECT_LE(p1.energyDrift, 1e-14);
    EXPECT_GT(plain.solve(c, c.freeEnd / 64, times).energyDrift, 1e3 * p1.energyDrift + 1e-13);
}

struct OrderCase {
    GslStepper stepper;
    double order;
    long steps; // n; the test compares n and 2n steps over [0, 10]
};

class GslFixedStepOrder : public ::testing::TestWithParam<OrderCase> {};

TEST_P(GslFixedStepOrder, FreeSleighConvergesAtTheStepperOrder) {
    const OrderCase oc = GetParam();
    Scene scene = presetScene("catenary");
    MethodCase c(scene);
    FreeMotion exact(c.params.system, c.freeInitial, 10);
    FreeState end = exact.at(10);
    FreeProblem prob(c.params.system);
    auto error = [&](long n) {
        double y[5] = {c.freeInitial.x, c.freeInitial.y, c.freeInitial.phi, c.freeInitial.sdot,
                       c.freeInitial.phidot};
        integrateGslFixed(prob, oc.stepper, 0, y, 10, n);
        return std::hypot(y[0] - end.x, y[1] - end.y);
    };
    double e1 = error(oc.steps), e2 = error(2 * oc.steps);
    EXPECT_NEAR(observedOrder(e1, e2), oc.order, 0.4)
        << gslStepperName(oc.stepper) << " " << e1 << " " << e2;
}

INSTANTIATE_TEST_SUITE_P(Steppers, GslFixedStepOrder,
                         ::testing::Values(OrderCase{GslStepper::Rk4, 4, 40},
                                           OrderCase{GslStepper::Rkf45, 5, 40},
                                           OrderCase{GslStepper::Rkck, 5, 40},
                                           OrderCase{GslStepper::Rk8pd, 8, 10}),
                         [](const auto& info) { return gslStepperName(info.param.stepper); });

class AdaptiveConvergence : public ::testing::TestWithParam<std::string> {};

// every adaptive method follows its tolerance on both problems: at 1e-13 the position error
// against the exact reference is below 1e-9, and it is 100x below the error at 1e-7
TEST_P(AdaptiveConvergence, ErrorFollowsTheToleranceOnBothProblems) {
    MethodCase c(presetScene("catenary"));
    c.freeEnd = 10;
    const std::vector<Method> methods = methodRegistry(c);
    const std::vector<double> tc = evenTimes(c.controlledEnd), tf = evenTimes(c.freeEnd);
    const MethodOutput refC = test::controlledReference(c, tc);
    const MethodOutput refF =
        methodNamed(methods, MotionProblem::Free, "closed_form").solve(c, 0, tf);
    for (MotionProblem problem : {MotionProblem::Controlled, MotionProblem::Free}) {
        const bool controlled = problem == MotionProblem::Controlled;
        const Method& m = methodNamed(methods, problem, GetParam());
        const auto& times = controlled ? tc : tf;
        const MethodOutput& ref = controlled ? refC : refF;
        double loose = maxDistance(m.solve(c, 1e-7, times), ref);
        double tight = maxDistance(m.solve(c, 1e-13, times), ref);
        EXPECT_LE(tight, 1e-9) << motionProblemName(problem);
        EXPECT_LE(tight, loose / 100) << motionProblemName(problem);
    }
}

INSTANTIATE_TEST_SUITE_P(Steppers, AdaptiveConvergence,
                         ::testing::Values("gsl_rk4", "gsl_rkf45", "gsl_rkck", "gsl_rk8pd",
                                           "gsl_msadams", "gsl_msbdf"),
                         [](const auto& info) { return info.param; });

TEST(NumericsConvergence, AppTimeLawMatchesTheIndependentQuadrature) {
    MethodCase c(presetScene("catenary"));
    const std::vector<double> times = evenTimes(c.controlledEnd);
    const std::vector<Method> methods = methodRegistry(c);
    const Method& app = methodNamed(methods, MotionProblem::Controlled, "quadrature_gauss_newton");
    EXPECT_TRUE(app.appDefault);
    EXPECT_LE(maxDistance(app.solve(c, 0, times), test::controlledReference(c, times)), 1e-13);
}

TEST(NumericsConvergence, QagNewtonMatchesTheSixtyOnePointReference) {
    MethodCase c(presetScene("catenary"));
    const std::vector<double> times = evenTimes(c.controlledEnd);
    const std::vector<Method> methods = methodRegistry(c);
    const Method& qag = methodNamed(methods, MotionProblem::Controlled, "gsl_qag_newton");
    // 21-point against 61-point Gauss-Kronrod: both at rounding on a smooth path
    EXPECT_LE(maxDistance(qag.solve(c, 1e-8, times), test::controlledReference(c, times)), 1e-13);
}

TEST(NumericsConvergence, ClosedFormTimeLawOnTheCircleMatchesTheOde) {
    MethodCase c(presetScene("circle"));
    const std::vector<double> times = evenTimes(c.controlledEnd);
    const std::vector<Method> methods = methodRegistry(c);
    const Method& app = methodNamed(methods, MotionProblem::Controlled, "closed_form");
    const Method& rk8 = methodNamed(methods, MotionProblem::Controlled, "gsl_rk8pd");
    EXPECT_LE(maxDistance(app.solve(c, 0, times), rk8.solve(c, 1e-13, times)), 1e-11);
}

} // namespace
} // namespace chaplygin
