#pragma once
// The vectors of any body for the canvas's arrows: its pose, velocities and forces.
#include "scene/solution.h"

namespace chaplygin {

/// What the canvas's arrows need of any body (the controlled, the free, or another model's):
/// its pose, its velocities and the forces on it (zero where the body has none). SI units.
struct BodyState {
    double x = 0, y = 0, phi = 0; ///< knife point P and heading
    double sdot = 0, phidot = 0;  ///< [m/s], [rad/s]
    double forceAxial = 0;        ///< control force f_s along s-hat, at the centre of mass [N]
    double knifeReaction = 0;     ///< knife's lateral reaction N along n-hat, at P [N]
    double controlCouple = 0;     ///< control couple tau, counter-clockwise > 0 [N m]
    bool pivot = false;           ///< turning in place about P at a corner
};

/// A vector quantity attached to a point, in world coordinates and physical units.
struct AttachedVector {
    double x = 0, y = 0;   ///< where it acts [m]
    double vx = 0, vy = 0; ///< its components [m/s] or [N]
};

/// The body's vectors in world coordinates (docs/physics.md §1 and §2).
struct BodyVectors {
    AttachedVector knifeVelocity;   ///< sdot s-hat at P
    AttachedVector cmVelocity;      ///< sdot s-hat + a phidot n-hat at C = P + a s-hat
    AttachedVector axialForce;      ///< f_s s-hat at C
    AttachedVector lateralReaction; ///< N n-hat at P
    double cx = 0, cy = 0;          ///< centre of mass C, where the couple acts [m]
    double couple = 0;              ///< tau [N m]
};

/// The controlled body of a sample, with its control forces.
BodyState controlledBodyState(const MotionSample& sample);
/// The free (Lagrange-d'Alembert) body: no control; its knife reaction is
/// N = -mu = m (1 - a^2/b^2) sdot phidot, paper (D15).
BodyState freeBodyState(const DerivedSystem& system, const FreeState& free);

BodyVectors bodyVectors(const DerivedSystem& system, const BodyState& body);

} // namespace chaplygin
