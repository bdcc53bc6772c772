#include "planning/unit_geodesic.h"

#include "numerics/gsl_callback.h"
#include "planning/complementary_elliptic.h"

#include <gsl/gsl_sf_ellint.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace chaplygin {
namespace {

using std::numbers::pi;

DerivedSystem unitSystem() {
    DerivedSystem s;
    s.mass = 1;
    s.translatingMass = 1;
    s.a = 0;
    s.b = 1;
    return s;
}

// (sdot, phidot) = (sin Psi0, cos Psi0), exact on the axes so that the line and pivoting are
// recognised as such
VakonomicInitial unitInitial(double psi0, double lambda0) {
    VakonomicInitial init;
    if (psi0 == pi / 2 || psi0 == -pi / 2) {
        init.sdot = psi0 > 0 ? 1 : -1;
    } else if (psi0 == pi || psi0 == -pi) {
        init.phidot = -1;
    } else {
        init.sdot = std::sin(psi0);
        init.phidot = std::cos(psi0);
    }
    init.lambda = lambda0; // a = 0, m = b = 1: lambda = lambda_c = Psidot
    return init;
}

double checked(int status, const gsl_sf_result& r, const char* what) {
    if (status != GSL_SUCCESS || !std::isfinite(r.val))
        throw std::runtime_error(std::string("internal error: GSL ") + what + " failed (" +
                                 gsl_strerror(status) + ")");
    return r.val;
}

// F(phi, q) for any phi: F(phi + j pi) = F(phi) + 2 j K
double extendedF(double phi, double q, double K) {
    const double j = std::nearbyint(phi / pi);
    gsl_sf_result r;
    return 2 * j * K + checked(gsl_sf_ellint_F_e(phi - j * pi, q, GSL_PREC_DOUBLE, &r), r, "F");
}

// D(theta, q) = int_0^theta sin^2/sqrt(1 - q^2 sin^2) for any theta: D(theta + j pi) gains
// 2 j D(pi/2); on [-pi/2, pi/2] it is (sin^3/3) R_D(cos^2, 1 - q^2 sin^2, 1)
double extendedD(double theta, double q, double Dc) {
    const double j = std::nearbyint(theta / pi);
    const double th = theta - j * pi;
    const double sn = std::sin(th), cn = std::cos(th);
    gsl_sf_result r;
    const int status = gsl_sf_ellint_RD_e(cn * cn, 1 - q * q * sn * sn, 1.0, GSL_PREC_DOUBLE, &r);
    return 2 * j * Dc + sn * sn * sn / 3 * checked(status, r, "RD");
}

double positiveRemainder(double a, double period) {
    double r = std::fmod(a, period);
    return r < 0 ? r + period : r;
}

} // namespace

UnitGeodesic::UnitGeodesic(double psi0, double lambda0)
    : UnitGeodesic(psi0, lambda0, [&] {
          const double c0 = unitInitial(psi0, lambda0).phidot;
          return (c0 - lambda0) * (c0 + lambda0);
      }()) {}

UnitGeodesic::UnitGeodesic(double psi0, double lambda0, double gap)
    : m_psi0(psi0), m_lambda0(lambda0), m_gap(gap) {
    const VakonomicInitial init = unitInitial(psi0, lambda0);
    const double S0 = init.sdot, C0 = init.phidot, L0 = lambda0;
    const bool line = C0 == 0 && (L0 == 0 || S0 * S0 + L0 * L0 == 1);
    if (line || gap == 0 || (S0 == 0 && L0 == 0)) {
        m_motion.emplace(unitSystem(), init);
        m_kind = m_motion->kind();
        m_k = m_motion->modulus();
        return;
    }
    // k from whichever of k^2 and 1 - k^2 is known to its last digits
    m_k = gap > 0.5 ? std::sqrt(S0 * S0 + L0 * L0) : std::sqrt(1 - gap);
    if (gap > 0) {
        // libration: sn w = eps sin Psi/k, cn w = Lambda/k, w = w0 + t (docs/physics.md §8)
        m_kind = VakonomicMotion::Case::Libration;
        m_mc = gap;
        m_sign = C0 >= 0 ? 1.0 : -1.0;
        m_am0 = std::atan2(m_sign * S0, L0);
        m_rate = 1;
    } else {
        // rotation: Psi = sigma am(W, 1/k), W = W0 + k t, parameter 1/k^2 = 1 - mc
        m_kind = VakonomicMotion::Case::Rotation;
        m_mc = -gap / (1 - gap);
        m_sign = L0 >= 0 ? 1.0 : -1.0;
        m_am0 = m_sign * std::atan2(S0, C0);
        m_rate = m_k;
    }
    m_K = completeKComplementary(m_mc);
    m_D = completeDComplementary(m_mc);
    const double j = std::nearbyint(m_am0 / pi);
    m_w0 = 2 * j * m_K + incompleteFComplementary(m_am0 - j * pi, m_mc);
    m_d0 = 2 * j * m_D + incompleteDComplementary(m_am0 - j * pi, m_mc);
    m_sn0 = std::sin(m_am0);
    m_cn0 = std::cos(m_am0);
    m_dn0 = std::sqrt(m_cn0 * m_cn0 + m_mc * m_sn0 * m_sn0);
    m_heading0 = gap > 0 ? m_am0 : std::atan2(m_sn0 / m_k, m_dn0);
}

