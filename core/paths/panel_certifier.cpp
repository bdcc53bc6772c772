#include "paths/panel_certifier.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace chaplygin {
namespace {

constexpr int kMaxCertifyDepth = 6; // further halvings of a panel whose interpolants fail
constexpr double kEps = 2.220446049250313e-16;
constexpr double kRateTolerance = 1e-13; // as TimeLaw's bound on t over a panel

double maxAbs(const std::array<double, cheb::kPoints>& v) {
    double m = 0;
    for (double x : v)
        m = std::max(m, std::fabs(x));
    return m;
}

// The interpolants of one panel and their error bounds: the larger of twice the coefficient
// tail and the largest deviation from the exact values at the panel's 8 Gauss nodes (points
// the interpolant was not built from). Returns the largest ratio of a bound to its tolerance
// (certified when <= 1); `bound` receives this panel's bounds.
double interpolate(const Curve& c, bool piecewise, const PanelData& d, double lengthScale,
                   PathTable::ChebPanel& out, PathTable::Bounds& bound) {
    using Q = PathTable::Quantity;
    constexpr int N = cheb::kDegree;
    const auto& xs = cheb::points();
    const double half = 0.5 * (d.b - d.a), mid = 0.5 * (d.a + d.b);
    std::array<std::array<double, cheb::kPoints>, PathTable::kQuantities> v{};
    // a curve evaluates a breakpoint with the piece that starts there; the panel's end takes
    // the piece it ends (one ulp inside), so a jump in a derivative stays outside the panel
    const double end = piecewise ? std::nextafter(d.b, d.a) : d.b;
    double prevPhi = 0, kappaNoise = 0, dkappaNoise = 0;
    for (int j = N; j >= 0; --j) { // from the panel's start (xi = -1) so phi unwraps in order
        double u = j == N ? d.a : (j == 0 ? end : mid + half * xs[j]);
        CurvePoint p;
        CurveGeometry g = checkedGeometry(c, u, &p);
        double phi = g.heading;
        if (j != N)
            phi += 2 * std::numbers::pi * std::round((prevPhi - phi) / (2 * std::numbers::pi));
        prevPhi = phi;
        // rounding in kappa and dkappa/ds: the size of the terms that cancel in them
        const double dd = p.dx * p.dx + p.dy * p.dy, d15 = dd * std::sqrt(dd);
        const double nTerms = std::fabs(p.dx * p.ddy) + std::fabs(p.dy * p.ddx);
        kappaNoise = std::max(kappaNoise, 64 * kEps * nTerms / d15);
        dkappaNoise =
            std::max(dkappaNoise,
                     64 * kEps *
                         (std::fabs(p.dx * p.dddy) + std::fabs(p.dy * p.dddx) +
                          3 * nTerms * (std::fabs(p.dx * p.ddx) + std::fabs(p.dy * p.ddy)) / dd) /
                         (d15 * std::sqrt(dd)));
        v[Q::kX][j] = p.x;
        v[Q::kY][j] = p.y;
        v[Q::kPhi][j] = phi;
        v[Q::kKappa][j] = g.kappa;
        v[Q::kDkappa][j] = g.dkappa;
        v[Q::kSpeed][j] = g.speed;
        out.dsdxi[j] = half * g.speed;
        out.kappa[j] = g.kappa;
    }
    std::array<std::array<double, cheb::kPoints + 1>, PathTable::kQuantities> coef{};
    for (int q : {Q::kX, Q::kY, Q::kPhi, Q::kKappa, Q::kDkappa, Q::kSpeed})
        cheb::coefficients(v[q].data(), coef[q].data());
    std::array<double, cheb::kPoints> dsdxiCoef;
    cheb::coefficients(out.dsdxi.data(), dsdxiCoef.data());
    cheb::integrate(dsdxiCoef.data(), cheb::kPoints, coef[Q::kS].data());
    for (int k = 0; k <= cheb::kPoints; ++k)
        for (int q = 0; q < PathTable::kQuantities; ++q)
            out.c[k][q] = coef[q][k];

    auto tail = [&](int q) { return 2 * cheb::tailEstimate(coef[q].data(), cheb::kPoints); };
    double ePos = std::max(tail(Q::kX), tail(Q::kY)), ePhi = tail(Q::kPhi),
           eKappa = tail(Q::kKappa), eDkappa = tail(Q::kDkappa);
    double eS = 2 * half * cheb::tailEstimate(dsdxiCoef.data(), cheb::kPoints);
    for (int i = 0; i < gauss::kPoints; ++i) {
        double f[PathTable::kQuantities];
        cheb::evaluateMany(out.c, gauss::kNodes[i], f);
        const CurvePoint& p = d.points[i];
        CurveGeometry g = geometryOf(p);
        double dphi = g.heading - f[Q::kPhi];
        dphi -= 2 * std::numbers::pi * std::round(dphi / (2 * std::numbers::pi));
        ePos = std::max(ePos, std::hypot(f[Q::kX] - p.x, f[Q::kY] - p.y));
        ePhi = std::max(ePhi, std::fabs(dphi));
        eKappa = std::max(eKappa, std::fabs(f[Q::kKappa] - g.kappa));
        eDkappa = std::max(eDkappa, std::fabs(f[Q::kDkappa] - g.dkappa));
    }
    double f[PathTable::kQuantities];
    cheb::evaluateMany(out.c, 1.0, f);
    eS = std::max(eS, std::fabs(f[Q::kS] - d.length)); // against the Gauss rule's panel length

    const double L = lengthScale;
    const double kappaMax = maxAbs(v[Q::kKappa]);
    const double tolPos =
        std::max({2e-15 * L, 8 * kEps * maxAbs(v[Q::kX]), 8 * kEps * maxAbs(v[Q::kY])});
    const double tolPhi = std::max(1e-14, 8 * kEps * maxAbs(v[Q::kPhi]));
    const double tolKappa = std::max({1e-14 / L, 1e-13 * kappaMax, kappaNoise});
    const double tolDkappa = std::max(
        {1e-14 / (L * L), 1e-13 * kappaMax / L, 1e-12 * maxAbs(v[Q::kDkappa]), dkappaNoise});
    // the time law's integrand for b of the path's size, |r'| sqrt(1 + (L kappa)^2), is
    // resolved as well (larger b may leave panels to exact evaluation, TimeLaw)
    std::array<double, cheb::kPoints> rate, rateCoef;
    std::array<double, cheb::kPoints + 1> rateIntegral;
    for (int j = 0; j < cheb::kPoints; ++j)
        rate[j] = out.dsdxi[j] * std::hypot(1.0, L * out.kappa[j]);
    cheb::coefficients(rate.data(), rateCoef.data());
    cheb::integrate(rateCoef.data(), cheb::kPoints, rateIntegral.data());
    double rateSum = 0; // the integral over the panel
    for (double a : rateIntegral)
        rateSum += a;
    const double tolS = std::max(2e-15 * L, 1e-14 * d.length);
    const double score = std::max(
        {ePos / tolPos, ePhi / tolPhi, eKappa / tolKappa, eDkappa / tolDkappa, eS / tolS,
         4 * cheb::tailEstimate(rateCoef.data(), cheb::kPoints) / (kRateTolerance * rateSum)});
    out.certified = score <= 1;
    out.bound = score;
    bound.position = ePos;
    bound.heading = ePhi;
    bound.kappa = eKappa;
    bound.dkappa = eDkappa;
    bound.arcLength = eS;
    return score;
}

} // namespace

