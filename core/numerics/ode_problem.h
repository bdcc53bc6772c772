#pragma once
// An ODE y' = f(t, y) with its Jacobian as the steppers see it, and the work counters of a solve.
#include <cstddef>

namespace chaplygin {

/// A first-order system y' = f(t, y) with its exact Jacobian, as the method registry sees it.
/// Dimensions are small (at most kMaxOdeDimension), so callers keep state in fixed arrays.
class OdeProblem {
  public:
    virtual ~OdeProblem() = default;
    virtual int dimension() const = 0;
    /// f(t, y) into dydt.
    virtual void rhs(double t, const double* y, double* dydt) const = 0;
    /// df/dy (row-major, dimension x dimension) into dfdy and df/dt into dfdt.
    virtual void jacobian(double t, const double* y, double* dfdy, double* dfdt) const = 0;
};

constexpr int kMaxOdeDimension = 8;

/// Work counters of one solve.
struct OdeWork {
    long rhsEvals = 0;      ///< calls of f
    long jacobianEvals = 0; ///< calls of df/dy (msbdf, and the quintic dense output)
    long steps = 0;         ///< accepted steps
    long rejected = 0;      ///< rejected steps (adaptive methods)
};

} // namespace chaplygin
