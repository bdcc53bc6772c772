#include "numerics/gsl_ode.h"

#include "numerics/gsl_callback.h"

#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace chaplygin {

std::string gslStepperName(GslStepper stepper) {
    switch (stepper) {
    case GslStepper::Rk4:
        return "gsl_rk4";
    case GslStepper::Rkf45:
        return "gsl_rkf45";
    case GslStepper::Rkck:
        return "gsl_rkck";
    case GslStepper::Rk8pd:
        return "gsl_rk8pd";
    case GslStepper::MsAdams:
        return "gsl_msadams";
    case GslStepper::MsBdf:
        return "gsl_msbdf";
    }
    return "gsl";
}

namespace {

const gsl_odeiv2_step_type* stepType(GslStepper stepper) {
    switch (stepper) {
    case GslStepper::Rk4:
        return gsl_odeiv2_step_rk4;
    case GslStepper::Rkf45:
        return gsl_odeiv2_step_rkf45;
    case GslStepper::Rkck:
        return gsl_odeiv2_step_rkck;
    case GslStepper::Rk8pd:
        return gsl_odeiv2_step_rk8pd;
    case GslStepper::MsAdams:
        return gsl_odeiv2_step_msadams;
    case GslStepper::MsBdf:
        return gsl_odeiv2_step_msbdf;
    }
    return gsl_odeiv2_step_rkf45;
}

struct StepDeleter {
    void operator()(gsl_odeiv2_step* s) const { gsl_odeiv2_step_free(s); }
};
using StepPtr = std::unique_ptr<gsl_odeiv2_step, StepDeleter>;

struct DriverDeleter {
    void operator()(gsl_odeiv2_driver* d) const { gsl_odeiv2_driver_free(d); }
};
using DriverPtr = std::unique_ptr<gsl_odeiv2_driver, DriverDeleter>;

gsl_odeiv2_system systemOf(gsl::OdeAdapter& adapter, int n) {
    return {&gsl::OdeAdapter::rhs, &gsl::OdeAdapter::jacobian, static_cast<std::size_t>(n),
            &adapter};
}

StepPtr stepOf(GslStepper stepper, int n) {
    StepPtr step(gsl_odeiv2_step_alloc(stepType(stepper), static_cast<std::size_t>(n)));
    if (!step)
        throw std::runtime_error("gsl_odeiv2_step_alloc failed");
    return step;
}

// The adaptive solve from t0 to t1: free steps through the driver's own evolve, control and
// stepper (msadams/msbdf need the driver), never clamped to output times. accepted(t, y, f) sees
// the start and every accepted step, f = f(t, y).
template <class Accepted>
void driveGsl(const OdeProblem& problem, GslStepper stepper, double t0, const double* y0, double t1,
              double tolerance, OdeWork& work, Accepted accepted) {
    const int n = problem.dimension();
    gsl::OdeAdapter adapter{&problem, &work};
    gsl_odeiv2_system sys = systemOf(adapter, n);
    gsl::ensureErrorHandlerOff();
    // a first step of tol^(1/4) of the span; the controller adapts it at once
    double h = (t1 - t0) * std::min(0.1, std::pow(tolerance, 0.25));
    DriverPtr driver(gsl_odeiv2_driver_alloc_standard_new(&sys, stepType(stepper), h, tolerance,
                                                          tolerance, 1.0, 0.0));
    if (!driver)
        throw std::runtime_error("gsl_odeiv2_driver_alloc failed");
    OdeValue y{}, f{};
    std::copy_n(y0, n, y.begin());
    double t = t0;
    problem.rhs(t, y.data(), f.data());
    ++work.rhsEvals;
    accepted(t, y, f);
    gsl_odeiv2_driver* d = driver.get();
    while (t < t1) {
        int status = gsl_odeiv2_evolve_apply(d->e, d->c, d->s, &sys, &t, t1, &h, y.data());
        if (status != GSL_SUCCESS) {
            adapter.rethrowProblemError();
            throw std::runtime_error(gslStepperName(stepper) + ": " + gsl_strerror(status) +
                                     " at t = " + std::to_string(t));
        }
        // f(t, y) at the accepted point: every odeiv2 stepper leaves it in the evolve object's
        // dydt_out (already counted), equal bit for bit to a fresh evaluation
        std::copy_n(d->e->dydt_out, n, f.begin());
        accepted(t, y, f);
        if (work.rhsEvals > 50'000'000)
            throw std::runtime_error(gslStepperName(stepper) + ": too many steps");
    }
    work.steps = static_cast<long>(d->e->count);
    work.rejected = static_cast<long>(d->e->failed_steps);
}

} // namespace

GslSolve integrateGsl(const OdeProblem& problem, GslStepper stepper, double t0, const double* y0,
                      double t1, double tolerance) {
    GslSolve out{DenseOutput(problem.dimension()), OdeWork{}};
    driveGsl(problem, stepper, t0, y0, t1, tolerance, out.work,
             [&](double t, const OdeValue& y, const OdeValue& f) {
                 out.dense.add(problem, t, y.data(), f.data(), out.work);
             });
    return out;
}

