#include "numerics/fixed_step.h"

#include <array>
#include <stdexcept>

namespace chaplygin {

FixedStepSolve integrateRk4(const OdeProblem& problem, double t0, const double* y0, double t1,
                            long steps, const StepProjection& projection) {
    if (steps < 1)
        throw std::invalid_argument("integrateRk4: steps must be >= 1");
    const int n = problem.dimension();
    FixedStepSolve out{DenseOutput(n), OdeWork{}};
    out.dense.reserve(static_cast<std::size_t>(steps) + 1);
    using Vec = std::array<double, kMaxOdeDimension>;
    Vec y{}, k1{}, k2{}, k3{}, k4{}, tmp{};
    std::copy_n(y0, n, y.begin());
    const double h = (t1 - t0) / static_cast<double>(steps);
    double t = t0;
    problem.rhs(t, y.data(), k1.data());
    ++out.work.rhsEvals;
    out.dense.add(problem, t, y.data(), k1.data(), out.work);
    for (long i = 0; i < steps; ++i) {
        // k1 is f at the current point (kept from the previous step's dense node)
        for (int j = 0; j < n; ++j)
            tmp[j] = y[j] + 0.5 * h * k1[j];
        problem.rhs(t + 0.5 * h, tmp.data(), k2.data());
        for (int j = 0; j < n; ++j)
            tmp[j] = y[j] + 0.5 * h * k2[j];
        problem.rhs(t + 0.5 * h, tmp.data(), k3.data());
        for (int j = 0; j < n; ++j)
            tmp[j] = y[j] + h * k3[j];
        problem.rhs(t + h, tmp.data(), k4.data());
        for (int j = 0; j < n; ++j)
            y[j] += h / 6.0 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
        t = i + 1 == steps ? t1 : t0 + h * static_cast<double>(i + 1);
        if (projection)
            projection(y.data());
        problem.rhs(t, y.data(), k1.data());
        out.work.rhsEvals += 4;
        out.dense.add(problem, t, y.data(), k1.data(), out.work);
    }
    out.work.steps = steps;
    return out;
}

} // namespace chaplygin