UnitGeodesicPoint UnitGeodesic::at(double t) const {
    if (m_motion) {
        const VakonomicState s = m_motion->at(t);
        return {s.x, s.y, s.phi, s.sdot, s.phidot};
    }
    // w reduced to [-K, K], where cn >= 0: sn(r + 2jK) = (-1)^j sn(r), likewise cn
    const double w = m_w0 + m_rate * t;
    const double j = std::nearbyint(w / (2 * m_K));
    JacobiValues e = jacobiComplementary(w - 2 * j * m_K, m_mc);
    const double am = j * pi + std::atan2(e.sn, e.cn);
    // D(am w) = 2 j D(pi/2) + (sn^3/3) R_D(cn^2, dn^2, 1)
    gsl_sf_result r;
    const int status = gsl_sf_ellint_RD_e(e.cn * e.cn, e.dn * e.dn, 1.0, GSL_PREC_DOUBLE, &r);
    const double d = 2 * j * m_D + e.sn * e.sn * e.sn / 3 * checked(status, r, "RD");
    if (std::fmod(std::fabs(j), 2.0) == 1.0) {
        e.sn = -e.sn;
        e.cn = -e.cn;
    }
    UnitGeodesicPoint p;
    if (m_kind == VakonomicMotion::Case::Libration) {
        // phi = eps (am w - am w0); z = k e^{i alpha}[eps (sn^2 - sn0^2)/(dn + dn0)
        // + i (D(am w) - D(am w0))], alpha = -eps am w0
        const double eps = m_sign, alpha = -eps * m_am0;
        const double re = eps * (e.sn - m_sn0) * (e.sn + m_sn0) / (e.dn + m_dn0), im = d - m_d0;
        p.x = m_k * (std::cos(alpha) * re - std::sin(alpha) * im);
        p.y = m_k * (std::sin(alpha) * re + std::cos(alpha) * im);
        p.phi = eps * (am - m_am0);
        p.sinPsi = eps * m_k * e.sn;
        p.cosPsi = eps * e.dn;
    } else {
        // phi = beta - beta0, beta = asin(q sn W); z = sigma q e^{-i beta0}[-(cn - cn0)
        // + i q (D(am W) - D(am W0))]
        const double q = 1 / m_k, sigma = m_sign, beta0 = m_heading0;
        const double re = -(e.cn - m_cn0), im = q * (d - m_d0);
        p.x = sigma * q * (std::cos(beta0) * re + std::sin(beta0) * im);
        p.y = sigma * q * (-std::sin(beta0) * re + std::cos(beta0) * im);
        p.phi = std::atan2(q * e.sn, e.dn) - beta0;
        p.sinPsi = sigma * e.sn;
        p.cosPsi = e.cn;
    }
    return p;
}

std::optional<PendulumPassage> UnitGeodesic::passage(double sinPsi1, double cosPsi1,
                                                     double lambda1) const {
    const auto kind = m_kind;
    if (kind != VakonomicMotion::Case::Libration && kind != VakonomicMotion::Case::Rotation)
        return std::nullopt;
    return pendulumPassage(m_psi0, m_lambda0, sinPsi1, cosPsi1, lambda1);
}

