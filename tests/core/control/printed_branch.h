#pragma once

namespace chaplygin {

/// The control angle as the paper prints it, tan(Psi) = rho/b with Psi in (-pi/2, pi/2)
/// (eq. 47 before the erratum): Psi = atan(rho/b). Kept only to show, in the gallery, why it
/// fails: sdot = v_T sin(Psi) turns negative on right turns and Psi jumps by pi at every
/// inflection. The app uses Psi = atan2(1, b kappa) (controlOnCurve).
double printedBranchPsi(double b, double kappa);

} // namespace chaplygin
