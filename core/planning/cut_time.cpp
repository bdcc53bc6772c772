#include "planning/cut_time.h"

#include "numerics/gsl_callback.h"
#include "numerics/safeguarded_newton.h"

#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_sf_elljac.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace chaplygin {

double firstRotationMaxwellRoot(double q) {
    gsl::ensureErrorHandlerOff();
    gsl_sf_result r;
    const double K = gsl::checkedResult(gsl_sf_ellint_Kcomp_e(q, GSL_PREC_DOUBLE, &r), r, "Kcomp");
    const double E = gsl::checkedResult(gsl_sf_ellint_Ecomp_e(q, GSL_PREC_DOUBLE, &r), r, "Ecomp");
    // on (K, 2K) write p = 2K + u, u in (-K, 0): sn p = -sn u, cn p = -cn u, dn p = dn u and
    // E(am p) = 2E + E(am u), so that f and f' = -sn dn (E(p) - p) - cn dn^2 need no reduction
    auto f = [&](double p) {
        const double u = p - 2 * K;
        double sn = 0, cn = 0, dn = 0;
        const int status = gsl_sf_elljac_e(u, q * q, &sn, &cn, &dn);
        gsl::checkedResult(status, gsl_sf_result{sn + cn + dn, 0}, "elljac");
        gsl_sf_result e;
        const double Eu = gsl::checkedResult(
            gsl_sf_ellint_E_e(std::atan2(sn, cn), q, GSL_PREC_DOUBLE, &e), e, "E");
        sn = -sn;
        cn = -cn;
        const double Ep = 2 * E + Eu;
        return NewtonValue{cn * (Ep - p) - dn * sn, -sn * dn * (Ep - p) - cn * dn * dn};
    };
    NewtonCaps caps;
    caps.maxIterations = 200;
    caps.newtonStep = {4e-16, true, 0};
    caps.bracket = {4e-16, true, 0};
    caps.stopAtRoot = true;
    return safeguardedNewton(f, 1.75 * K, {K, 2 * K}, caps).x;
}

double unitCutTime(double k) {
    if (!(k >= 0) || !std::isfinite(k))
        throw std::invalid_argument("unitCutTime: the modulus must be finite and >= 0");
    if (k == 0)
        return std::numbers::pi;
    if (k == 1)
        return std::numeric_limits<double>::infinity();
    gsl::ensureErrorHandlerOff();
    if (k < 1) {
        gsl_sf_result r;
        return 2 * gsl::checkedResult(gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &r), r, "Kcomp");
    }
    const double q = 1 / k;
    return 2 * q * firstRotationMaxwellRoot(q);
}

} // namespace chaplygin
