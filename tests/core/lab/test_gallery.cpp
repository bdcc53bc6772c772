// The gallery (docs/numerics.md §4, core-only cases): where methods fail, each failure detected.
#include "lab/sleigh_problems.h"
#include "lab/vakonomic_problem.h"
#include "numerics/fixed_step.h"
#include "numerics/gsl_ode.h"
#include "numerics_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace chaplygin {
namespace {

using test::evenTimes;

// distance of the body from the graph y = -sin x, measured vertically
double offSinusoid(double x, double y) {
    return std::fabs(y + std::sin(x));
}

TEST(Gallery, OpenLoopIntegrationDriftsOffTheSinusoid) {
    MethodCase c(presetScene("sinusoid"));
    const std::vector<double> times = evenTimes(c.controlledEnd);
    const long steps = 100;
    // the open loop of paper (35)-(37), against the ODE for the path parameter, same RK4 step
    OpenLoopProblem open(*c.plan);
    PlannedMotion::State s0 = c.plan->at(0);
    double y[3] = {s0.x, s0.y, s0.phi};
    FixedStepSolve o = integrateRk4(open, 0, y, c.controlledEnd, steps);
    ControlledProblem along(*c.curve, c.params);
    double u0 = c.curve->u0();
    FixedStepSolve a = integrateRk4(along, 0, &u0, c.controlledEnd, steps);
    double openOff = 0, alongOff = 0;
    for (double t : times) {
        double v[3], u;
        o.dense.at(t, v);
        openOff = std::max(openOff, offSinusoid(v[0], v[1]));
        a.dense.at(t, &u);
        CurvePoint p = c.curve->eval(u);
        alongOff = std::max(alongOff, offSinusoid(p.x, p.y));
    }
    EXPECT_GT(openOff, 1e-6);   // the open loop leaves the path (drift detected)
    EXPECT_LE(alongOff, 1e-12); // integrating along the path stays on it by construction
}

TEST(Gallery, OpenLoopNeverRecoversFromAHeadingError) {
    MethodCase c(presetScene("sinusoid"));
    OpenLoopProblem open(*c.plan);
    PlannedMotion::State s0 = c.plan->at(0);
    const double dphi = 1e-3;
    double y[3] = {s0.x, s0.y, s0.phi + dphi};
    GslSolve s = integrateGsl(open, GslStepper::Rk8pd, 0, y, c.controlledEnd, 1e-12);
    double v[3];
    s.dense.at(c.controlledEnd, v);
    // the heading error decays (sin Psi > 0 damps it through paper (33)) but the offset it caused
    // stays: nothing in (36)-(37) pulls P back to the path
    EXPECT_LT(std::fabs(v[2] - c.plan->at(c.controlledEnd).phi), dphi / 100);
    EXPECT_GT(offSinusoid(v[0], v[1]), dphi);
}

// y = -A sin(x/A) over two periods, b = 1: b kappa_max = 1/A
MethodCase sharpSinusoid(double amplitude) {
    Scene s = presetScene("sinusoid");
    char y[96];
    std::snprintf(y, sizeof y, "-%.17g*sin(x/%.17g)", amplitude, amplitude);
    s.path.y = y;
    s.path.to = 4 * 3.141592653589793 * amplitude;
    return MethodCase(s);
}

// the smallest accepted step (the last, cut short at t_end, left out)
double smallestStep(const GslSolve& r) {
    double h = INFINITY;
    for (std::size_t k = 1; k + 1 < r.dense.size(); ++k)
        h = std::min(h, r.dense.time(k) - r.dense.time(k - 1));
    return h;
}

TEST(Gallery, HighCurvatureMakesExplicitSteppersTakeTinySteps) {
    double hmin[2] = {};
    int i = 0;
    for (double amplitude : {1.0, 1e-3}) {
        MethodCase c = sharpSinusoid(amplitude);
        ControlledProblem prob(*c.curve, c.params);
        double u0 = c.curve->u0();
        GslSolve r = integrateGsl(prob, GslStepper::Rkf45, 0, &u0, c.controlledEnd, 1e-9);
        hmin[i++] = smallestStep(r);
        // the explicit stepper still gets it right (against the independent quadrature)
        const std::vector<double> times = evenTimes(c.controlledEnd);
        GslSolve r8 = integrateGsl(prob, GslStepper::Rk8pd, 0, &u0, c.controlledEnd, 1e-13);
        std::vector<OdeValue> u = gslValuesAt(prob, GslStepper::Rk8pd, r8, times);
        MethodOutput ode;
        for (const OdeValue& v : u) {
            CurvePoint p = c.curve->eval(v[0]);
            ode.x.push_back(p.x);
            ode.y.push_back(p.y);
        }
        EXPECT_LE(test::maxDistance(ode, test::controlledReference(c, times)), 1e-9) << amplitude;
    }
    // near the inflections sdot = v_T but the heading turns at a rate set by b kappa: the
    // smallest step shrinks like 1/(b kappa_max)^2 (measured: 0.096 s against 4.1e-6 s)
    EXPECT_LT(hmin[1], 1e-3 * hmin[0]) << hmin[0] << " " << hmin[1];
}

// the app's time law at b kappa = 1000: sqrt(1 + b^2 kappa^2) has a near-kink of width 1/b in
// kappa at every inflection, which the path table must resolve (it once did not: 5.2e-7)
TEST(Gallery, AppTimeLawStaysExactAtHighCurvature) {
    MethodCase c = sharpSinusoid(1e-3);
    const std::vector<double> times = evenTimes(c.controlledEnd);
    const std::vector<Method> methods = methodRegistry(c);
    const Method& app =
        test::methodNamed(methods, MotionProblem::Controlled, "quadrature_gauss_newton");
    EXPECT_LE(test::maxDistance(app.solve(c, 0, times), test::controlledReference(c, times)), 1e-9);
}

TEST(Gallery, LongHorizonFreeMotionStaysFiniteAndNormal) {
    MethodCase c(presetScene("catenary"));
    const double horizon = 5000;
    FreeMotion exact(c.params.system, c.freeInitial, horizon);
    for (double t : evenTimes(horizon)) {
        FreeState s = exact.at(t);
        for (double v : {s.x, s.y, s.phi, s.sdot, s.phidot, s.energy})
            ASSERT_TRUE(std::isfinite(v)) << "closed form at t = " << t;
    }
    FreeProblem prob(c.params.system);
    double y[5] = {c.freeInitial.x, c.freeInitial.y, c.freeInitial.phi, c.freeInitial.sdot,
                   c.freeInitial.phidot};
    GslSolve r = integrateGsl(prob, GslStepper::Rkf45, 0, y, horizon, 1e-10);
    // finite cost: after the sech transient the steps grow, the whole run is a few thousand steps
    EXPECT_LT(r.work.steps, 5000);
    // no NaN and no subnormal number anywhere (phidot ~ sech is flushed below 1e-150)
    for (std::size_t k = 0; k < r.dense.size(); ++k)
        for (int i = 0; i < 5; ++i) {
            double v = r.dense.state(k)[i];
            ASSERT_TRUE(std::isfinite(v));
            ASSERT_NE(std::fpclassify(v), FP_SUBNORMAL) << "t = " << r.dense.time(k);
        }
    double v[5];
    r.dense.at(horizon, v);
    FreeState end = exact.at(horizon);
    EXPECT_LE(std::hypot(v[0] - end.x, v[1] - end.y), 1e-6 * horizon);
}

TEST(Gallery, GenuineVakonomicSystemLeavesTheCircle) {
    MethodCase c(presetScene("circle"));
    const double radius = 2.0, horizon = 5.0;
    // the genuine vakonomic system from the tracked circle's state: lambda_c = lambda + m a phidot
    // = 0
    VakonomicProblem vak(c.params.system);
    double y[6] = {c.freeInitial.x,    c.freeInitial.y,      c.freeInitial.phi,
                   c.freeInitial.sdot, c.freeInitial.phidot, 0};
    GslSolve r = integrateGsl(vak, GslStepper::Rk8pd, 0, y, horizon, 1e-12);
    const std::vector<Method> methods = methodRegistry(c);
    const std::vector<double> times = evenTimes(horizon);
    MethodOutput tracked =
        test::methodNamed(methods, MotionProblem::Controlled, "closed_form").solve(c, 0, times);
    MethodCase freeCase(c);
    freeCase.freeEnd = horizon;
    MethodOutput free =
        test::methodNamed(methods, MotionProblem::Free, "closed_form").solve(freeCase, 0, times);
    double vakOff = 0, trackedOff = 0, freeOff = 0;
    for (std::size_t i = 0; i < times.size(); ++i) {
        double v[6];
        r.dense.at(times[i], v);
        vakOff = std::max(vakOff, std::fabs(std::hypot(v[0], v[1]) - radius));
        trackedOff =
            std::max(trackedOff, std::fabs(std::hypot(tracked.x[i], tracked.y[i]) - radius));
        freeOff = std::max(freeOff, std::fabs(std::hypot(free.x[i], free.y[i]) - radius));
    }
    EXPECT_GT(vakOff, 0.1); // paper (21) forces lambda_c away from 0: the body leaves the circle
    EXPECT_LE(trackedOff, 1e-12); // the control-input system (lambda a free input) stays on it
    EXPECT_GT(freeOff, 0.1);      // and so does the free motion, which has no control at all
}

} // namespace
} // namespace chaplygin
