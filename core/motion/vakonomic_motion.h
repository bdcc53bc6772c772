#pragma once
// The genuine vakonomic body in closed form through Jacobi elliptic functions
// (docs/physics.md §8).
#include "systems/system.h"

#include <string>

namespace chaplygin {

/// Initial state of the genuine vakonomic body: the controlled motion's state at t = 0 and the
/// tracking's multiplier lambda(0), the only free constant of the vakonomic system.
struct VakonomicInitial {
    double x = 0, y = 0, phi = 0, sdot = 0, phidot = 0;
    double lambda = 0; ///< lambda(0) [kg m/s]; lambda_c = lambda + m a phidot
};

struct VakonomicState {
    double x = 0, y = 0, phi = 0, sdot = 0, phidot = 0;
    double lambda = 0; ///< lambda = lambda_c - m a phidot [kg m/s]
    double psi = 0;    ///< Psi = atan2(sdot, b phidot), continuous in t [rad]
    double psidot = 0; ///< Lambda = lambda_c/(m b) [rad/s]
    double chi = 0;    ///< Psi - (a/b) phi [rad]
    double energy = 0; ///< T = (m/2)(sdot^2 + b^2 phidot^2) from the state [J]
};

/// The genuine vakonomic body, the multiplier obeying its own equation (docs/physics.md §2,
/// paper (14)-(17)): m sddot = lambda_c phidot, m b^2 phiddot = -lambda_c sdot,
/// lambda_c_dot = -m sdot phidot. With sdot = v_T sin Psi, b phidot = v_T cos Psi and
/// Psidot = lambda_c/(m b), Psi'' = -(v_T^2/(2 b^2)) sin 2Psi: a pendulum in 2Psi, solved in
/// closed form through Jacobi elliptic functions (docs/physics.md §2), and so are phi and
/// the position (through the elliptic integral D). Every value at any t costs one sn-cn-dn and
/// one Carlson R_D; nothing is integrated step by step.
class VakonomicMotion {
  public:
    enum class Case {
        Rest,       ///< v_T = 0
        Line,       ///< Psi = pi/2 (mod pi), Psidot = 0: the unstable straight line
        Libration,  ///< k < 1: Psi swings about 0 (phidot > 0) or pi (phidot < 0)
        Rotation,   ///< k > 1: Psi turns over monotonically
        Separatrix, ///< k = 1: Psi creeps towards pi/2 (mod pi)
    };

    VakonomicMotion(const DerivedSystem& system, const VakonomicInitial& initial);
    VakonomicState at(double t) const;
    Case kind() const { return m_case; }
    /// The pendulum's modulus k^2 = sin^2 Psi0 + (b Psidot0/v_T)^2.
    double modulus() const { return m_k; }
    /// The model used, for the Solution's report.
    std::string model() const;

  private:
    DerivedSystem m_sys;
    VakonomicInitial m_init;
    Case m_case = Case::Rest;
    double m_vT = 0, m_omega = 0; // v_T and omega0 = v_T/b
    double m_lambdaC0 = 0;        // lambda_c(0)
    double m_psi0 = 0;            // Psi(0)
    double m_k = 0;               // modulus
    double m_eps = 1;             // sign(phidot0) (libration, separatrix)
    double m_sigma = 1;           // sign(Psidot0) (rotation, separatrix)
    double m_q = 0;               // elliptic modulus used (k or 1/k)
    double m_K = 0, m_D = 0;      // K(q), D(pi/2, q) = (K - E)/q^2
    double m_w0 = 0;              // elliptic argument (or tau) at t = 0
    double m_rate = 0;            // its rate dw/dt
    double m_am0 = 0;             // heading term at t = 0: am(w0), asin(q sn(w0)) or gd(tau0)
    double m_sn0 = 0, m_cn0 = 0, m_dn0 = 0, m_d0 = 0; // sn, cn, dn and D(am w0) at t = 0
};

} // namespace chaplygin
