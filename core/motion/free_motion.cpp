#include "motion/free_motion.h"

#include "numerics/chebyshev.h"
#include "numerics/gauss_legendre.h"
#include "systems/system_parameters.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace chaplygin {
namespace {

constexpr double kTailTau = 40.0; // sech(40) < 1e-17

// e^y and e^y - 1 for y <= 0: expm1 only where e^y - 1 would cancel (e^-0.7 ~ 0.5)
void expAndExpm1(double y, double* e, double* em) {
    *e = std::exp(y);
    *em = y > -0.7 ? std::expm1(y) : *e - 1;
}

// sinh(x)/cosh(c + x) without overflow for any x and without cancellation for small x, given
// e^c and e^-c (one exponential per call; |c| <= 300 keeps both finite)
double sinhOverCosh(double x, double c, double expC, double expMinusC) {
    double e, em;
    expAndExpm1(-2 * std::fabs(x), &e, &em);
    if (std::fabs(c) > 300)
        return x >= 0 ? -em / (std::exp(c) + std::exp(-c - 2 * x))
                      : em / (std::exp(c + 2 * x) + std::exp(-c));
    return x >= 0 ? -em / (expC + expMinusC * e) : em / (expC * e + expMinusC);
}

} // namespace

FreeMotion::FreeMotion(const DerivedSystem& system, const FreeInitial& initial, double horizon)
    : m_sys(system), m_init(initial), m_horizon(std::max(horizon, 0.0)) {
    const double b = m_sys.b, a = m_sys.a;
    m_v = std::hypot(initial.sdot, b * initial.phidot);
    if (m_v == 0) {
        m_case = Case::Rest;
        return;
    }
    if (initial.phidot == 0) {
        m_case = Case::Line;
        return;
    }
    if (a == 0) {
        m_case = Case::Circle;
        return;
    }
    m_case = Case::General;
    m_k = a * m_v / (b * b);
    // tanh c = sdot0/V and sech c = b|phidot0|/V, so sinh c = sdot0/(b|phidot0|): well conditioned
    // even when sdot0/V rounds to 1 (tiny curvature), where atanh(sdot0/V) is not
    m_c = std::asinh(initial.sdot / (b * std::fabs(initial.phidot)));
    m_expC = std::exp(m_c);
    m_expMinusC = std::exp(-m_c);
    m_sigma = initial.phidot > 0 ? 1.0 : -1.0;
    m_beta = b / a;
    // past the tail the heading differs from its limit by |beta| 2 e^-|tau|; the position by
    // about beta^2 b 2 e^-|tau|
    double tauEnd =
        kTailTau + 2 * std::log(std::max(1.0, std::fabs(m_beta))) + std::log(std::max(1.0, b));
    if (m_k < 0)
        tauEnd = -tauEnd;
    m_tail = std::max(0.0, (tauEnd - m_c) / m_k);

    // panels narrower than both time scales, up to the horizon or the tail
    double span = std::min(m_tail, m_horizon);
    double width = std::min(0.5 / std::fabs(m_k), b / m_v);
    int panels = std::max(1, static_cast<int>(std::ceil(span / width)));
    m_panelT.assign(1, 0.0);
    m_panelZ.assign(1, {initial.x, initial.y});
    for (int i = 0; i < panels; ++i)
        addPanel(span * i / panels, i + 1 == panels ? span : span * (i + 1) / panels, 0);
}