OdeWork integrateGslFixed(const OdeProblem& problem, GslStepper stepper, double t0, double* y,
                          double t1, long steps) {
    if (stepper == GslStepper::MsAdams || stepper == GslStepper::MsBdf || steps < 1)
        throw std::invalid_argument("integrateGslFixed: explicit steppers and steps >= 1 only");
    const int n = problem.dimension();
    OdeWork work;
    gsl::OdeAdapter adapter{&problem, &work};
    gsl_odeiv2_system sys = systemOf(adapter, n);
    gsl::ensureErrorHandlerOff();
    StepPtr step = stepOf(stepper, n);
    OdeValue err{};
    const double h = (t1 - t0) / static_cast<double>(steps);
    for (long i = 0; i < steps; ++i) {
        int status = gsl_odeiv2_step_apply(step.get(), t0 + h * static_cast<double>(i), h, y,
                                           err.data(), nullptr, nullptr, &sys);
        if (status != GSL_SUCCESS) {
            adapter.rethrowProblemError();
            throw std::runtime_error(gslStepperName(stepper) + ": fixed step failed");
        }
    }
    work.steps = steps;
    return work;
}

std::vector<OdeValue> gslValuesAt(const OdeProblem& problem, GslStepper stepper, GslSolve& solve,
                                  const std::vector<double>& times) {
    const int n = problem.dimension();
    std::vector<OdeValue> out(times.size());
    if (stepper != GslStepper::Rk8pd) {
        for (std::size_t i = 0; i < times.size(); ++i)
            solve.dense.at(times[i], out[i].data());
        return out;
    }
    gsl::OdeAdapter adapter{&problem, &solve.work};
    gsl_odeiv2_system sys = systemOf(adapter, n);
    gsl::ensureErrorHandlerOff();
    StepPtr step = stepOf(stepper, n);
    OdeValue err{}, dydt{};
    for (std::size_t i = 0; i < times.size(); ++i) {
        const double t = times[i];
        std::size_t k = solve.dense.nodeBefore(t);
        const double tk = solve.dense.time(k);
        std::copy_n(solve.dense.state(k), n, out[i].begin());
        if (t <= tk || k + 1 == solve.dense.size())
            continue;
        // one step of the method itself from the accepted node, with the stored derivative
        std::copy_n(solve.dense.derivative(k), n, dydt.begin());
        gsl_odeiv2_step_reset(step.get());
        int status = gsl_odeiv2_step_apply(step.get(), tk, t - tk, out[i].data(), err.data(),
                                           dydt.data(), nullptr, &sys);
        if (status != GSL_SUCCESS) {
            adapter.rethrowProblemError();
            throw std::runtime_error(gslStepperName(stepper) + ": dense step failed");
        }
    }
    return out;
}

GslSteps integrateGslSteps(const OdeProblem& problem, GslStepper stepper, double t0,
                           const double* y0, double t1, double tolerance,
                           const std::function<void(double, const double*)>& accepted) {
    GslSteps out;
    driveGsl(problem, stepper, t0, y0, t1, tolerance, out.work,
             [&](double t, const OdeValue& y, const OdeValue& f) {
                 out.t.push_back(t);
                 out.y.push_back(y);
                 out.f.push_back(f);
                 if (accepted)
                     accepted(t, y.data());
             });
    return out;
}

void gslStepFrom(const OdeProblem& problem, GslStepper stepper, const GslSteps& steps, double t,
                 double* out) {
    if (stepper == GslStepper::MsAdams || stepper == GslStepper::MsBdf)
        throw std::invalid_argument("gslStepFrom: explicit steppers only");
    const int n = problem.dimension();
    auto it = std::upper_bound(steps.t.begin(), steps.t.end(), t);
    const std::size_t k =
        it == steps.t.begin() ? 0 : static_cast<std::size_t>(it - steps.t.begin()) - 1;
    const double tk = steps.t[k];
    std::copy_n(steps.y[k].data(), n, out);
    if (t <= tk)
        return;
    OdeWork work;
    gsl::OdeAdapter adapter{&problem, &work};
    gsl_odeiv2_system sys = systemOf(adapter, n);
    gsl::ensureErrorHandlerOff();
    StepPtr step = stepOf(stepper, n);
    OdeValue err{}, dydt = steps.f[k];
    int status =
        gsl_odeiv2_step_apply(step.get(), tk, t - tk, out, err.data(), dydt.data(), nullptr, &sys);
    if (status != GSL_SUCCESS) {
        adapter.rethrowProblemError();
        throw std::runtime_error(gslStepperName(stepper) + ": step to t = " + std::to_string(t) +
                                 " failed");
    }
}

} // namespace chaplygin
