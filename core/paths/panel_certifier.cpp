#include "paths/panel_certifier.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace chaplygin {
namespace {

constexpr int kMaxCertifyDepth = 6; // further halvings of a panel whose interpolants fail
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kRateTolerance = 1e-13; // as TimeLaw's bound on t over a panel

// The exact geometry at the degree-kDegree Chebyshev points of a panel, each evaluated on first
// use: a panel tried at kLowDegree and then at kDegree evaluates the curve once per point.
struct ExactAtPoints {
    std::array<CurvePoint, cheb::kPoints> point;
    std::array<CurveGeometry, cheb::kPoints> geometry;
    std::array<bool, cheb::kPoints> done{};
};

void sampleAt(const Curve& c, bool piecewise, const PanelData& d, int j, ExactAtPoints& s) {
    if (s.done[j])
        return;
    // a curve evaluates a breakpoint with the piece that starts there; the panel's end takes
    // the piece it ends (one ulp inside), so a jump in a derivative stays outside the panel
    double u = 0.5 * (d.a + d.b) + 0.5 * (d.b - d.a) * cheb::points()[j];
    if (j == cheb::kDegree)
        u = d.a;
    else if (j == 0)
        u = piecewise ? std::nextafter(d.b, d.a) : d.b;
    s.geometry[j] = checkedGeometry(c, u, &s.point[j]);
    s.done[j] = true;
}

// The multiple of 2 pi nearest to a - b: 0 without calling round() while |a - b| < pi
double turnsBetween(double a, double b) {
    const double d = a - b;
    return std::fabs(d) < std::numbers::pi
               ? 0.0
               : 2 * std::numbers::pi * std::round(d / (2 * std::numbers::pi));
}

// T_k at the positive Gauss nodes x_i = gauss::kNodes[kHalf + i], k = 0..kDegree. The nodes come
// in pairs +-x_i and T_k(-x) = (-1)^k T_k(x): a series is its even part plus or minus its odd part.
constexpr int kHalf = gauss::kPoints / 2;
struct GaussChebyshev {
    std::array<std::array<double, cheb::kPoints>, kHalf> t;
    GaussChebyshev() {
        for (int i = 0; i < kHalf; ++i) {
            const double x = gauss::kNodes[kHalf + i];
            t[i][0] = 1;
            t[i][1] = x;
            for (int k = 2; k < cheb::kPoints; ++k)
                t[i][k] = 2 * x * t[i][k - 1] - t[i][k - 2];
        }
    }
};
const GaussChebyshev& gaussChebyshev() {
    static const GaussChebyshev g;
    return g;
}

// The interpolants of one panel at `degree` and their error bounds: the larger of twice the
// coefficient tail and the largest deviation from the exact values at the panel's 8 Gauss nodes
// (points the interpolant was not built from). Returns the largest ratio of a bound to its
// tolerance (certified when <= 1); `bound` receives this panel's bounds and `stiffBound` the
// error bound of the stiff time-law integrand's interpolant (PanelData::stiff).
double interpolate(const Curve& c, bool piecewise, const PanelData& d, double lengthScale,
                   int degree, ExactAtPoints& exact, Interpolant& out, PathTable::Bounds& bound,
                   double& stiffBound) {
    using Q = PathTable::Quantity;
    // the series transformed together: the quantities, and the time-law integrands for b of the
    // path's size (rate) and kStiffScale times it (stiff)
    enum Column { cX, cY, cPhi, cKappa, cDkappa, cSpeed, cRate, cStiff, cColumns };
    const int n = degree, stride = cheb::kDegree / degree;
    const double half = 0.5 * (d.b - d.a), L = lengthScale;
    out.panel = {};
    out.panel.degree = degree;
    std::array<std::array<double, cColumns>, cheb::kPoints> v; // [i][column] at cos(pi i/n)
    double prevPhi = 0, kappaNoise = 0, dkappaNoise = 0;
    double maxX = 0, maxY = 0, maxPhi = 0, kappaMax = 0, dkappaMax = 0;
    for (int i = n; i >= 0; --i) { // from the panel's start (xi = -1) so phi unwraps in order
        const int j = i * stride;
        sampleAt(c, piecewise, d, j, exact);
        const CurvePoint& p = exact.point[j];
        const CurveGeometry& g = exact.geometry[j];
        const double phi = i == n ? g.heading : g.heading + turnsBetween(prevPhi, g.heading);
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
        const double ds = half * g.speed, lk = L * g.kappa;
        v[i] = {p.x,
                p.y,
                phi,
                g.kappa,
                g.dkappa,
                g.speed,
                ds * hypotOne(lk),
                ds * hypotOne(kStiffScale * lk)};
        out.samples[i] = {ds, g.kappa};
        maxX = std::max(maxX, std::fabs(p.x));
        maxY = std::max(maxY, std::fabs(p.y));
        maxPhi = std::max(maxPhi, std::fabs(phi));
        kappaMax = std::max(kappaMax, std::fabs(g.kappa));
        dkappaMax = std::max(dkappaMax, std::fabs(g.dkappa));
    }
    std::array<std::array<double, cColumns>, cheb::kPoints> coef;
    cheb::coefficientsMany(v.data(), n, coef.data());
    std::array<double, cheb::kPoints> dsdxiCoef;
    for (int k = 0; k <= n; ++k) {
        out.c[k][Q::kX] = coef[k][cX];
        out.c[k][Q::kY] = coef[k][cY];
        out.c[k][Q::kPhi] = coef[k][cPhi];
        out.c[k][Q::kKappa] = coef[k][cKappa];
        out.c[k][Q::kDkappa] = coef[k][cDkappa];
        out.c[k][Q::kSpeed] = coef[k][cSpeed];
        out.c[k][Q::kPadding] = 0;
        dsdxiCoef[k] = half * coef[k][cSpeed];
    }
    std::array<double, cheb::kPoints + 1> sCoef;
    cheb::integrate(dsdxiCoef.data(), n + 1, sCoef.data());
    out.c[n + 1] = {}; // s has one coefficient more than the others
    for (int k = 0; k <= n + 1; ++k)
        out.c[k][Q::kS] = sCoef[k];

    auto tail = [&](int column) {
        return 2 * cheb::tailEstimate(coef.data(), n + 1, static_cast<std::size_t>(column));
    };
    double ePos = std::max(tail(cX), tail(cY)), ePhi = tail(cPhi), eKappa = tail(cKappa),
           eDkappa = tail(cDkappa);
    // s integrates ds/dxi = half ds/du over at most 2 in xi
    double eS = 2 * half * tail(cSpeed);
    // the interpolants of x, y, phi, kappa and dkappa/ds at the Gauss nodes against the exact
    // values there, both nodes +-x_i at once (the columns up to dkappa/ds, with ds/du to make
    // whole pairs)
    constexpr std::size_t kChecked = cSpeed + 1;
    static_assert(cX == 0 && kChecked % 2 == 0, "the checked columns come first");
    const GaussChebyshev& gt = gaussChebyshev();
    for (int i = 0; i < kHalf; ++i) {
        double atPlus[kChecked], atMinus[kChecked];
        cheb::evaluateAtPlusMinus<kChecked>(coef.data(), n + 1, gt.t[i].data(), atPlus, atMinus);
        for (int sign : {1, -1}) {
            const int node = sign > 0 ? kHalf + i : kHalf - 1 - i;
            const double* f = sign > 0 ? atPlus : atMinus;
            const CurveGeometry& g = d.geometry[node];
            const double ex = f[cX] - d.x[node], ey = f[cY] - d.y[node];
            ePos = std::max(ePos, std::sqrt(ex * ex + ey * ey));
            const double dphi = g.heading - f[cPhi] - turnsBetween(g.heading, f[cPhi]);
            ePhi = std::max(ePhi, std::fabs(dphi));
            eKappa = std::max(eKappa, std::fabs(f[cKappa] - g.kappa));
            eDkappa = std::max(eDkappa, std::fabs(f[cDkappa] - g.dkappa));
        }
    }
    double sEnd = 0; // s - s(panel start) at xi = 1: the sum of its coefficients
    for (int k = 0; k <= n + 1; ++k)
        sEnd += sCoef[k];
    eS = std::max(eS, std::fabs(sEnd - d.length)); // against the Gauss rule's panel length

    const double tolPos = std::max({2e-15 * L, 8 * kEps * maxX, 8 * kEps * maxY});
    const double tolPhi = std::max(1e-14, 8 * kEps * maxPhi);
    const double tolKappa = std::max({1e-14 / L, 1e-13 * kappaMax, kappaNoise});
    const double tolDkappa =
        std::max({1e-14 / (L * L), 1e-13 * kappaMax / L, 1e-12 * dkappaMax, dkappaNoise});
    // the time law's integrand for b of the path's size, |r'| sqrt(1 + (L kappa)^2), is
    // resolved as well (larger b may leave panels to exact evaluation, TimeLaw)
    const double rateSum = cheb::integral(coef.data(), n + 1, cRate); // over the panel
    const double tolS = std::max(2e-15 * L, 1e-14 * d.length);
    const double score =
        std::max({ePos / tolPos, ePhi / tolPhi, eKappa / tolKappa, eDkappa / tolDkappa, eS / tolS,
                  2 * tail(cRate) / (kRateTolerance * rateSum)});
    stiffBound = 2 * tail(cStiff);
    out.panel.certified = score <= 1;
    out.panel.bound = score;
    bound.position = ePos;
    bound.heading = ePhi;
    bound.kappa = eKappa;
    bound.dkappa = eDkappa;
    bound.arcLength = eS;
    return score;
}

} // namespace

