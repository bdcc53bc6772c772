#include "planning/complementary_elliptic.h"

#include "numerics/gsl_callback.h"

#include <gsl/gsl_sf_ellint.h>

#include <array>
#include <cmath>
#include <limits>

namespace chaplygin {

JacobiValues jacobiComplementary(double u, double mc) {
    constexpr int maxLevels = 16;
    constexpr double eps = std::numeric_limits<double>::epsilon();
    // the arithmetic-geometric mean of a = 1 and b = sqrt(mc) = k'
    std::array<double, maxLevels> a{}, b{};
    a[0] = 1;
    b[0] = std::sqrt(mc);
    int n = 0;
    while (n + 1 < maxLevels && std::fabs(a[n] - b[n]) > 4 * eps * (a[n] + b[n])) {
        a[n + 1] = 0.5 * (a[n] + b[n]);
        b[n + 1] = std::sqrt(a[n] * b[n]);
        ++n;
    }
    // at the mean the functions are circular; descend back to mc through the ratios
    // c_{j-1} = d_j c_j, d_{j-1} = (c_j^2/a_j + b_{j-1})/(c_j^2/a_j + a_{j-1}); the tangent or
    // the cotangent, whichever is at most 1, so that neither end divides by zero
    const double v = u * a[n], s = std::sin(v), c = std::cos(v);
    const bool tangent = std::fabs(s) < std::fabs(c);
    double ratio = a[n] * (tangent ? s / c : c / s), d = 1;
    for (int j = n; j > 0; --j) {
        const double r = ratio * ratio / a[j];
        ratio *= d;
        d = (r + b[j - 1]) / (r + a[j - 1]);
    }
    JacobiValues out;
    if (tangent) {
        // ratio = sn/cn and d = k'/dn (the reflection u -> K - u of the other branch)
        out.dn = b[0] / d;
        const double h = std::hypot(1.0, ratio);
        out.cn = (c < 0 ? -1.0 : 1.0) / (d * h) * b[0];
        out.sn = (c < 0 ? -1.0 : 1.0) * ratio / (d * h);
    } else {
        out.dn = d;
        out.sn = (s < 0 ? -1.0 : 1.0) / std::hypot(1.0, ratio);
        out.cn = ratio * out.sn;
    }
    return out;
}

double completeKComplementary(double mc) {
    gsl::ensureErrorHandlerOff();
    gsl_sf_result r;
    return gsl::checkedResult(gsl_sf_ellint_RF_e(0.0, mc, 1.0, GSL_PREC_DOUBLE, &r), r, "RF");
}

double completeDComplementary(double mc) {
    gsl::ensureErrorHandlerOff();
    gsl_sf_result r;
    return gsl::checkedResult(gsl_sf_ellint_RD_e(0.0, mc, 1.0, GSL_PREC_DOUBLE, &r), r, "RD") / 3;
}

double incompleteFComplementary(double theta, double mc) {
    gsl::ensureErrorHandlerOff();
    const double s = std::sin(theta), c = std::cos(theta);
    gsl_sf_result r;
    const int status = gsl_sf_ellint_RF_e(c * c, c * c + mc * s * s, 1.0, GSL_PREC_DOUBLE, &r);
    return s * gsl::checkedResult(status, r, "RF");
}

double incompleteDComplementary(double theta, double mc) {
    gsl::ensureErrorHandlerOff();
    const double s = std::sin(theta), c = std::cos(theta);
    gsl_sf_result r;
    const int status = gsl_sf_ellint_RD_e(c * c, c * c + mc * s * s, 1.0, GSL_PREC_DOUBLE, &r);
    return s * s * s / 3 * gsl::checkedResult(status, r, "RD");
}

} // namespace chaplygin
