#include "motion/vakonomic_motion.h"

#include "numerics/gsl_callback.h"
#include "systems/system_parameters.h"

#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_sf_elljac.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace chaplygin {
namespace {

using std::numbers::pi;
using Complex = std::complex<double>;

double completeK(double q) {
    gsl_sf_result r;
    int status = gsl_sf_ellint_Kcomp_e(q, GSL_PREC_DOUBLE, &r);
    return gsl::checkedResult(status, r, "ellint_Kcomp");
}

// D(pi/2, q) = (K - E)/q^2 = int_0^{pi/2} sin^2/sqrt(1 - q^2 sin^2)
double completeD(double q) {
    gsl_sf_result r;
    int status = gsl_sf_ellint_Dcomp_e(q, GSL_PREC_DOUBLE, &r);
    return gsl::checkedResult(status, r, "ellint_Dcomp");
}

// F(phi, q) for any phi: F(phi + j pi) = F(phi) + 2 j K
double extendedF(double phi, double q, double K) {
    double j = std::nearbyint(phi / pi);
    gsl_sf_result r;
    int status = gsl_sf_ellint_F_e(phi - j * pi, q, GSL_PREC_DOUBLE, &r);
    double f = gsl::checkedResult(status, r, "ellint_F");
    return 2 * j * K + f;
}

// sn, cn, dn at w, am(w) unwrapped, and D(am w) = int_0^w sn^2 du (no cancellation for small q)
struct Elliptic {
    double sn, cn, dn, am, d;
};
Elliptic elliptic(double w, double q, double K, double D) {
    // reduce to r in [-K, K], where cn >= 0: sn(r + 2jK) = (-1)^j sn(r), likewise cn
    double j = std::nearbyint(w / (2 * K));
    double r = w - 2 * K * j;
    Elliptic e;
    int status = gsl_sf_elljac_e(r, q * q, &e.sn, &e.cn, &e.dn);
    gsl::checkedResult(status, gsl_sf_result{e.sn + e.cn + e.dn, 0}, "elljac");
    e.am = j * pi + std::atan2(e.sn, e.cn);
    // D(theta) = (sin^3 theta/3) R_D(cos^2 theta, 1 - q^2 sin^2 theta, 1), theta = am r
    gsl_sf_result rd;
    double cn2 = std::max(e.cn * e.cn, 0.0);
    status = gsl_sf_ellint_RD_e(cn2, e.dn * e.dn, 1.0, GSL_PREC_DOUBLE, &rd);
    gsl::checkedResult(status, rd, "ellint_RD");
    e.d = 2 * j * D + e.sn * e.sn * e.sn / 3 * rd.val;
    if (std::fmod(std::fabs(j), 2.0) == 1.0) {
        e.sn = -e.sn;
        e.cn = -e.cn;
    }
    return e;
}

double sech(double tau) {
    return 1.0 / std::cosh(tau);
}

} // namespace