void Certifier::keep(const PanelData& d, const PathTable::ChebPanel& panel,
                     const PathTable::Bounds& b) {
    if (panel.certified) {
        bounds.position = std::max(bounds.position, b.position);
        bounds.heading = std::max(bounds.heading, b.heading);
        bounds.kappa = std::max(bounds.kappa, b.kappa);
        bounds.dkappa = std::max(bounds.dkappa, b.dkappa);
        bounds.arcLength = std::max(bounds.arcLength, b.arcLength);
        bounds.noisePanels += panel.noiseLimited ? 1 : 0;
    } else {
        bounds.exactPanels += 1;
    }
    leaves.push_back(d);
    cheb.push_back(panel);
}

bool Certifier::acceptWhole(const PanelData& d, double stiffTolerance) {
    if (d.a == cuspStart || d.b == cuspEnd)
        return false;
    PathTable::ChebPanel panel;
    PathTable::Bounds b;
    if (interpolate(curve, piecewise, d, lengthScale, panel, b) > 1)
        return false;
    std::array<double, cheb::kPoints> stiff, stiffCoef;
    for (int j = 0; j < cheb::kPoints; ++j)
        stiff[j] = panel.dsdxi[j] * std::hypot(1.0, kStiffScale * lengthScale * panel.kappa[j]);
    cheb::coefficients(stiff.data(), stiffCoef.data());
    if (4 * cheb::tailEstimate(stiffCoef.data(), cheb::kPoints) > stiffTolerance)
        return false;
    keep(d, panel, b);
    return true;
}

void Certifier::certify(const PanelData& d, int depth, double parentScore) {
    PathTable::ChebPanel panel;
    if (d.a == cuspStart || d.b == cuspEnd) {
        // kappa and dkappa/ds grow without bound towards a cusp: no interpolant
        keep(d, panel, {});
        return;
    }
    PathTable::Bounds b;
    double score = interpolate(curve, piecewise, d, lengthScale, panel, b);
    bool noise = score > 1 && depth > 0 && score > 0.25 * parentScore;
    if (score <= 1 || noise || depth >= kMaxCertifyDepth || halvingsLeft == 0) {
        panel.certified = score <= 1 || noise;
        panel.noiseLimited = noise;
        keep(d, panel, b);
        return;
    }
    --halvingsLeft;
    double mid = 0.5 * (d.a + d.b);
    certify(computePanel(curve, d.a, mid, lengthScale), depth + 1, score);
    certify(computePanel(curve, mid, d.b, lengthScale), depth + 1, score);
}

} // namespace chaplygin