void FreeMotion::addPanel(double t0, double t1, int depth) {
    constexpr double kEps = std::numeric_limits<double>::epsilon();
    constexpr int kMaxSplits = 3; // a panel whose position is not certified is halved, so often
    const auto& xs = cheb::points();
    // a point between the interpolation points, near an end where the error of an interpolant
    // is largest: the check against the closed forms there
    const double check = std::cos(std::numbers::pi / (2 * cheb::kDegree));
    // dz/dxi = half sdot e^{i phi}, sdot, phidot, phi at t
    auto exact = [&](double t, double half) {
        std::array<double, kSeries> v{};
        velocities(t, &v[kSdot], &v[kPhidot], &v[kPhi]);
        v[kZx] = half * v[kSdot] * std::cos(v[kPhi]);
        v[kZy] = half * v[kSdot] * std::sin(v[kPhi]);
        return v;
    };
    const double half = 0.5 * (t1 - t0), mid = 0.5 * (t1 + t0);
    const std::complex<double> z0 = m_panelZ.back();
    // phi is interpolated as its change from the panel's start, which keeps the rounding
    // of the interpolant at that of the change (the sum rounds once)
    std::array<std::array<double, kSeries>, cheb::kPoints> f, c;
    double phiMax = 0;
    for (int j = 0; j < cheb::kPoints; ++j) {
        f[j] = exact(mid + half * xs[j], half);
        phiMax = std::max(phiMax, std::fabs(f[j][kPhi]));
    }
    const double phiStart = f[cheb::kDegree][kPhi];
    for (int j = 0; j < cheb::kPoints; ++j)
        f[j][kPhi] -= phiStart;
    cheb::coefficientsMany(f.data(), cheb::kDegree, c.data());
    // the position: the integral of the interpolant of dz/dxi
    std::array<double, cheb::kPoints> cx, cy;
    for (int k = 0; k < cheb::kPoints; ++k) {
        cx[k] = c[k][kZx];
        cy[k] = c[k][kZy];
    }
    std::array<double, cheb::kPoints + 1> ix, iy;
    cheb::integrate(cx.data(), cheb::kPoints, ix.data());
    cheb::integrate(cy.data(), cheb::kPoints, iy.data());
    double zx = 0, zy = 0;
    std::array<std::array<double, kSeries>, cheb::kPoints + 1> panel;
    for (int k = 0; k <= cheb::kPoints; ++k) {
        panel[k] = {};
        if (k < cheb::kPoints)
            for (int q : {kSdot, kPhidot, kPhi})
                panel[k][q] = c[k][q];
        panel[k][kZx] = ix[k];
        panel[k][kZy] = iy[k];
        zx += ix[k];
        zy += iy[k];
    }
    // each interpolant's largest error, estimated from its tail and measured at the check
    // point; the position's bound over the panel is twice that of dz/dxi
    std::array<double, kSeries> e = exact(mid + half * check, half);
    e[kPhi] -= phiStart;
    double p[kSeries];
    cheb::evaluateMany(c.data(), cheb::kPoints, check, p);
    auto error = [&](int q) {
        return std::max(
            2 * cheb::tailEstimate(c.data(), cheb::kPoints, static_cast<std::size_t>(q)),
            std::fabs(p[q] - e[q]));
    };
    const double bound = 2 * std::hypot(error(kZx), error(kZy));
    const std::complex<double> dz(zx, zy);
    const bool position =
        bound <= 1e-15 * std::max(std::abs(dz), m_v * half) || bound <= 4e-16 * std::abs(z0 + dz);
    if (!position && depth < kMaxSplits) {
        addPanel(t0, mid, depth + 1);
        addPanel(mid, t1, depth + 1);
        return;
    }
    m_panelT.push_back(t1);
    m_panelZ.push_back(z0 + (position ? dz : panelIntegral(t0, t1)));
    m_panelCheb.push_back(panel);
    m_panelPhi.push_back(phiStart);
    m_positionCertified.push_back(position);
    m_velocityCertified.push_back(error(kSdot) <= 1e-15 * m_v &&
                                  error(kPhidot) <= 1e-15 * m_v / m_sys.b &&
                                  error(kPhi) <= 2 * kEps * (1 + phiMax));
}

