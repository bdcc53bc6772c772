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

// The series transformed together: the table's quantities, and the time-law integrands for b of
// the path's size (rate) and kStiffScale times it (stiff)
enum Column { cX, cY, cPhi, cKappa, cDkappa, cSpeed, cRate, cStiff, cColumns };
using Columns = std::array<std::array<double, cColumns>, cheb::kPoints>;

// The exact geometry at the degree-kDegree Chebyshev points of a panel, each evaluated on first
// use: a panel tried at kLowDegree and then at kDegree evaluates the curve once per point.
struct ExactAtPoints {
    const Curve& curve;
    bool piecewise; // the curve has breakpoints
    const PanelData& panel;
    std::array<CurvePoint, cheb::kPoints> point{};
    std::array<CurveGeometry, cheb::kPoints> geometry{};
    std::array<bool, cheb::kPoints> done{};

    void evaluate(int j) {
        if (done[j])
            return;
        // a curve evaluates a breakpoint with the piece that starts there; the panel's end takes
        // the piece it ends (one ulp inside), so a jump in a derivative stays outside the panel
        const PanelData& d = panel;
        double u = 0.5 * (d.a + d.b) + 0.5 * (d.b - d.a) * cheb::points()[j];
        if (j == cheb::kDegree)
            u = d.a;
        else if (j == 0)
            u = piecewise ? std::nextafter(d.b, d.a) : d.b;
        geometry[j] = checkedGeometry(curve, u, &point[j]);
        done[j] = true;
    }
};

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

// The exact values at the Chebyshev points of one degree, with what the tolerances need: the
// largest values, and the rounding noise of kappa and dkappa/ds (the size of the terms that
// cancel in them)
struct PointValues {
    Columns v; // [i][column] at cos(pi i/degree)
    std::array<PathTable::Sample, cheb::kPoints> samples;
    double maxX = 0, maxY = 0, maxPhi = 0, kappaMax = 0, dkappaMax = 0;
    double kappaNoise = 0, dkappaNoise = 0;
};

PointValues valuesAtPoints(ExactAtPoints& exact, double lengthScale, int degree) {
    const int n = degree, stride = cheb::kDegree / degree;
    const double half = 0.5 * (exact.panel.b - exact.panel.a), L = lengthScale;
    PointValues out;
    double prevPhi = 0;
    for (int i = n; i >= 0; --i) { // from the panel's start (xi = -1) so phi unwraps in order
        const int j = i * stride;
        exact.evaluate(j);
        const CurvePoint& p = exact.point[j];
        const CurveGeometry& g = exact.geometry[j];
        const double phi = i == n ? g.heading : g.heading + turnsBetween(prevPhi, g.heading);
        prevPhi = phi;
        const double dd = p.dx * p.dx + p.dy * p.dy, d15 = dd * std::sqrt(dd);
        const double nTerms = std::fabs(p.dx * p.ddy) + std::fabs(p.dy * p.ddx);
        out.kappaNoise = std::max(out.kappaNoise, 64 * kEps * nTerms / d15);
        out.dkappaNoise =
            std::max(out.dkappaNoise,
                     64 * kEps *
                         (std::fabs(p.dx * p.dddy) + std::fabs(p.dy * p.dddx) +
                          3 * nTerms * (std::fabs(p.dx * p.ddx) + std::fabs(p.dy * p.ddy)) / dd) /
                         (d15 * std::sqrt(dd)));
        const double ds = half * g.speed, lk = L * g.kappa;
        out.v[i] = {p.x,
                    p.y,
                    phi,
                    g.kappa,
                    g.dkappa,
                    g.speed,
                    ds * hypotOne(lk),
                    ds * hypotOne(kStiffScale * lk)};
        out.samples[i] = {ds, g.kappa};
        out.maxX = std::max(out.maxX, std::fabs(p.x));
        out.maxY = std::max(out.maxY, std::fabs(p.y));
        out.maxPhi = std::max(out.maxPhi, std::fabs(phi));
        out.kappaMax = std::max(out.kappaMax, std::fabs(g.kappa));
        out.dkappaMax = std::max(out.dkappaMax, std::fabs(g.dkappa));
    }
    return out;
}

// The Chebyshev coefficients of every column at one degree, and those of s - s(panel start), the
// integral of ds/dxi = half ds/du (one coefficient more than the others)
struct Series {
    int degree = cheb::kDegree;
    Columns coef;
    std::array<double, cheb::kPoints + 1> s;

