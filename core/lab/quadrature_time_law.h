#pragma once
// The time law by GSL's adaptive quadrature and its inversion by Newton: the method lab's
// gsl_qag_newton and its reference (docs/numerics.md §1).
#include "control/control_law.h"
#include "numerics/ode_problem.h"
#include "paths/curve.h"

#include <vector>

namespace chaplygin {

/// The time law by adaptive GSL quadrature (QAG, Gauss-Kronrod) of
/// t(u) = \int |r'(u)| sqrt(1 + b^2 kappa^2)/v_T du (docs/physics.md §2, paper (52)-(53) corrected)
/// and its inversion by Newton with the exact dt/du. The tolerance bounds the quadrature's
/// absolute error of t over the whole path; Newton converges to rounding.
class QuadratureTimeLaw {
  public:
    /// rule: the Gauss-Kronrod rule's point count, 15, 21, 31, 41, 51 or 61.
    QuadratureTimeLaw(const Curve& curve, const ControlParams& params, double tolerance,
                      int rule = 21);
    /// dt/du at u [s].
    double rate(double u) const;
    /// The curve parameter u at each of the ascending times (from t = 0 at u0). Curve evaluations
    /// are counted as work.rhsEvals.
    std::vector<double> invert(const std::vector<double>& times, OdeWork& work) const;

  private:
    const Curve& m_curve;
    ControlParams m_params;
    double m_tolerance;
    int m_key;
};

} // namespace chaplygin
