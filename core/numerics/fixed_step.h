#pragma once
// Hand-written classical RK4 with equal steps, optionally projected after each step: the
// benchmarks' floor.
#include "numerics/dense_output.h"
#include "numerics/ode_problem.h"

#include <functional>

namespace chaplygin {

/// A map applied to the state after every step (e.g. a projection onto an invariant manifold).
using StepProjection = std::function<void(double* y)>;

/// Hand-written classical RK4 (4 f per step) with n equal steps from t0 to t1: the floor the
/// benchmarks compare GSL against. With a projection, y is mapped after every step (the
/// structure-preserving variant: projection onto the energy level, Hairer-Lubich-Wanner IV.4).
struct FixedStepSolve {
    DenseOutput dense;
    OdeWork work;
};
FixedStepSolve integrateRk4(const OdeProblem& problem, double t0, const double* y0, double t1,
                            long steps, const StepProjection& projection = {});

} // namespace chaplygin
