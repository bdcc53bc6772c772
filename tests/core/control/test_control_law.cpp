// The tracking control law (docs/physics.md §2, §3) against its derivation by the chain rule:
// the accelerations are d/dt of the speeds along the path, the energy is T = (m/2)(ṡ² + b²φ̇²),
// and the forces are paper (69)-(70), on a curve, backing up, at a cusp and while pivoting.
#include "common/input_error.h"
#include "control/control_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace chaplygin;

namespace {

ControlParams params(SpeedMode mode, double speed) {
    ControlParams p;
    p.system.mass = 2.0;
    p.system.a = 0.3;
    p.system.b = 0.8;
    p.system.translatingMass = 1.5; // as the carriage's M + 2m is not m_eff
    p.mode = mode;
    p.speed = speed;
    return p;
}

void expectForces(const ControlParams& p, const ControlState& c) {
    const double m = p.system.mass, a = p.system.a, b = p.system.b;
    const double inertia = m * (b * b - a * a);
    EXPECT_NEAR(c.forceAxial, m * (c.sddot - a * c.phidot * c.phidot), 1e-13);
    EXPECT_NEAR(c.forceLateral, p.system.translatingMass * c.sdot * c.phidot + m * a * c.phiddot,
                1e-13);
    EXPECT_NEAR(c.torque, inertia * c.phiddot, 1e-13);
    EXPECT_EQ(c.knifeReaction, c.forceLateral);
    EXPECT_NEAR(c.controlCouple, c.torque + a * c.knifeReaction, 1e-13);
}

} // namespace

TEST(ControlLaw, ConstantEnergyOnACurveIsTheChainRuleOfItsSpeed) {
    const ControlParams p = params(SpeedMode::Energy, 1.3);
    const double vT = 1.3, b = 0.8, m = 2.0, a = 0.3;
    const double kappa = -0.7, dkappa = 0.4, phi = 0.25;
    const ControlState c = controlOnCurve(p, kappa, dkappa, phi);
    // ṡ(s) = v_T/√(1 + b²κ²) (34), φ̇ = κṡ (35)
    const double q = 1 + b * b * kappa * kappa;
    EXPECT_NEAR(c.sdot, vT / std::sqrt(q), 1e-15);
    EXPECT_NEAR(c.phidot, kappa * c.sdot, 1e-15);
    // s̈ = (dṡ/ds) ṡ = -v_T b² κ κ_s q^(-3/2) ṡ; φ̈ = κ_s ṡ² + κ s̈
    const double sddot = -vT * b * b * kappa * dkappa * std::pow(q, -1.5) * c.sdot;
    EXPECT_NEAR(c.sddot, sddot, 1e-14);
    EXPECT_NEAR(c.phiddot, dkappa * c.sdot * c.sdot + kappa * sddot, 1e-14);
    // Ψ = atan2(1, bκ) in (0, π) (45), its rate d/ds atan2(1, bκ) ṡ, and χ = Ψ - (a/b)φ
    EXPECT_NEAR(c.psi, std::atan2(1, b * kappa), 1e-15);
    EXPECT_GT(c.psi, 0);
    EXPECT_LT(c.psi, std::numbers::pi);
    EXPECT_NEAR(c.psidot, -b * dkappa / q * c.sdot, 1e-15);
    EXPECT_NEAR(c.chi, c.psi - a / b * phi, 1e-15);
    EXPECT_NEAR(c.lambda, m * (b * c.psidot - a * c.phidot), 1e-15);
    EXPECT_NEAR(c.energy, 0.5 * m * vT * vT, 1e-14);
    EXPECT_NEAR(c.vT, vT, 1e-15);
    expectForces(p, c);
}