void FreeMotion::velocities(double t, double* sdot, double* phidot, double* phi) const {
    const double b = m_sys.b;
    switch (m_case) {
    case Case::Rest:
        *sdot = 0;
        *phidot = 0;
        *phi = m_init.phi;
        return;
    case Case::Line:
        *sdot = m_init.sdot;
        *phidot = 0;
        *phi = m_init.phi;
        return;
    case Case::Circle: // a = 0: sddot = 0, phiddot = 0
        *sdot = m_init.sdot;
        *phidot = m_init.phidot;
        *phi = m_init.phi + m_init.phidot * t;
        return;
    case Case::General: {
        // e = exp(-|tau|), em = e - 1: tanh|tau| = -em (2 + em)/(1 + e^2) keeps its digits for
        // small tau, sech tau = 2e/(1 + e^2) for large tau (1 + em would lose e's); the heading
        // from turn(t), which does not cancel
        const double tau = m_k * t + m_c;
        double e, em;
        expAndExpm1(-std::fabs(tau), &e, &em);
        const double inv = 1 / (1 + e * e), sign = tau < 0 ? -1.0 : 1.0;
        *sdot = sign * m_v * (-em * (2 + em)) * inv;
        *phidot = m_sigma * (m_v / b) * (2 * e * inv);
        *phi = m_init.phi + turn(t);
        return;
    }
    }
}

std::complex<double> FreeMotion::panelIntegral(double t0, double t1) const {
    gauss::Mapped m = gauss::mapTo(t0, t1);
    std::complex<double> z = 0;
    for (int i = 0; i < gauss::kPoints; ++i) {
        double sdot, phidot, phi;
        velocities(m.x[i], &sdot, &phidot, &phi);
        z += m.w[i] * sdot * std::complex<double>(std::cos(phi), std::sin(phi));
    }
    return z;
}

FreeState FreeMotion::at(double t) const {
    FreeState st;
    bool interpolated = false; // the velocities from a panel's interpolants
    std::complex<double> z0(m_init.x, m_init.y), z;
    auto dir0 = [this] { return std::complex<double>(std::cos(m_init.phi), std::sin(m_init.phi)); };
    switch (m_case) {
    case Case::Rest:
        z = z0;
        break;
    case Case::Line:
        z = z0 + m_init.sdot * t * dir0();
        break;
    case Case::Circle: {
        // z = z0 + sdot/(i omega) (e^{i omega t} - 1) e^{i phi0}, with e^{i th} - 1 = -2
        // sin^2(th/2) + i sin th
        double th = m_init.phidot * t, s = std::sin(0.5 * th);
        std::complex<double> em1(-2 * s * s, std::sin(th));
        z = z0 + m_init.sdot / m_init.phidot * std::complex<double>(0, -1) * em1 * dir0();
        break;
    }
    case Case::General: {
        double span = m_panelT.back();
        if (t <= span) {
            auto it = std::upper_bound(m_panelT.begin(), m_panelT.end(), t);
            int k = std::clamp(static_cast<int>(it - m_panelT.begin()) - 1, 0,
                               static_cast<int>(m_panelT.size()) - 2);
            const double a = m_panelT[k], b = m_panelT[k + 1];
            double f[kSeries];
            if (m_positionCertified[k] || m_velocityCertified[k])
                cheb::evaluateMany(m_panelCheb[k], (2 * t - (a + b)) / (b - a), f);
            if (m_velocityCertified[k]) {
                st.sdot = f[kSdot];
                st.phidot = f[kPhidot];
                st.phi = m_panelPhi[k] + f[kPhi];
                interpolated = true;
            }
            z = m_panelZ[k] + (m_positionCertified[k] ? std::complex<double>(f[kZx], f[kZy])
                                                      : panelIntegral(a, t));
        } else if (span >= m_tail) {
            // beyond the tail the heading is constant and |sdot| = V (to 1e-17)
            double sdot, phidot, phi;
            velocities(span, &sdot, &phidot, &phi);
            z = m_panelZ.back() + m_v * (m_k > 0 ? 1.0 : -1.0) * (t - span) *
                                      std::complex<double>(std::cos(phi), std::sin(phi));
        } else {
            // past the tabulated horizon but before the tail: integrate on from the last panel
            z = m_panelZ.back();
            double width = std::min(0.5 / std::fabs(m_k), m_sys.b / m_v);
            double t0 = span, stop = std::min(t, m_tail);
            while (t0 < stop) {
                double t1 = std::min(stop, t0 + width);
                z += panelIntegral(t0, t1);
                t0 = t1;
            }
            if (t > m_tail) {
                double sdot, phidot, phi;
                velocities(m_tail, &sdot, &phidot, &phi);
                z += m_v * (m_k > 0 ? 1.0 : -1.0) * (t - m_tail) *
                     std::complex<double>(std::cos(phi), std::sin(phi));
            }
        }
        break;
    }
    }
    st.x = z.real();
    st.y = z.imag();
    if (!interpolated)
        velocities(t, &st.sdot, &st.phidot, &st.phi);
    st.energy = 0.5 * m_sys.mass * (st.sdot * st.sdot + m_sys.b * m_sys.b * st.phidot * st.phidot);
    st.psi = std::atan2(st.sdot, m_sys.b * st.phidot);
    // backing up on a right turn Psi leaves (pi/2, pi) above pi, continuously (docs/physics.md §4)
    if (std::signbit(st.phidot) && st.psi < 0)
        st.psi += 2 * std::numbers::pi;
    st.chi = st.psi - (m_sys.a / m_sys.b) * st.phi;
    return st;
}

