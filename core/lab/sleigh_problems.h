#pragma once
// The sleigh's ODE problems for the method lab: the controlled time law in u, the free sleigh and
// the paper's open loop.
#include "control/control_law.h"
#include "lab/planned_motion.h"
#include "numerics/ode_problem.h"
#include "paths/curve.h"
#include "systems/system.h"

namespace chaplygin {

/// The controlled time law as an ODE in t for the curve parameter u (docs/physics.md §2):
/// du/dt = sdot/|r'(u)| with sdot = v_T/sqrt(1 + b^2 kappa^2) (Energy) or v_s (Speed).
/// For an arc-length parametrised curve (the catenary, paper (97)-(98)) u = s and this is
/// ds/dt = v_T/sqrt(1 + b^2 kappa(s)^2); kappa and ds/du come exactly from the curve.
class ControlledProblem final : public OdeProblem {
  public:
    ControlledProblem(const Curve& curve, const ControlParams& params)
        : m_curve(curve), m_params(params) {}
    int dimension() const override { return 1; }
    void rhs(double t, const double* y, double* dydt) const override;
    void jacobian(double t, const double* y, double* dfdy, double* dfdt) const override;

  private:
    const Curve& m_curve;
    ControlParams m_params;
};

/// The free (Lagrange-d'Alembert) sleigh in y = (x, y, phi, sdot, phidot), paper (D12)-(D13):
/// sddot = a phidot^2, phiddot = -a sdot phidot/b^2, xdot = sdot cos phi, ydot = sdot sin phi.
/// phidot below 1e-150 is flushed to 0 so that long horizons never compute with subnormal
/// numbers (RK4 measured 3.5x slower on them); its contribution is below 1e-150 either way.
class FreeProblem final : public OdeProblem {
  public:
    explicit FreeProblem(const DerivedSystem& system) : m_sys(system) {}
    int dimension() const override { return 5; }
    void rhs(double t, const double* y, double* dydt) const override;
    void jacobian(double t, const double* y, double* dfdy, double* dfdt) const override;
    /// Kinetic energy per unit mass: (sdot^2 + b^2 phidot^2)/2.
    double energy(const double* y) const;
    /// The projection onto the energy level of e0: (sdot, phidot) scaled radially in the metric
    /// diag(1, b^2), the closest point of the level set in that metric.
    void projectToEnergy(double* y, double e0) const;

  private:
    DerivedSystem m_sys;
};

/// The open-loop integration of paper (35)-(37) in (x, y, phi) for Fig. 3: the control
/// input chi(t) is taken from the planned motion and Psi = chi + (a/b) phi, paper (33);
/// xdot = v_T sin Psi cos phi (36), ydot = v_T sin Psi sin phi (37), phidot = (v_T/b) cos Psi (35).
/// Nothing pulls the body back to the path, so integration errors accumulate as drift.
/// Energy mode only.
class OpenLoopProblem final : public OdeProblem {
  public:
    explicit OpenLoopProblem(const PlannedMotion& plan) : m_plan(plan) {}
    int dimension() const override { return 3; }
    void rhs(double t, const double* y, double* dydt) const override;
    void jacobian(double t, const double* y, double* dfdy, double* dfdt) const override;

  private:
    const PlannedMotion& m_plan;
};

} // namespace chaplygin