    // twice the tail estimate of a column
    double tail(int column) const {
        return 2 * cheb::tailEstimate(coef.data(), degree + 1, static_cast<std::size_t>(column));
    }
};

Series seriesOf(const PointValues& values, double half, int degree) {
    Series out; // only the coefficients up to the degree are written
    out.degree = degree;
    const int n = degree;
    cheb::coefficientsMany(values.v.data(), n, out.coef.data());
    std::array<double, cheb::kPoints> dsdxiCoef;
    for (int k = 0; k <= n; ++k)
        dsdxiCoef[k] = half * out.coef[k][cSpeed];
    cheb::integrate(dsdxiCoef.data(), n + 1, out.s.data());
    return out;
}

// The panel's rows as the table keeps them (PathTable::Quantity) and its samples, written into
// the fit in place (returning the 1.2 KB of rows cost a tabulation 1 % more instructions)
void pack(const Series& series, const PointValues& values, Interpolant& out) {
    using Q = PathTable::Quantity;
    const int n = series.degree;
    for (int k = 0; k <= n; ++k) {
        const auto& c = series.coef[k];
        out.c[k][Q::kX] = c[cX];
        out.c[k][Q::kY] = c[cY];
        out.c[k][Q::kPhi] = c[cPhi];
        out.c[k][Q::kKappa] = c[cKappa];
        out.c[k][Q::kDkappa] = c[cDkappa];
        out.c[k][Q::kSpeed] = c[cSpeed];
        out.c[k][Q::kPadding] = 0;
    }
    out.c[n + 1] = {}; // s has one coefficient more than the others
    for (int k = 0; k <= n + 1; ++k)
        out.c[k][Q::kS] = series.s[k];
    for (int i = 0; i <= n; ++i)
        out.samples[i] = values.samples[i];
    out.panel = {};
    out.panel.degree = n;
}

// The interpolants' error bounds: the larger of twice the coefficient tail and the largest
// deviation from the exact values at the panel's 8 Gauss nodes (points the interpolants were not
// built from); s also against the Gauss rule's panel length
PathTable::Bounds errorBounds(const Series& series, const PanelData& d) {
    const int n = series.degree;
    const double half = 0.5 * (d.b - d.a);
    double ePos = std::max(series.tail(cX), series.tail(cY)), ePhi = series.tail(cPhi),
           eKappa = series.tail(cKappa), eDkappa = series.tail(cDkappa);
    // s integrates ds/dxi = half ds/du over at most 2 in xi
    double eS = 2 * half * series.tail(cSpeed);
    // x, y, phi, kappa and dkappa/ds at both Gauss nodes +-x_i at once (with ds/du to make whole
    // pairs)
    constexpr std::size_t kChecked = cSpeed + 1;
    static_assert(cX == 0 && kChecked % 2 == 0, "the checked columns come first");
    const GaussChebyshev& gt = gaussChebyshev();
    for (int i = 0; i < kHalf; ++i) {
        cheb::evaluateAtPlusMinus<kChecked>(
            series.coef.data(), n + 1, gt.t[i].data(), [&](int sign, const double* f) {
                const int node = sign > 0 ? kHalf + i : kHalf - 1 - i;
                const CurveGeometry& g = d.geometry[node];
                const double ex = f[cX] - d.x[node], ey = f[cY] - d.y[node];
                ePos = std::max(ePos, std::sqrt(ex * ex + ey * ey));
                const double dphi = g.heading - f[cPhi] - turnsBetween(g.heading, f[cPhi]);
                ePhi = std::max(ePhi, std::fabs(dphi));
                eKappa = std::max(eKappa, std::fabs(f[cKappa] - g.kappa));
                eDkappa = std::max(eDkappa, std::fabs(f[cDkappa] - g.dkappa));
            });
    }
    double sEnd = 0; // s - s(panel start) at xi = 1: the sum of its coefficients
    for (int k = 0; k <= n + 1; ++k)
        sEnd += series.s[k];
    eS = std::max(eS, std::fabs(sEnd - d.length));
    return {.position = ePos, .heading = ePhi, .kappa = eKappa, .dkappa = eDkappa, .arcLength = eS};
}

