#include "control/control_law.h"

#include "common/input_error.h"

#include <cmath>
#include <numbers>

namespace chaplygin {

SpeedMode speedModeFromName(const std::string& name) {
    if (name == "energy")
        return SpeedMode::Energy;
    if (name == "speed")
        return SpeedMode::Speed;
    throw InputError("mode", "unknown mode '" + name + "' (use energy or speed)");
}

std::string speedModeName(SpeedMode mode) {
    return mode == SpeedMode::Energy ? "energy" : "speed";
}

namespace {

void addForces(const ControlParams& p, ControlState& c) {
    const DerivedSystem& sys = p.system;
    const double m = sys.mass, a = sys.a;
    // docs/physics.md §2, paper (69)-(70). The lateral reaction is carried by the mass that
    // translates (the disk's m, the carriage's M + 2m); for the sleigh it is m_eff = m.
    c.forceAxial = m * (c.sddot - a * c.phidot * c.phidot);
    c.forceLateral = sys.translatingMass * c.sdot * c.phidot + m * a * c.phiddot;
    c.torque = sys.inertia() * c.phiddot;
    c.knifeReaction = c.forceLateral;
    c.controlCouple = c.torque + a * c.knifeReaction;
}

} // namespace

ControlState controlOnCurve(const ControlParams& p, double kappa, double dkappa, double phi,
                            int direction, double psiOffset) {
    const double m = p.system.mass, a = p.system.a, b = p.system.b;
    ControlState c;
    const double bk = b * kappa;
    const double root = std::sqrt(1 + bk * bk);
    // tan(Psi) = rho/b, paper (45); written as Psi = atan2(1, b kappa) in (0, pi), finite at
    // inflections
    // backing up: Psi = atan2(sdot, b phidot) = atan2(-1, -b kappa) with phidot = kappa sdot
    c.psi = std::atan2(static_cast<double>(direction), direction * bk) + psiOffset;
    if (p.mode == SpeedMode::Energy) {
        // sdot = v_T sin(Psi) (34), phidot = (v_T/b) cos(Psi) = kappa sdot (35)
        c.sdot = direction * p.speed / root;
    } else {
        c.sdot = p.speed; // App. C: sdot = v_s
    }
    c.phidot = kappa * c.sdot;
    // dPsi/ds = -b kappa_s/(1 + b^2 kappa^2), either direction
    c.psidot = -b * dkappa * c.sdot / (1 + bk * bk);
    if (p.mode == SpeedMode::Energy) {
        // docs/physics.md §2: sddot = b phidot Psidot, phiddot = -(sdot/b) Psidot
        c.sddot = b * c.phidot * c.psidot;
        c.phiddot = -(c.sdot / b) * c.psidot;
    } else {
        c.sddot = 0;
        c.phiddot = c.sdot * c.sdot * dkappa;
    }
    c.chi = c.psi - (a / b) * phi;
    // lambda = m b chidot = m (b Psidot - a phidot)
    c.lambda = m * (b * c.psidot - a * c.phidot);
    c.energy = 0.5 * m * (c.sdot * c.sdot + b * b * c.phidot * c.phidot);
    c.vT = std::sqrt(c.sdot * c.sdot + b * b * c.phidot * c.phidot);
    addForces(p, c);
    return c;
}

ControlState controlAtCusp(const ControlParams& p, double phi, double psi, double turnRate,
                           double accel, int slope) {
    const double m = p.system.mass, a = p.system.a, b = p.system.b;
    ControlState c;
    c.psi = psi;
    c.sdot = 0;
    c.phidot = std::copysign(p.speed / b, turnRate);
    // Psi = atan2(sigma, b phi') with sigma = sdot/udot passing 0 at slope -|r''| (forwards to
    // backing up) or +|r''| (back to forwards): dPsi/du = slope |r''|/(b phi'), and
    // du/dt = v_T/(b |phi'|)
    c.psidot = slope * accel * p.speed / (b * b * turnRate * std::fabs(turnRate));
    c.sddot = b * c.phidot * c.psidot;
    c.phiddot = 0;
    c.chi = c.psi - (a / b) * phi;
    c.lambda = m * (b * c.psidot - a * c.phidot);
    c.energy = 0.5 * m * b * b * c.phidot * c.phidot;
    c.vT = p.speed;
    addForces(p, c);
    return c;
}

ControlState controlAtPivot(const ControlParams& p, double phi, double turnSign) {
    const double m = p.system.mass, a = p.system.a, b = p.system.b;
    ControlState c;
    // kappa -> +-inf (docs/physics.md §3): Psi -> 0 (left) or pi (right), sdot = 0,
    // |phidot| = v_T/b
    c.psi = turnSign > 0 ? 0.0 : std::numbers::pi;
    c.sdot = 0;
    c.phidot = (turnSign > 0 ? 1.0 : -1.0) * p.speed / b;
    c.chi = c.psi - (a / b) * phi;
    c.lambda = -m * a * c.phidot;
    c.energy = 0.5 * m * b * b * c.phidot * c.phidot;
    c.vT = p.speed;
    addForces(p, c);
    return c;
}

} // namespace chaplygin