VakonomicMotion::VakonomicMotion(const DerivedSystem& system, const VakonomicInitial& initial)
    : m_sys(system), m_init(initial) {
    gsl::ensureErrorHandlerOff();
    const double b = m_sys.b, m = m_sys.mass;
    m_lambdaC0 = initial.lambda + m * m_sys.a * initial.phidot; // lambda_c = lambda + m a phidot
    const double Lambda0 = m_lambdaC0 / (m * b);                // Psidot(0) = lambda_c/(m b)
    m_vT = std::hypot(initial.sdot, b * initial.phidot);
    if (m_vT == 0) {
        m_case = Case::Rest;
        return;
    }
    m_omega = m_vT / b;
    m_psi0 = std::atan2(initial.sdot, b * initial.phidot);
    if (initial.phidot == 0 && Lambda0 == 0) {
        m_case = Case::Line;
        return;
    }
    // the pendulum 2Psi'' = -omega^2 sin 2Psi has modulus k^2 = sin^2 Psi0 + (Psidot0/omega)^2
    const double S0 = initial.sdot / m_vT, L0 = Lambda0 / m_omega;
    const double k2 = S0 * S0 + L0 * L0;
    if (initial.phidot == 0 && k2 == 1) {
        // Psi0 = +-pi/2 with |Psidot0/omega| below the rounding of k^2 (a straight start whose
        // curvature's rate is rounding): the separatrix's tau0 = asinh(sdot/(b phidot)) would be
        // infinite; the motion is the straight line within the rounding (docs/physics.md §8)
        m_case = Case::Line;
        return;
    }
    m_k = std::sqrt(k2);
    m_eps = initial.phidot >= 0 ? 1.0 : -1.0;
    m_sigma = Lambda0 >= 0 ? 1.0 : -1.0;
    if (k2 < 1) {
        // sin(Psi - Psi_c) = k sn(w), w = w0 + omega t, Psi_c = 0 or pi; Psidot = k omega cn
        m_case = Case::Libration;
        m_q = m_k; // sqrt(k2) < 1 for k2 < 1 (correctly rounded sqrt)
        m_K = completeK(m_q);
        m_D = completeD(m_q);
        m_rate = m_omega;
        m_am0 = std::atan2(m_eps * S0, L0); // sn(w0) = eps S0/k, cn(w0) = L0/k
        m_w0 = extendedF(m_am0, m_q, m_K);
    } else if (k2 > 1) {
        // Psi = sigma am(W, 1/k), W = W0 + k omega t; Psidot = sigma k omega dn
        m_case = Case::Rotation;
        m_q = std::sqrt(1 / k2); // < 1 for every k2 > 1, unlike 1/sqrt(k2)
        m_K = completeK(m_q);
        m_D = completeD(m_q);
        m_rate = m_k * m_omega;
        m_w0 = extendedF(m_sigma * m_psi0, m_q, m_K);
    } else {
        // Psi - Psi_c = gd(tau), tau = tau0 + sigma omega t
        m_case = Case::Separatrix;
        m_w0 = std::asinh(initial.sdot / (b * initial.phidot));
        m_rate = m_sigma * m_omega;
        m_am0 = std::atan(std::sinh(m_w0));
        m_sn0 = std::tanh(m_w0);
        m_cn0 = sech(m_w0);
        return;
    }
    Elliptic e0 = elliptic(m_w0, m_q, m_K, m_D);
    m_sn0 = e0.sn;
    m_cn0 = e0.cn;
    m_dn0 = e0.dn;
    m_d0 = e0.d;
    if (m_case == Case::Rotation)
        m_am0 = std::atan2(m_q * e0.sn, e0.dn);
}

