#pragma once
#include "numerics/dense_output.h"
#include "numerics/ode_problem.h"

#include <functional>
#include <string>
#include <vector>

namespace chaplygin {

/// The GSL odeiv2 steppers of the method registry.
enum class GslStepper {
    Rk4,     ///< NOT classical RK4: one step plus two half steps for the error, 11 f per step
    Rkf45,   ///< Runge-Kutta-Fehlberg 4(5)
    Rkck,    ///< Runge-Kutta Cash-Karp 4(5)
    Rk8pd,   ///< Runge-Kutta Prince-Dormand 8(9)
    MsAdams, ///< variable-order Adams (orders 1-12), functional iteration
    MsBdf    ///< variable-order BDF (orders 1-5), Newton with the exact Jacobian
};
std::string gslStepperName(GslStepper stepper);

/// Integrates y' = f(t, y) from (t0, y0) to t1 with a GSL stepper under the standard error
/// control |err_i| <= tol (1 + |y_i|), stepping freely (the last step lands on t1) and keeping
/// every accepted step for dense output. Throws std::runtime_error when GSL fails.
struct GslSolve {
    DenseOutput dense;
    OdeWork work;
};
GslSolve integrateGsl(const OdeProblem& problem, GslStepper stepper, double t0, const double* y0,
                      double t1, double tolerance);

/// n equal steps of an explicit GSL stepper (Rk4, Rkf45, Rkck, Rk8pd) without error control,
/// for measuring its order; y0 in, y(t1) out.
OdeWork integrateGslFixed(const OdeProblem& problem, GslStepper stepper, double t0, double* y,
                          double t1, long steps);

/// The solution at the ascending times. A stepper whose local order exceeds the quintic Hermite
/// interpolant's (rk8pd: 9 against 6) takes one step of its own from the last accepted point
/// to each time (counted in work), so the output keeps the method's order; the others
/// interpolate (their local error is at most O(h^6) already, and msadams/msbdf cannot restart
/// a step without their history).
std::vector<OdeValue> gslValuesAt(const OdeProblem& problem, GslStepper stepper, GslSolve& solve,
                                  const std::vector<double>& times);

/// The accepted steps of a free run (t, y and f = y' at each), for problems without a Jacobian:
/// a value between them is one step of the method from the last step before it (gslStepFrom).
struct GslSteps {
    std::vector<double> t;
    std::vector<OdeValue> y, f;
    OdeWork work;
};
/// Integrates freely from (t0, y0) to t1 as integrateGsl does, keeping the accepted steps only.
/// `accepted`, when given, sees every accepted (t, y) and may throw to stop the run.
GslSteps integrateGslSteps(const OdeProblem& problem, GslStepper stepper, double t0,
                           const double* y0, double t1, double tolerance,
                           const std::function<void(double, const double*)>& accepted = {});
/// y(t) into out for t in [steps.t.front(), steps.t.back()]: one step of an explicit stepper
/// (Rk4, Rkf45, Rkck, Rk8pd) from the last accepted step at or before t, so the value has the
/// method's own order. Thread-safe (its stepper is its own).
void gslStepFrom(const OdeProblem& problem, GslStepper stepper, const GslSteps& steps, double t,
                 double* out);

} // namespace chaplygin