// The largest ratio of a bound to its tolerance (certified when <= 1). The time law's integrand
// for b of the path's size, |r'| sqrt(1 + (L kappa)^2), is resolved as well (larger b may leave
// panels to exact evaluation, TimeLaw).
double toleranceRatio(const PathTable::Bounds& e, const PointValues& values, const Series& series,
                      const PanelData& d, double lengthScale) {
    const double L = lengthScale;
    const double tolPos = std::max({2e-15 * L, 8 * kEps * values.maxX, 8 * kEps * values.maxY});
    const double tolPhi = std::max(1e-14, 8 * kEps * values.maxPhi);
    const double tolKappa = std::max({1e-14 / L, 1e-13 * values.kappaMax, values.kappaNoise});
    const double tolDkappa = std::max({1e-14 / (L * L), 1e-13 * values.kappaMax / L,
                                       1e-12 * values.dkappaMax, values.dkappaNoise});
    const double rateSum = cheb::integral(series.coef.data(), series.degree + 1, cRate);
    const double tolS = std::max(2e-15 * L, 1e-14 * d.length);
    return std::max({e.position / tolPos, e.heading / tolPhi, e.kappa / tolKappa,
                     e.dkappa / tolDkappa, e.arcLength / tolS,
                     2 * series.tail(cRate) / (kRateTolerance * rateSum)});
}

// The interpolants of one panel at one degree, and how well they fit
struct PanelFit {
    Interpolant interpolant;
    PathTable::Bounds bounds; // this panel's
    double score = 0;         // the largest ratio of a bound to its tolerance: certified when <= 1
    double stiffBound = 0;    // of the stiff time-law integrand's interpolant (PanelData::stiff)
};

PanelFit fit(ExactAtPoints& exact, double lengthScale, int degree) {
    const PanelData& d = exact.panel;
    const PointValues values = valuesAtPoints(exact, lengthScale, degree);
    const Series series = seriesOf(values, 0.5 * (d.b - d.a), degree);
    PanelFit out;
    pack(series, values, out.interpolant);
    out.bounds = errorBounds(series, d);
    out.score = toleranceRatio(out.bounds, values, series, d, lengthScale);
    out.stiffBound = 2 * series.tail(cStiff);
    out.interpolant.panel.certified = out.score <= 1;
    out.interpolant.panel.bound = out.score;
    return out;
}

// The interpolants at kLowDegree where `enough` says they will do, else at kDegree
template <class Enough>
PanelFit lowestDegreeFit(ExactAtPoints& exact, double lengthScale, Enough&& enough) {
    for (int degree = cheb::kLowDegree;; degree = cheb::kDegree) {
        PanelFit f = fit(exact, lengthScale, degree);
        if (degree == cheb::kDegree || enough(f))
            return f;
    }
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
    ExactAtPoints exact{.curve = curve, .piecewise = piecewise, .panel = d};
    // certified, and the stiff time-law integrand resolved as well
    auto accepted = [&](const PanelFit& f) {
        return f.score <= 1 && f.stiffBound <= stiffTolerance;
    };
    const PanelFit f = lowestDegreeFit(exact, lengthScale, accepted);
    if (!accepted(f))
        return false;
    keep(d, f.interpolant, f.bounds);
    return true;
}

void Certifier::certify(const PanelData& d, int depth, double parentScore) {
    if (d.a == cuspStart || d.b == cuspEnd) {
        // kappa and dkappa/ds grow without bound towards a cusp: no interpolant
        Interpolant none;
        keep(d, none, {});
        return;
    }
    ExactAtPoints exact{.curve = curve, .piecewise = piecewise, .panel = d};
    PanelFit f =
        lowestDegreeFit(exact, lengthScale, [](const PanelFit& low) { return !(low.score > 1); });
    const double score = f.score;
    bool noise = score > 1 && depth > 0 && score > 0.25 * parentScore;
    if (score <= 1 || noise || depth >= kMaxCertifyDepth || halvingsLeft == 0) {
        f.interpolant.panel.certified = score <= 1 || noise;
        f.interpolant.panel.noiseLimited = noise;
        keep(d, f.interpolant, f.bounds);
        return;
    }
    --halvingsLeft;
    double mid = 0.5 * (d.a + d.b);
    certify(computePanel(curve, d.a, mid, lengthScale), depth + 1, score);
    certify(computePanel(curve, mid, d.b, lengthScale), depth + 1, score);
}

} // namespace chaplygin
