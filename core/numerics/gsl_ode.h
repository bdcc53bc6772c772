#pragma once
#include "numerics/dense_output.h"
#include "numerics/ode_problem.h"

#include <string>

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

} // namespace chaplygin
