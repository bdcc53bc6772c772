#include "control/path_feedback.h"

#include <cmath>

namespace chaplygin {

ChainedForm chainedForm(const PathError& err) {
    // docs/physics.md §9: with q = 1 - kappa e, T = tan theta, S = sec theta,
    // e' = q T, theta' = kappa_b q S - kappa, q' = -kappa' e - kappa q T,
    // z4 = -kappa' e T - kappa q (T^2 + S^2) + kappa_b q^2 S^3
    const double e = err.e, k = err.kappa, k1 = err.dkappa, k2 = err.ddkappa, kb = err.kappaBody;
    const double q = 1 - k * e, T = std::tan(err.theta), S = 1 / std::cos(err.theta);
    const double T2S2 = T * T + S * S, S2 = S * S, S3 = S2 * S;
    const double de = q * T, dtheta = kb * q * S - k, dq = -k1 * e - k * q * T;
    ChainedForm z;
    z.z2 = e;
    z.z3 = q * T;
    z.z4 = -k1 * e * T - k * q * T2S2 + kb * q * q * S3;
    // z4' = G kappa_b' + F, differentiating each term of z4 along s_p
    z.gain = q * q * S3;
    z.drift = -k2 * e * T - k1 * de * T - k1 * e * S2 * dtheta - k1 * q * T2S2 - k * dq * T2S2 -
              4 * k * q * T * S2 * dtheta + kb * q * S3 * (2 * dq + 3 * q * T * dtheta);
    return z;
}

double triplePoleInput(const ChainedForm& z, double rate) {
    const double p = rate;
    return -p * p * p * z.z2 - 3 * p * p * z.z3 - 3 * p * z.z4;
}

double curvatureRate(const ChainedForm& z, double u) {
    return (u - z.drift) / z.gain;
}

double psiRateForCurvatureRate(double b, double kappaBody, double sdotPath, double curvatureRate) {
    const double bk = b * kappaBody;
    return -b * sdotPath * curvatureRate / (1 + bk * bk);
}

} // namespace chaplygin
