#include "lab/vakonomic_problem.h"

#include <cmath>

namespace chaplygin {

void VakonomicProblem::rhs(double, const double* y, double* dydt) const {
    const double b2 = m_sys.b * m_sys.b;
    const double sdot = y[3], phidot = y[4], l = y[5];
    dydt[0] = sdot * std::cos(y[2]);
    dydt[1] = sdot * std::sin(y[2]);
    dydt[2] = phidot;
    dydt[3] = l * phidot;     // m sddot = lambda_c phidot, (19) corrected
    dydt[4] = -l * sdot / b2; // m b^2 phiddot = -lambda_c sdot, (20)
    dydt[5] = -sdot * phidot; // lambda_c_dot = -m sdot phidot, (21)
}

void VakonomicProblem::jacobian(double, const double* y, double* J, double* dfdt) const {
    const double b2 = m_sys.b * m_sys.b;
    const double sdot = y[3], phidot = y[4], l = y[5];
    const double c = std::cos(y[2]), s = std::sin(y[2]);
    for (int i = 0; i < 36; ++i)
        J[i] = 0;
    J[0 * 6 + 2] = -sdot * s;
    J[0 * 6 + 3] = c;
    J[1 * 6 + 2] = sdot * c;
    J[1 * 6 + 3] = s;
    J[2 * 6 + 4] = 1;
    J[3 * 6 + 4] = l;
    J[3 * 6 + 5] = phidot;
    J[4 * 6 + 3] = -l / b2;
    J[4 * 6 + 5] = -sdot / b2;
    J[5 * 6 + 3] = -phidot;
    J[5 * 6 + 4] = -sdot;
    for (int i = 0; i < 6; ++i)
        dfdt[i] = 0;
}

} // namespace chaplygin
