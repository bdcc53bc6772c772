#pragma once

namespace chaplygin {

/// The body relative to the closest point of its path (docs/physics.md §9): the lateral error e
/// (> 0 to the left), the heading error theta = phi - phi_path(s_p), the body's own path curvature
/// kappa_b = phidot/sdot, and the path's kappa, kappa' and kappa'' (d/ds) at s_p.
struct PathError {
    double e = 0, theta = 0, kappaBody = 0;
    double kappa = 0, dkappa = 0, ddkappa = 0;
};

/// The chained form (De Luca, Oriolo, Samson 1998) in the path length s_p: z2 = e,
/// z3 = (1 - kappa e) tan theta = z2', z4 = z3', and z4' = F + G kappa_b' with the body's
/// curvature rate kappa_b' = d kappa_b/ds_p as the input (docs/physics.md §9).
struct ChainedForm {
    double z2 = 0, z3 = 0, z4 = 0;
    double drift = 0; ///< F
    double gain = 0;  ///< G = (1 - kappa e)^2 / cos^3 theta
};
ChainedForm chainedForm(const PathError& err);

/// u = -P^3 z2 - 3 P^2 z3 - 3 P z4: a triple pole at -P in path length,
/// e''' + 3 P e'' + 3 P^2 e' + P^3 e = 0 [P in 1/m].
double triplePoleInput(const ChainedForm& z, double rate);

/// The body curvature rate that makes z4' = u: kappa_b' = (u - F)/G [1/m^2]. The nominal
/// feedforward is its value at zero error, kappa_b' = kappa'.
double curvatureRate(const ChainedForm& z, double u);

/// Psidot from the curvature rate for a body of gyration radius b moving at sdot_p along the path:
/// kappa_b = cot(Psi)/b gives Psidot = -b kappa_bdot/(1 + b^2 kappa_b^2), kappa_bdot =
/// sdot_p kappa_b'.
double psiRateForCurvatureRate(double b, double kappaBody, double sdotPath, double curvatureRate);

} // namespace chaplygin