void Certifier::keep(const PanelData& d, const Interpolant& in, const PathTable::Bounds& b) {
    PathTable::ChebPanel panel = in.panel;
    if (panel.certified) {
        bounds.position = std::max(bounds.position, b.position);
        bounds.heading = std::max(bounds.heading, b.heading);
        bounds.kappa = std::max(bounds.kappa, b.kappa);
        bounds.dkappa = std::max(bounds.dkappa, b.dkappa);
        bounds.arcLength = std::max(bounds.arcLength, b.arcLength);
        bounds.noisePanels += panel.noiseLimited ? 1 : 0;
        panel.row = static_cast<std::uint32_t>(rows.size());
        panel.sample = static_cast<std::uint32_t>(samples.size());
        rows.insert(rows.end(), in.c.begin(), in.c.begin() + panel.degree + 2);
        samples.insert(samples.end(), in.samples.begin(), in.samples.begin() + panel.degree + 1);
    } else {
        bounds.exactPanels += 1;
    }
    leaves.push_back(static_cast<const PanelSums&>(d));
    cheb.push_back(panel);
}

bool Certifier::acceptWhole(const PanelData& d, double stiffTolerance) {
    if (d.a == cuspStart || d.b == cuspEnd)
        return false;
    ExactAtPoints exact;
    for (int degree : {cheb::kLowDegree, cheb::kDegree}) {
        Interpolant panel;
        PathTable::Bounds b;
        double stiffBound = 0;
        if (interpolate(curve, piecewise, d, lengthScale, degree, exact, panel, b, stiffBound) <=
                1 &&
            stiffBound <= stiffTolerance) {
            keep(d, panel, b);
            return true;
        }
    }
    return false;
}

