#pragma once
// The cut time of a geodesic of the sub-Riemannian problem on SE(2) with the metric
// ds^2 + b^2 dphi^2: the first Maxwell time, in closed form per family (docs/physics.md §10).

namespace chaplygin {

/// Cut time of the normalised problem (b = v_T = 1) for the pendulum's modulus
/// k^2 = sin^2 Psi0 + Psidot0^2 (Sachkov, ESAIM: COCV 17 (2011) 293-321):
///   k = 0 (pivoting in place):  pi,
///   0 < k < 1 (libration):      2 K(k), half the pendulum's period,
///   k > 1 (rotation):           2 p1(1/k) / k, p1 the first positive root of
///                               cn p (E(p) - p) - dn p sn p for the modulus 1/k,
///   k = 1 (separatrix, line):   infinity.
/// In seconds it is this times b/v_T.
double unitCutTime(double k);

/// p1(q): the first positive root of cn p (E(am p, q) - p) - dn p sn p, 0 < q < 1. It lies in
/// (K(q), 2 K(q)), where the function goes from -sqrt(1 - q^2) to 2 (K - E) > 0.
double firstRotationMaxwellRoot(double q);

} // namespace chaplygin
