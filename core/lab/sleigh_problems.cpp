#include "lab/sleigh_problems.h"

#include <cmath>

namespace chaplygin {

void ControlledProblem::rhs(double, const double* y, double* dydt) const {
    CurveGeometry g = geometryOf(m_curve.eval(y[0]));
    const double bk = m_params.system.b * g.kappa;
    const double sdot = m_params.mode == SpeedMode::Energy ? m_params.speed / std::sqrt(1 + bk * bk)
                                                           : m_params.speed;
    dydt[0] = sdot / g.speed;
}

void ControlledProblem::jacobian(double, const double* y, double* dfdy, double* dfdt) const {
    CurvePoint p = m_curve.eval(y[0]);
    CurveGeometry g = geometryOf(p);
    const double b = m_params.system.b, bk = b * g.kappa;
    const double root = std::sqrt(1 + bk * bk);
    const bool energy = m_params.mode == SpeedMode::Energy;
    const double sdot = energy ? m_params.speed / root : m_params.speed;
    // d|r'|/du = (x'x'' + y'y'')/|r'|, dkappa/du = (dkappa/ds) |r'|
    const double dspeed = (p.dx * p.ddx + p.dy * p.ddy) / g.speed;
    const double dkappa = g.dkappa * g.speed;
    // d sdot/d kappa = -v_T b^2 kappa/(1 + b^2 kappa^2)^(3/2) in Energy mode
    const double dsdot = energy ? -m_params.speed * b * bk / (root * root * root) : 0.0;
    dfdy[0] = dsdot * dkappa / g.speed - sdot * dspeed / (g.speed * g.speed);
    dfdt[0] = 0;
}

namespace {
constexpr double kFlush = 1e-150;
double flushed(double v) {
    return std::fabs(v) < kFlush ? 0.0 : v;
}
} // namespace

void FreeProblem::rhs(double, const double* y, double* dydt) const {
    const double a = m_sys.a, b2 = m_sys.b * m_sys.b;
    const double sdot = y[3], phidot = flushed(y[4]);
    dydt[0] = sdot * std::cos(y[2]);
    dydt[1] = sdot * std::sin(y[2]);
    dydt[2] = phidot;
    dydt[3] = a * phidot * phidot;     // (D12)
    dydt[4] = -a * sdot * phidot / b2; // (D13)
}

void FreeProblem::jacobian(double, const double* y, double* J, double* dfdt) const {
    const double a = m_sys.a, b2 = m_sys.b * m_sys.b;
    const double sdot = y[3], phidot = flushed(y[4]);
    const double c = std::cos(y[2]), s = std::sin(y[2]);
    for (int i = 0; i < 25; ++i)
        J[i] = 0;
    J[0 * 5 + 2] = -sdot * s;
    J[0 * 5 + 3] = c;
    J[1 * 5 + 2] = sdot * c;
    J[1 * 5 + 3] = s;
    J[2 * 5 + 4] = 1;
    J[3 * 5 + 4] = 2 * a * phidot;
    J[4 * 5 + 3] = -a * phidot / b2;
    J[4 * 5 + 4] = -a * sdot / b2;
    for (int i = 0; i < 5; ++i)
        dfdt[i] = 0;
}

double FreeProblem::energy(const double* y) const {
    return 0.5 * (y[3] * y[3] + m_sys.b * m_sys.b * y[4] * y[4]);
}

void FreeProblem::projectToEnergy(double* y, double e0) const {
    const double e = energy(y);
    if (e > 0) {
        const double scale = std::sqrt(e0 / e);
        y[3] *= scale;
        y[4] *= scale;
    }
}

namespace {

struct OpenLoopTerms {
    double v, b, a, psi, phi, chidot;
};

OpenLoopTerms openLoopTerms(const PlannedMotion& plan, double t, const double* y) {
    PlannedMotion::State st = plan.at(t);
    const DerivedSystem& sys = plan.params().system;
    // Psi = chi(t) + (a/b) phi, paper (33), with chi(t) = Psi_plan(t) - (a/b) phi_plan(t)
    const double psi = st.psi + (sys.a / sys.b) * (y[2] - st.phi);
    return {plan.params().speed, sys.b, sys.a, psi, y[2], st.chidot};
}

} // namespace

void OpenLoopProblem::rhs(double t, const double* y, double* dydt) const {
    OpenLoopTerms k = openLoopTerms(m_plan, t, y);
    const double sp = std::sin(k.psi);
    dydt[0] = k.v * sp * std::cos(k.phi);    // (36)
    dydt[1] = k.v * sp * std::sin(k.phi);    // (37)
    dydt[2] = (k.v / k.b) * std::cos(k.psi); // (35)
}

void OpenLoopProblem::jacobian(double t, const double* y, double* J, double* dfdt) const {
    OpenLoopTerms k = openLoopTerms(m_plan, t, y);
    const double sp = std::sin(k.psi), cp = std::cos(k.psi);
    const double c = std::cos(k.phi), s = std::sin(k.phi), r = k.a / k.b;
    for (int i = 0; i < 9; ++i)
        J[i] = 0;
    // dPsi/dphi = a/b, dPsi/dt = chidot
    J[0 * 3 + 2] = k.v * (cp * r * c - sp * s);
    J[1 * 3 + 2] = k.v * (cp * r * s + sp * c);
    J[2 * 3 + 2] = -(k.v / k.b) * sp * r;
    dfdt[0] = k.v * cp * c * k.chidot;
    dfdt[1] = k.v * cp * s * k.chidot;
    dfdt[2] = -(k.v / k.b) * sp * k.chidot;
}

} // namespace chaplygin
