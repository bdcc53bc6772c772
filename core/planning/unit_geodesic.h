#pragma once
// A geodesic of the normalised sub-Riemannian problem on SE(2) (b = v_T = 1, from the identity
// pose): the genuine vakonomic motion's closed form (docs/physics.md §8) read as the exponential
// map, with the pendulum's passage time through a given state (docs/physics.md §10). Libration
// and rotation are evaluated in the complementary parameter 1 - k^2, carried exactly, so that
// the end stays exact next to the separatrix.
#include "motion/vakonomic_motion.h"

#include <optional>

namespace chaplygin {

/// The pose and the pendulum's state of a unit geodesic at one time.
struct UnitGeodesicPoint {
    double x = 0, y = 0, phi = 0;
    double sinPsi = 0, cosPsi = 0; ///< u = (sdot, phidot) = (sin Psi, cos Psi)
};

/// When the pendulum Psi'' = -(1/2) sin 2Psi passes a state of its own orbit: the first time
/// t >= 0, the period after which it passes it again (Psi mod 2 pi), and the displacement of the
/// knife point over one period (it is the same after every period).
struct PendulumPassage {
    double t = 0;
    double period = 0;
    double x = 0, y = 0; ///< the knife point at t
    double driftX = 0, driftY = 0;
};

/// The passage of the geodesic (psi0, lambda0) through (Psi1, Lambda1) and its position there,
/// from the state alone (no sn-cn-dn): what the planner evaluates along its curves. None as for
/// UnitGeodesic::passage, and on the separatrix level.
std::optional<PendulumPassage> pendulumPassage(double psi0, double lambda0, double sinPsi1,
                                               double cosPsi1, double lambda1);

/// The geodesic with Psi(0) = psi0 and Psidot(0) = lambda0 from (0, 0, 0), at unit speed and
/// b = 1. Its momentum P = (sin Psi0, Lambda0) is constant in the plane (|P| = k, the
/// pendulum's modulus), and cos Psi + x P_y - y P_x is constant.
class UnitGeodesic {
  public:
    /// 1 - k^2 = (cos Psi0 - Lambda0)(cos Psi0 + Lambda0), from the start's doubles.
    UnitGeodesic(double psi0, double lambda0);
    /// The geodesic of the start Psi0 whose 1 - k^2 is `gap` exactly; lambda0 gives the sign of
    /// Psidot0 and the start's phase (next to the separatrix Lambda0 = +-sqrt(cos^2 Psi0 - gap)
    /// rounded to a double no longer fixes k).
    UnitGeodesic(double psi0, double lambda0, double gap);

    UnitGeodesicPoint at(double t) const;
    double psi0() const { return m_psi0; }
    double lambda0() const { return m_lambda0; }
    /// The pendulum's modulus k.
    double modulus() const { return m_k; }
    /// 1 - k^2.
    double gap() const { return m_gap; }
    VakonomicMotion::Case kind() const { return m_kind; }

    /// The first passage through (Psi1 mod 2 pi, Lambda1), a state on the same energy level;
    /// none when it lies on the other libration orbit (about the other rest point), on another
    /// rotation direction, or when the motion is the separatrix, the line or pivoting (those
    /// are solved in closed form by the planner, docs/physics.md §10).
    std::optional<PendulumPassage> passage(double sinPsi1, double cosPsi1, double lambda1) const;

  private:
    double m_psi0, m_lambda0, m_gap;
    VakonomicMotion::Case m_kind = VakonomicMotion::Case::Rest;
    double m_k = 0;
    /// the line, pivoting and the separatrix: the vakonomic body's own closed form
    std::optional<VakonomicMotion> m_motion;
    // libration and rotation (docs/physics.md §8): the complementary parameter mc, the sign
    // eps (libration) or sigma (rotation), K, D(pi/2), the argument w0 at t = 0, its rate, and
    // at t = 0 the amplitude, the heading term (am w0 or asin(q sn w0)), sn, cn, dn, D(am w0)
    double m_mc = 0, m_sign = 1, m_K = 0, m_D = 0, m_w0 = 0, m_rate = 1;
    double m_am0 = 0, m_heading0 = 0, m_sn0 = 0, m_cn0 = 0, m_dn0 = 0, m_d0 = 0;
};

} // namespace chaplygin
