// integrateGslSteps and gslStepFrom: a value between the accepted steps of a free rk8pd run by one
// step of the method, against the closed form of a harmonic oscillator.
#include "numerics/gsl_ode.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace chaplygin;

namespace {

// y'' = -w^2 y as (y, y'), without a Jacobian
class Oscillator final : public OdeProblem {
  public:
    int dimension() const override { return 2; }
    void rhs(double, const double* y, double* f) const override {
        f[0] = y[1];
        f[1] = -4 * y[0];
    }
    void jacobian(double, const double*, double*, double*) const override {
        throw std::logic_error("no Jacobian");
    }
};

} // namespace

TEST(GslSteps, ValuesBetweenStepsHaveTheMethodsAccuracy) {
    const Oscillator o;
    const double y0[2] = {1, 0};
    int seen = 0;
    const GslSteps steps = integrateGslSteps(o, GslStepper::Rk8pd, 0, y0, 20, 1e-12,
                                             [&](double, const double*) { ++seen; });
    EXPECT_EQ(seen, static_cast<int>(steps.t.size()));
    EXPECT_EQ(steps.t.back(), 20);
    EXPECT_GT(steps.t.size(), 20u);
    for (double t : {0.0, 0.37, 7.1, 13.333, 19.99, 20.0}) {
        double y[2];
        gslStepFrom(o, GslStepper::Rk8pd, steps, t, y);
        EXPECT_NEAR(y[0], std::cos(2 * t), 1e-10) << t;
        EXPECT_NEAR(y[1], -2 * std::sin(2 * t), 2e-10) << t;
    }
}

TEST(GslSteps, TheAcceptedCallbackMayStopTheRun) {
    const Oscillator o;
    const double y0[2] = {1, 0};
    EXPECT_THROW(integrateGslSteps(o, GslStepper::Rk8pd, 0, y0, 20, 1e-12,
                                   [](double t, const double*) {
                                       if (t > 3)
                                           throw std::domain_error("stop");
                                   }),
                 std::domain_error);
}
