#pragma once
// The tracking control law: Psi, chi, lambda, the accelerations, forces and energy from kappa,
// dkappa/ds and phi on a smooth stretch, at a cusp and while pivoting (docs/physics.md §2, §3).
#include "systems/system.h"

#include <string>

namespace chaplygin {

enum class SpeedMode {
    Energy, ///< constant kinetic energy: v_T = sqrt(2T/m_eff) fixed (paper sec. 4)
    Speed   ///< constant speed along the path: sdot = v_s fixed (App. C)
};
SpeedMode speedModeFromName(const std::string& name);
std::string speedModeName(SpeedMode mode);

/// Fixed parameters of the control law (a const value; state is separate).
struct ControlParams {
    DerivedSystem system;
    SpeedMode mode = SpeedMode::Energy;
    double speed = 1.0; ///< v_T [m/s] in Energy mode, v_s [m/s] in Speed mode
};

/// The tracking control at one point of the path (docs/physics.md §2). Units: SI.
struct ControlState {
    double sdot = 0, phidot = 0;   ///< [m/s], [rad/s]
    double sddot = 0, phiddot = 0; ///< [m/s^2], [rad/s^2]
    double psi = 0;    ///< control angle Psi = atan2(sdot, b phidot): in (0, pi) while sdot > 0,
                       ///< continued through cusps (docs/physics.md §3)
    double psidot = 0; ///< [rad/s]
    double chi = 0;    ///< Psi - (a/b) phi
    double lambda = 0; ///< m b chidot [N s/m * m = kg m/s]
    double energy = 0; ///< kinetic energy T [J]
    double vT = 0;     ///< sqrt(2T/m) [m/s]
    double forceAxial = 0;    ///< F_cs = m (sddot - a phidot^2) [N]; M_eff sddot (a = 0)
    double forceLateral = 0;  ///< F_cphi = m_tr sdot phidot + m a phiddot [N] (m_tr: the
                              ///< translating mass, docs/physics.md §2)
    double torque = 0;        ///< S_c = I phiddot about the CM (J phiddot, carriage) [N m]
    double knifeReaction = 0; ///< N = F_cphi, acting at P [N]
    double controlCouple = 0; ///< tau = S_c + a N [N m]
};

/// The control on a smooth stretch, from the curvature, its arc-length derivative and heading.
/// Backing up (direction -1, after a cusp): kappa = dphi/ds and s along the heading, so sdot < 0,
/// and Psi = atan2(-1, -b kappa) + psiOffset (docs/physics.md §3).
ControlState controlOnCurve(const ControlParams& p, double kappa, double dkappa, double phi,
                            int direction = 1, double psiOffset = 0);

/// The control at a cusp (Energy mode): sdot = 0, phidot = sign(dphi/du) v_T/b, and
/// Psidot = (dPsi/du)(du/dt) = -|r''| v_T/(b^2 dphi/du |dphi/du|) (docs/physics.md §3).
/// `slope` is the sign of d sigma/du there: -1 from driving forwards to backing up, +1 from
/// backing up to driving forwards (Psidot changes sign with it).
ControlState controlAtCusp(const ControlParams& p, double phi, double psi, double turnRate,
                           double accel, int slope = -1);

/// The control while pivoting in place at a corner (turn > 0: left). Only Energy mode can pivot.
ControlState controlAtPivot(const ControlParams& p, double phi, double turnSign);

} // namespace chaplygin