void Certifier::certify(const PanelData& d, int depth, double parentScore) {
    Interpolant panel;
    if (d.a == cuspStart || d.b == cuspEnd) {
        // kappa and dkappa/ds grow without bound towards a cusp: no interpolant
        keep(d, panel, {});
        return;
    }
    PathTable::Bounds b;
    ExactAtPoints exact;
    double stiffBound = 0;
    double score = interpolate(curve, piecewise, d, lengthScale, cheb::kLowDegree, exact, panel, b,
                               stiffBound);
    if (score > 1)
        score = interpolate(curve, piecewise, d, lengthScale, cheb::kDegree, exact, panel, b,
                            stiffBound);
    bool noise = score > 1 && depth > 0 && score > 0.25 * parentScore;
    if (score <= 1 || noise || depth >= kMaxCertifyDepth || halvingsLeft == 0) {
        panel.panel.certified = score <= 1 || noise;
        panel.panel.noiseLimited = noise;
        keep(d, panel, b);
        return;
    }
    --halvingsLeft;
    double mid = 0.5 * (d.a + d.b);
    certify(computePanel(curve, d.a, mid, lengthScale), depth + 1, score);
    certify(computePanel(curve, mid, d.b, lengthScale), depth + 1, score);
}

} // namespace chaplygin
