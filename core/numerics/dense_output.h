#pragma once
// Quintic Hermite dense output between an ODE method's accepted steps (docs/numerics.md §1).
#include "numerics/ode_problem.h"

#include <array>
#include <vector>

namespace chaplygin {

/// The solution of an ODE between its accepted steps, interpolated by quintic Hermite
/// polynomials through y, y' = f and y'' = (df/dy) f + df/dt at both ends of each step. Integrating
/// freely and interpolating keeps the step size the method chose (docs/numerics.md §1): the
/// interpolation error is O(h^6), below the local error of every method here at its own step.
using OdeValue = std::array<double, kMaxOdeDimension>;

class DenseOutput {
  public:
    explicit DenseOutput(int dimension) : m_dim(dimension) {}

    /// Appends the node (t, y) with y' = f(t, y) given; y'' from the problem's Jacobian.
    void add(const OdeProblem& problem, double t, const double* y, const double* f, OdeWork& work);
    /// Room for this many nodes (fixed-step methods know their count).
    void reserve(std::size_t nodes);
    int dimension() const { return m_dim; }
    std::size_t size() const { return m_t.size(); }
    double tFront() const { return m_t.front(); }
    double tBack() const { return m_t.back(); }
    /// y(t) into out (t clamped to the nodes' range).
    void at(double t, double* out) const;
    /// The last node at or before t, and a node's time and state.
    std::size_t nodeBefore(double t) const;
    double time(std::size_t node) const { return m_t[node]; }
    const double* state(std::size_t node) const { return m_y[node].data(); }
    const double* derivative(std::size_t node) const { return m_f[node].data(); }

  private:
    using Row = std::array<double, kMaxOdeDimension>;
    int m_dim;
    std::vector<double> m_t;
    std::vector<Row> m_y, m_f, m_g; // y, y', y''
};

} // namespace chaplygin
