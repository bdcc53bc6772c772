#pragma once
#include "numerics/ode_problem.h"
#include "systems/system.h"

namespace chaplygin {

/// The genuine vakonomic sleigh, with the multiplier obeying its own equation (docs/physics.md
/// §2), in y = (x, y, phi, sdot, phidot, l) where l = lambda_c/m:
/// sddot = l phidot (paper (19) corrected), b^2 phiddot = -l sdot (20), ldot = -sdot phidot (21).
/// Only l(0) is free. The paper's tracking drops (21) and treats lambda as a control input.
class VakonomicProblem final : public OdeProblem {
  public:
    explicit VakonomicProblem(const DerivedSystem& system) : m_sys(system) {}
    int dimension() const override { return 6; }
    void rhs(double t, const double* y, double* dydt) const override;
    void jacobian(double t, const double* y, double* dfdy, double* dfdt) const override;

  private:
    DerivedSystem m_sys;
};

} // namespace chaplygin