std::optional<PendulumPassage> pendulumPassage(double psi0, double lambda0, double sinPsi1,
                                               double cosPsi1, double lambda1) {
    gsl::ensureErrorHandlerOff();
    const VakonomicInitial init = unitInitial(psi0, lambda0);
    const double S0 = init.sdot, C0 = init.phidot, L0 = lambda0;
    const double k2 = S0 * S0 + L0 * L0;
    if (k2 == 0 || k2 == 1)
        return std::nullopt;
    const double k = std::sqrt(k2);
    gsl_sf_result r;
    PendulumPassage p;
    if (k2 < 1) {
        // sn w = sin am w = eps sin Psi / k, cn w = Lambda / k (docs/physics.md §8), w = w0 + t
        const double eps = C0 >= 0 ? 1.0 : -1.0;
        if ((cosPsi1 >= 0 ? 1.0 : -1.0) != eps)
            return std::nullopt;
        const double K = checked(gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &r), r, "Kcomp");
        const double Dc = checked(gsl_sf_ellint_Dcomp_e(k, GSL_PREC_DOUBLE, &r), r, "Dcomp");
        const double am0 = std::atan2(eps * S0, L0), am1 = std::atan2(eps * sinPsi1, lambda1);
        const double w0 = extendedF(am0, k, K), w1 = extendedF(am1, k, K);
        p.period = 4 * K;
        p.t = positiveRemainder(w1 - w0, p.period);
        // am w1 for w1 = w0 + t: F(am + j pi) = F(am) + 2 j K
        const double am1t = am1 + pi * std::nearbyint((w0 + p.t - w1) / (2 * K));
        // z = k e^{i alpha}[eps (sn^2 - sn0^2)/(dn + dn0) + i (D(am w) - D(am w0))],
        // alpha = -eps am0, dn = |cos Psi|
        const double alpha = -eps * am0;
        const double sn0 = std::sin(am0), sn1 = std::sin(am1t);
        const double re = eps * (sn1 - sn0) * (sn1 + sn0) / (std::fabs(cosPsi1) + std::fabs(C0));
        const double im = extendedD(am1t, k, Dc) - extendedD(am0, k, Dc);
        p.x = k * (std::cos(alpha) * re - std::sin(alpha) * im);
        p.y = k * (std::sin(alpha) * re + std::cos(alpha) * im);
        // over 4K, D(am w) gains 4 D(pi/2): z gains k e^{i alpha} i 4 D
        const double len = 4 * k * Dc;
        p.driftX = -len * std::sin(alpha);
        p.driftY = len * std::cos(alpha);
    } else {
        // Psi = sigma am(W, q), q = 1/k, W = W0 + k t
        const double sigma = L0 >= 0 ? 1.0 : -1.0;
        if ((lambda1 >= 0 ? 1.0 : -1.0) != sigma)
            return std::nullopt;
        const double q = std::sqrt(1 / k2);
        const double K = checked(gsl_sf_ellint_Kcomp_e(q, GSL_PREC_DOUBLE, &r), r, "Kcomp");
        const double Dc = checked(gsl_sf_ellint_Dcomp_e(q, GSL_PREC_DOUBLE, &r), r, "Dcomp");
        const double a0 = sigma * std::atan2(S0, C0);
        const double a1 = a0 + positiveRemainder(sigma * std::atan2(sinPsi1, cosPsi1) - a0, 2 * pi);
        const double W0 = extendedF(a0, q, K);
        const double W1 = extendedF(a1, q, K);
        p.period = 4 * K / k;
        p.t = (W1 - W0) / k;
        // z = sigma q e^{i alpha}[-(cn - cn0) + i q (D(am W) - D(am W0))], alpha = -beta0,
        // beta0 = atan2(q sn W0, dn W0), sn W0 = sin a0
        const double snW0 = std::sin(a0);
        const double beta0 = std::atan2(q * snW0, std::sqrt(1 - q * q * snW0 * snW0));
        const double re = -(std::cos(a1) - std::cos(a0));
        const double im = q * (extendedD(a1, q, Dc) - extendedD(a0, q, Dc));
        p.x = sigma * q * (std::cos(beta0) * re + std::sin(beta0) * im);
        p.y = sigma * q * (-std::sin(beta0) * re + std::cos(beta0) * im);
        // over 4K, D(am W) gains 4 D(pi/2): z gains sigma q^2 e^{-i beta0} i 4 D
        const double len = sigma * q * q * 4 * Dc;
        p.driftX = len * std::sin(beta0);
        p.driftY = len * std::cos(beta0);
    }
    return p;
}

} // namespace chaplygin