VakonomicState VakonomicMotion::at(double t) const {
    const double b = m_sys.b, m = m_sys.mass, vT = m_vT;
    const Complex z0(m_init.x, m_init.y);
    VakonomicState st;
    Complex z = z0;
    switch (m_case) {
    case Case::Rest: // lambda_c_dot = 0, Psi'' = 0
        st.phi = m_init.phi;
        st.psidot = m_lambdaC0 / (m * b);
        st.psi = st.psidot * t;
        break;
    case Case::Line:
        st.sdot = m_init.sdot;
        st.phi = m_init.phi;
        st.psi = m_psi0;
        z += m_init.sdot * t * Complex(std::cos(m_init.phi), std::sin(m_init.phi));
        break;
    case Case::Libration: {
        Elliptic e = elliptic(m_w0 + m_rate * t, m_q, m_K, m_D);
        const double k = m_q;
        st.psi = (m_eps > 0 ? 0.0 : pi) + std::atan2(k * e.sn, e.dn);
        st.psidot = k * m_omega * e.cn;
        st.sdot = m_eps * vT * k * e.sn;
        st.phidot = m_eps * m_omega * e.dn;
        // phi = phi0 + eps (am w - am w0), since int dn dw = am w
        st.phi = m_init.phi + m_eps * (e.am - m_am0);
        // z = z0 + b k e^{i alpha}[eps (sn^2 - sn0^2)/(dn + dn0) + i (D(w) - D(w0))],
        // alpha = phi0 - eps am w0 (int sn cn = -dn/k^2, int sn^2 = D)
        const double alpha = m_init.phi - m_eps * m_am0;
        Complex bracket(m_eps * (e.sn * e.sn - m_sn0 * m_sn0) / (e.dn + m_dn0), e.d - m_d0);
        z += b * k * Complex(std::cos(alpha), std::sin(alpha)) * bracket;
        break;
    }
    case Case::Rotation: {
        Elliptic e = elliptic(m_w0 + m_rate * t, m_q, m_K, m_D);
        const double q = m_q;
        st.psi = m_sigma * e.am;
        st.psidot = m_sigma * m_k * m_omega * e.dn;
        st.sdot = m_sigma * vT * e.sn;
        st.phidot = m_omega * e.cn;
        // phi = phi0 + asin(q sn W) - asin(q sn W0), since int cn dW = asin(q sn)/q
        const double beta = std::atan2(q * e.sn, e.dn);
        st.phi = m_init.phi + beta - m_am0;
        // z = z0 + sigma q b e^{i alpha}[-(cn - cn0) + i q (D(W) - D(W0))], alpha = phi0 - beta0
        const double alpha = m_init.phi - m_am0;
        Complex bracket(-(e.cn - m_cn0), q * (e.d - m_d0));
        z += m_sigma * q * b * Complex(std::cos(alpha), std::sin(alpha)) * bracket;
        break;
    }
    case Case::Separatrix: {
        const double tau = m_w0 + m_rate * t, th = std::tanh(tau), sh = sech(tau);
        const double es = m_eps * m_sigma;
        st.psi = (m_eps > 0 ? 0.0 : pi) + std::atan(std::sinh(tau));
        st.psidot = m_sigma * m_omega * sh;
        st.sdot = m_eps * vT * th;
        st.phidot = m_eps * m_omega * sh;
        st.phi = m_init.phi + es * (std::atan(std::sinh(tau)) - m_am0);
        // z = z0 + b e^{i alpha}[-eps sigma (sech - sech0) + i ((tau - tau0) - (tanh - tanh0))]
        const double alpha = m_init.phi - es * m_am0;
        Complex bracket(-es * (sh - m_cn0), (tau - m_w0) - (th - m_sn0));
        z += b * Complex(std::cos(alpha), std::sin(alpha)) * bracket;
        break;
    }
    }
    st.x = z.real();
    st.y = z.imag();
    // lambda_c = m b Psidot, lambda = lambda_c - m a phidot (docs/physics.md §2)
    st.lambda = m * b * st.psidot - m * m_sys.a * st.phidot;
    st.chi = st.psi - (m_sys.a / b) * st.phi;
    st.energy = 0.5 * m * (st.sdot * st.sdot + b * b * st.phidot * st.phidot);
    return st;
}

std::string VakonomicMotion::model() const {
    switch (m_case) {
    case Case::Rest:
        return TRANSLATABLE_TEXT("ModelReport", "closed form (at rest)");
    case Case::Line:
        return TRANSLATABLE_TEXT(
            "ModelReport",
            "closed form (straight line: Psi = pi/2, Psidot = 0, an unstable equilibrium)");
    case Case::Libration:
        return "closed form (Jacobi elliptic, libration k = " + std::to_string(m_k) +
               ": Psi, phi = am, position through the elliptic integral D)";
    case Case::Rotation:
        return "closed form (Jacobi elliptic, rotation k = " + std::to_string(m_k) +
               ": Psi = am, phi = asin(sn/k), position through the elliptic integral D)";
    case Case::Separatrix:
        return TRANSLATABLE_TEXT(
            "ModelReport",
            "closed form (separatrix k = 1: Psi = gd(tau), position in tanh and sech)");
    }
    return "";
}

} // namespace chaplygin