double FreeMotion::turn(double t) const {
    switch (m_case) {
    case Case::Rest:
    case Case::Line:
        return 0;
    case Case::Circle:
        return m_init.phidot * t;
    case Case::General:
        // gd(kt + c) - gd(c) = 2 atan(sinh(kt/2)/cosh(c + kt/2)): no cancellation when beta is
        // large (tiny a) or c is large (tiny curvature)
        return m_sigma * m_beta * 2 *
               std::atan(sinhOverCosh(0.5 * m_k * t, m_c, m_expC, m_expMinusC));
    }
    return 0;
}

double FreeMotion::totalTurn() const {
    switch (m_case) {
    case Case::Rest:
    case Case::Line:
        return 0;
    case Case::Circle:
        return m_init.phidot > 0 ? INFINITY : -INFINITY;
    case Case::General:
        // beta (+-pi/2 - gd(c)), with pi/2 - gd(c) = 2 atan(e^-c) and pi/2 + gd(c) = 2 atan(e^c)
        return m_sigma * m_beta *
               (m_k > 0 ? 2 * std::atan(std::exp(-m_c)) : -2 * std::atan(std::exp(m_c)));
    }
    return 0;
}

std::string FreeMotion::velocityModel() const {
    switch (m_case) {
    case Case::Rest:
        return TRANSLATABLE_TEXT("ModelReport", "closed form (at rest)");
    case Case::Line:
        return TRANSLATABLE_TEXT("ModelReport", "closed form (straight line, phidot0 = 0)");
    case Case::Circle:
        return TRANSLATABLE_TEXT("ModelReport", "closed form (uniform circle, a = 0)");
    case Case::General:
        return TRANSLATABLE_TEXT(
            "ModelReport",
            "closed form (sdot = V tanh, phidot = (V/b) sech); inside the tabulated horizon "
            "from degree-16 interpolants of it, certified to 1e-15 V and 1e-15 V/b");
    }
    return "";
}

std::string FreeMotion::positionModel() const {
    return m_case == Case::General
               ? TRANSLATABLE_TEXT(
                     "ModelReport",
                     "quadrature: per panel the integral of the degree-16 interpolant of sdot e^(i "
                     "phi), certified to 1e-15 of the panel's displacement (Gauss-Legendre where "
                     "not); straight-line tail")
               : TRANSLATABLE_TEXT("ModelReport", "closed form");
}

} // namespace chaplygin