TEST(ControlLaw, ConstantSpeedOnACurveFollowsAppendixC) {
    const ControlParams p = params(SpeedMode::Speed, 0.9);
    const double vs = 0.9, b = 0.8, m = 2.0;
    const double kappa = 1.1, dkappa = -0.6;
    const ControlState c = controlOnCurve(p, kappa, dkappa, 0.0);
    EXPECT_EQ(c.sdot, vs);
    EXPECT_EQ(c.sddot, 0);
    EXPECT_NEAR(c.phidot, vs * kappa, 1e-15);
    EXPECT_NEAR(c.phiddot, vs * vs * dkappa, 1e-15);
    // T = (m/2) v_s² (1 + b²κ²), paper (C15)
    EXPECT_NEAR(c.energy, 0.5 * m * vs * vs * (1 + b * b * kappa * kappa), 1e-14);
    expectForces(p, c);
}

TEST(ControlLaw, BackingUpReversesTheSpeedAndKeepsTheEnergy) {
    const ControlParams p = params(SpeedMode::Energy, 1.0);
    const double b = 0.8, kappa = 0.5;
    const ControlState c = controlOnCurve(p, kappa, 0.0, 0.0, -1, 2 * std::numbers::pi);
    EXPECT_NEAR(c.sdot, -1.0 / std::sqrt(1 + b * b * kappa * kappa), 1e-15);
    EXPECT_NEAR(c.phidot, kappa * c.sdot, 1e-15);
    // Ψ = atan2(ṡ, bφ̇) continued by the offset (docs/physics.md §3)
    EXPECT_NEAR(c.psi, std::atan2(c.sdot, b * c.phidot) + 2 * std::numbers::pi, 1e-14);
    EXPECT_NEAR(c.energy, 0.5 * 2.0, 1e-14);
}

TEST(ControlLaw, AtACuspTheBodyTurnsInPlaceAtTheEnergysRate) {
    const ControlParams p = params(SpeedMode::Energy, 1.2);
    const double b = 0.8, vT = 1.2, turnRate = -0.5, accel = 3.0;
    const ControlState c = controlAtCusp(p, 0.1, 1.0, turnRate, accel);
    EXPECT_EQ(c.sdot, 0);
    EXPECT_NEAR(c.phidot, -vT / b, 1e-15); // the sign of dφ/du
    // Ψ̇ = (dΨ/du)(du/dt), dΨ/du = -|r''|/(b φ'), du/dt = v_T/(b|φ'|)
    EXPECT_NEAR(c.psidot, (-accel / (b * turnRate)) * (vT / (b * std::fabs(turnRate))), 1e-14);
    EXPECT_NEAR(c.energy, 0.5 * 2.0 * vT * vT, 1e-14);
    expectForces(p, c);
}

TEST(ControlLaw, PivotingTurnsAtVTOverB) {
    const ControlParams p = params(SpeedMode::Energy, 1.2);
    const ControlState left = controlAtPivot(p, 0.0, 1), right = controlAtPivot(p, 0.0, -1);
    EXPECT_EQ(left.psi, 0.0);
    EXPECT_EQ(right.psi, std::numbers::pi);
    EXPECT_NEAR(left.phidot, 1.2 / 0.8, 1e-15);
    EXPECT_NEAR(right.phidot, -1.2 / 0.8, 1e-15);
    EXPECT_EQ(left.sdot, 0);
    // λ = m b χ̇ = -m a φ̇ with Ψ fixed
    EXPECT_NEAR(left.lambda, -2.0 * 0.3 * left.phidot, 1e-15);
    EXPECT_NEAR(left.energy, 0.5 * 2.0 * 1.2 * 1.2, 1e-14);
    expectForces(p, left);
}

TEST(ControlLaw, ModeNamesRoundTrip) {
    EXPECT_EQ(speedModeFromName("energy"), SpeedMode::Energy);
    EXPECT_EQ(speedModeFromName("speed"), SpeedMode::Speed);
    EXPECT_EQ(speedModeName(SpeedMode::Energy), "energy");
    EXPECT_EQ(speedModeName(SpeedMode::Speed), "speed");
    EXPECT_THROW(speedModeFromName("Energy"), InputError);
}
