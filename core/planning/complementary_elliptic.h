#pragma once
// Jacobi's elliptic functions and the elliptic integrals of parameter m = 1 - mc, given by the
// complementary parameter mc itself, so that nothing cancels next to m = 1: the pendulum next to
// its separatrix, where 1 - m falls like e^{-d/b} for a target d away (docs/physics.md §10).

namespace chaplygin {

struct JacobiValues {
    double sn = 0, cn = 1, dn = 1;
};

/// sn, cn, dn of u for the parameter 1 - mc, 0 < mc <= 1: the descending Gauss (Landen)
/// transformation from the arithmetic-geometric mean of 1 and sqrt(mc).
JacobiValues jacobiComplementary(double u, double mc);

/// K = R_F(0, mc, 1).
double completeKComplementary(double mc);

/// D(pi/2) = (K - E)/m = R_D(0, mc, 1)/3.
double completeDComplementary(double mc);

/// F(theta) = int_0^theta 1/sqrt(1 - m sin^2) for |theta| <= pi/2, through
/// 1 - m sin^2 = cos^2 + mc sin^2: sin R_F(cos^2, cos^2 + mc sin^2, 1).
double incompleteFComplementary(double theta, double mc);

/// D(theta) = int_0^theta sin^2/sqrt(1 - m sin^2) for |theta| <= pi/2:
/// (sin^3/3) R_D(cos^2, cos^2 + mc sin^2, 1).
double incompleteDComplementary(double theta, double mc);

} // namespace chaplygin
