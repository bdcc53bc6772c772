#include "paths/path_table.h"

#include "common/input_error.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace chaplygin {
namespace {

constexpr int kInitialPanels = 32;
constexpr int kMaxDepth = 40;
constexpr std::size_t kMaxPanels = 50000; // y = sin(20 x) on [0, 100] needs 42,000
constexpr double kPanelTolerance = 1e-11; // parent-versus-halves difference, relative to the whole
constexpr double kRounding = 1e-15;       // the same difference at rounding: keep the parent
constexpr double kMaxTurnPerPanel = 1.0;  // rad; keeps the unwrapping of phi unambiguous
// the time law sqrt(1 + b^2 kappa^2) sharpens near inflections as b grows; the table resolves
// it for gyration radii up to this many times the path's size
constexpr double kStiffScale = 100.0;

std::string place(const Curve& c, double u) {
    return "path at " + c.parameterName() + " = " + formatNumber(c.parameterValue(u));
}

bool finite(const CurvePoint& p) {
    return std::isfinite(p.dx) && std::isfinite(p.dy) && std::isfinite(p.ddx) &&
           std::isfinite(p.ddy) && std::isfinite(p.dddx) && std::isfinite(p.dddy);
}

CurveGeometry checkedGeometry(const Curve& c, double u, CurvePoint* out = nullptr) {
    CurvePoint p = c.eval(u);
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw InputError(place(c, u),
                         "the path is not defined here (division by zero, log of 0 or of a "
                         "negative number, sqrt of a negative number, or overflow)");
    if (!finite(p))
        throw InputError(place(c, u),
                         "the path has no finite tangent or curvature here (a vertical "
                         "tangent, a kink, or a singular point)");
    if (p.dx == 0 && p.dy == 0)
        throw InputError(place(c, u),
                         "the path stops here (x' = y' = 0): a cusp or a stationary point "
                         "has no direction to follow");
    CurveGeometry g = geometryOf(p);
    if (!std::isfinite(g.kappa) || !std::isfinite(g.dkappa))
        throw InputError(place(c, u), "the curvature overflows here");
    if (out)
        *out = p;
    return g;
}

// The limits at a cusp (docs/physics.md §3): ds/du = 0, kappa = +-inf with the sign of the
// heading's turn, and the tangent line's heading: r' ~ (u - u*) r'', so the stretch that starts at
// the cusp leaves along r'' and the one that ends there arrives along -r''.
PathNode cuspNode(const Curve& c, const Cusp& cusp, bool atStart) {
    CurvePoint p = c.eval(cusp.u);
    PathNode n;
    n.u = cusp.u;
    n.x = p.x;
    n.y = p.y;
    n.speed = 0;
    n.kappa = std::copysign(INFINITY, cusp.turnRate);
    n.dkappa = 0;
    n.phi = atStart ? std::atan2(p.ddy, p.ddx) : std::atan2(-p.ddy, -p.ddx);
    return n;
}

struct PanelData {
    double a = 0, b = 0;
    double length = 0, turn = 0, absTurn = 0; // \int ds, \int kappa ds, \int |kappa| ds
    double weighted = 0, stiff = 0; // time-law proxies for b ~ the path's size and b >> it
    PathTable::GaussPanel gauss;
    std::array<CurvePoint, gauss::kPoints> points; // exact, for certifying the interpolants
};

PanelData computePanel(const Curve& c, double a, double b, double lengthScale) {
    PanelData d;
    d.a = a;
    d.b = b;
    gauss::Mapped m = gauss::mapTo(a, b);
    for (int i = 0; i < gauss::kPoints; ++i) {
        CurveGeometry g = checkedGeometry(c, m.x[i], &d.points[i]);
        double ds = m.w[i] * g.speed;
        d.gauss.weight[i] = ds;
        d.gauss.kappa[i] = g.kappa;
        d.length += ds;
        d.turn += ds * g.kappa;
        d.absTurn += ds * std::fabs(g.kappa);
        // proxy for the time-law integrand sqrt(1 + b^2 kappa^2) ds with b of the path's size
        d.weighted += ds * std::hypot(1.0, lengthScale * g.kappa);
        d.stiff += ds * std::hypot(1.0, kStiffScale * lengthScale * g.kappa);
    }
    return d;
}

struct Refiner {
    const Curve& curve;
    double lengthScale, totalWidth, lengthRef, weightedRef, stiffRef;
    std::vector<PanelData> leaves;
    std::size_t splits = 0; // panels halved so far: the work, bounded like the leaves

    bool close(double coarse, double fine, double ref, double width) const {
        return std::fabs(coarse - fine) <= kPanelTolerance * ref * (width / totalWidth);
    }
    static bool rounding(double coarse, double fine, double ref) {
        return std::fabs(coarse - fine) <= kRounding * ref;
    }

    void refine(const PanelData& parent, int depth) {
        ++splits;
        double mid = 0.5 * (parent.a + parent.b);
        PanelData left = computePanel(curve, parent.a, mid, lengthScale);
        PanelData right = computePanel(curve, mid, parent.b, lengthScale);
        double w = parent.b - parent.a;
        bool ok = close(parent.length, left.length + right.length, lengthRef, w) &&
                  close(parent.weighted, left.weighted + right.weighted, weightedRef, w) &&
                  close(parent.stiff, left.stiff + right.stiff, stiffRef, w) &&
                  close(parent.turn, left.turn + right.turn,
                        std::max(1.0, weightedRef / lengthScale), w) &&
                  left.absTurn <= kMaxTurnPerPanel && right.absTurn <= kMaxTurnPerPanel;
        // a panel that its halves reproduce to rounding (a line, a circular arc, a spline
        // piece on a short knot interval) is kept whole: splitting it gains nothing
        bool whole = rounding(parent.length, left.length + right.length, lengthRef) &&
                     rounding(parent.weighted, left.weighted + right.weighted, weightedRef) &&
                     rounding(parent.stiff, left.stiff + right.stiff, stiffRef) &&
                     rounding(parent.turn, left.turn + right.turn,
                              std::max(1.0, weightedRef / lengthScale)) &&
                     parent.absTurn <= kMaxTurnPerPanel;
        if (whole) {
            leaves.push_back(parent);
        } else if (ok) {
            leaves.push_back(left);
            leaves.push_back(right);
        } else {
            if (depth >= kMaxDepth)
                throw InputError(place(curve, mid),
                                 "the curvature varies too fast here to be tabulated "
                                 "(a singular point or a near-corner)");
            if (leaves.size() > kMaxPanels || splits > kMaxPanels)
                throw InputError(place(curve, mid),
                                 "the path needs more than 50,000 panels to be tabulated (its "
                                 "curvature varies too fast or too often); shorten the range or "
                                 "smooth the expression");
            refine(left, depth + 1);
            refine(right, depth + 1);
        }
    }
};

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

struct Certifier {
    const Curve& curve;
    bool piecewise; // the curve has breakpoints
    double lengthScale;
    double cuspStart, cuspEnd; // u of a cusp at either end, or NaN
    std::vector<PanelData> leaves;
    std::vector<PathTable::ChebPanel> cheb;
    PathTable::Bounds bounds;

    // Splits a panel whose interpolants miss their tolerance. A resolved function's error falls
    // by orders of magnitude per halving; when a halving gains less than a factor 4 the error is
    // the rounding noise of the exact evaluation itself (a jittery interpolating spline), which
    // no panel can beat: the panel is kept with that measured bound (noiseLimited).
    void certify(const PanelData& d, int depth, double parentScore) {
        PathTable::ChebPanel panel;
        if (d.a == cuspStart || d.b == cuspEnd) {
            // kappa and dkappa/ds grow without bound towards a cusp: no interpolant
            bounds.exactPanels += 1;
            leaves.push_back(d);
            cheb.push_back(panel);
            return;
        }
        PathTable::Bounds b;
        double score = interpolate(curve, piecewise, d, lengthScale, panel, b);
        bool noise = score > 1 && depth > 0 && score > 0.25 * parentScore;
        if (score <= 1 || noise || depth >= kMaxCertifyDepth) {
            if (score <= 1 || noise) {
                panel.certified = true;
                panel.noiseLimited = noise;
                bounds.position = std::max(bounds.position, b.position);
                bounds.heading = std::max(bounds.heading, b.heading);
                bounds.kappa = std::max(bounds.kappa, b.kappa);
                bounds.dkappa = std::max(bounds.dkappa, b.dkappa);
                bounds.arcLength = std::max(bounds.arcLength, b.arcLength);
                bounds.noisePanels += noise ? 1 : 0;
            }
            bounds.exactPanels += panel.certified ? 0 : 1;
            leaves.push_back(d);
            cheb.push_back(panel);
            return;
        }
        double mid = 0.5 * (d.a + d.b);
        certify(computePanel(curve, d.a, mid, lengthScale), depth + 1, score);
        certify(computePanel(curve, mid, d.b, lengthScale), depth + 1, score);
    }
};

// the Gauss nodes alone already show constant ds/du and kappa (lines, circles)
bool uniformAtGaussNodes(const std::vector<PanelData>& leaves) {
    const double speed0 = geometryOf(leaves.front().points[0]).speed;
    const double kappa0 = leaves.front().gauss.kappa[0];
    for (const PanelData& d : leaves) {
        gauss::Mapped m = gauss::mapTo(d.a, d.b);
        for (int i = 0; i < gauss::kPoints; ++i)
            if (std::fabs(d.gauss.weight[i] / m.w[i] - speed0) > 1e-12 * speed0 ||
                std::fabs(d.gauss.kappa[i] - kappa0) > 1e-12 * std::fabs(kappa0) + 1e-300)
                return false;
    }
    return true;
}

} // namespace

PathTable::PathTable(std::shared_ptr<const Curve> curve) : PathTable(std::move(curve), {}) {}

PathTable::PathTable(std::shared_ptr<const Curve> curve, CuspEnds ends)
    : m_curve(std::move(curve)), m_ends(std::move(ends)) {
    const Curve& c = *m_curve;
    double u0 = c.u0(), u1 = c.u1();
    if (!std::isfinite(u0) || !std::isfinite(u1) || !(u0 < u1))
        throw InputError(c.parameterName() + "-range",
                         "needs two different finite numbers " + c.parameterName() + "0, " +
                             c.parameterName() + "1, got " + formatNumber(c.parameterValue(u0)) +
                             ", " + formatNumber(c.parameterValue(u1)));

    if (c.straight()) {
        // one panel, closed form: no scales to find, nothing to refine
        PanelData d = computePanel(c, u0, u1, u1 - u0);
        for (double u : {u0, u1}) {
            CurvePoint p = c.eval(u);
            CurveGeometry g = geometryOf(p);
            PathNode n;
            n.u = u;
            n.s = u == u0 ? 0.0 : d.length;
            n.x = p.x;
            n.y = p.y;
            n.speed = g.speed;
            n.phi = g.heading;
            m_nodes.push_back(n);
        }
        m_panels.push_back(d.gauss);
        m_uniform = true;
        indexNodes();
        return;
    }
    // a coarse look at the whole curve sets the scales of the refinement
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    CurveGeometry g0;
    bool looksUniform = true; // the same ds/du and kappa at every sample
    for (int i = m_ends.start ? 1 : 0; i <= (m_ends.end ? 63 : 64); ++i) {
        double u = u0 + (u1 - u0) * i / 64.0;
        CurvePoint p;
        CurveGeometry g = checkedGeometry(c, u, &p);
        if (i == 0)
            g0 = g;
        looksUniform = looksUniform && std::fabs(g.speed - g0.speed) <= 1e-12 * g0.speed &&
                       std::fabs(g.kappa - g0.kappa) <= 1e-12 * std::fabs(g0.kappa) + 1e-300;
        xmin = std::min(xmin, p.x);
        xmax = std::max(xmax, p.x);
        ymin = std::min(ymin, p.y);
        ymax = std::max(ymax, p.y);
    }
    double lengthScale = std::max({xmax - xmin, ymax - ymin, 1e-300});

    std::vector<PanelData> initial;
    double lengthRef = 0, weightedRef = 0, stiffRef = 0;
    std::vector<double> edges = c.breakpoints();
    if (edges.size() < 2) {
        edges.clear();
        // a line or a circular arc starts from as few panels as the turn per panel allows
        int count = kInitialPanels;
        if (looksUniform)
            count = std::clamp(static_cast<int>(std::ceil(std::fabs(g0.kappa) * g0.speed *
                                                          (u1 - u0) / (0.9 * kMaxTurnPerPanel))),
                               1, kInitialPanels);
        for (int k = 0; k < count; ++k)
            edges.push_back(u0 + (u1 - u0) * k / count);
        edges.push_back(u1);
    }
    for (std::size_t k = 0; k + 1 < edges.size(); ++k) {
        double a = edges[k], b = edges[k + 1];
        if (!(b > a))
            continue;
        initial.push_back(computePanel(c, a, b, lengthScale));
        lengthRef += initial.back().length;
        weightedRef += initial.back().weighted;
        stiffRef += initial.back().stiff;
    }
    Refiner refiner{c, lengthScale, u1 - u0, lengthRef, weightedRef, stiffRef, {}, 0};
    for (const PanelData& p : initial)
        refiner.refine(p, 0);

    // interpolants on every panel of a curve that is not a line or a circle, split where
    // they cannot be certified
    std::vector<PanelData> certifiedLeaves;
    if (!uniformAtGaussNodes(refiner.leaves)) {
        Certifier certifier{c,
                            c.breakpoints().size() >= 2,
                            lengthScale,
                            m_ends.start ? u0 : NAN,
                            m_ends.end ? u1 : NAN,
                            {},
                            {},
                            {}};
        for (const PanelData& d : refiner.leaves)
            certifier.certify(d, 0, INFINITY);
        certifiedLeaves = std::move(certifier.leaves);
        m_cheb = std::move(certifier.cheb);
        m_bounds = certifier.bounds;
    }
    const auto& leaves = m_cheb.empty() ? refiner.leaves : certifiedLeaves;

    // panel ends carry the exact geometry; phi is unwrapped by the quadrature of kappa ds
    m_nodes.reserve(leaves.size() + 1);
    m_panels.reserve(leaves.size());
    auto nodeAt = [&](double u) {
        const std::optional<Cusp>& cusp = u == u0 ? m_ends.start : m_ends.end;
        if ((u == u0 || u == u1) && cusp)
            return cuspNode(c, *cusp, u == u0);
        CurvePoint p;
        CurveGeometry g = checkedGeometry(c, u, &p);
        PathNode n;
        n.u = u;
        n.x = p.x;
        n.y = p.y;
        n.kappa = g.kappa;
        n.dkappa = g.dkappa;
        n.speed = g.speed;
        n.phi = g.heading;
        return n;
    };
    m_nodes.push_back(nodeAt(u0));
    std::vector<double> wraps{0.0}; // 2 pi n added to atan2 at each node
    for (const PanelData& leaf : leaves) {
        PathNode n = nodeAt(leaf.b);
        const PathNode& prev = m_nodes.back();
        n.s = prev.s + leaf.length;
        double predicted = prev.phi + leaf.turn;
        double wrap =
            2 * std::numbers::pi * std::round((predicted - n.phi) / (2 * std::numbers::pi));
        n.phi += wrap;
        wraps.push_back(wrap);
        m_nodes.push_back(n);
        m_panels.push_back(leaf.gauss);
    }
    indexNodes();
    // the interpolated phi starts from atan2 at the panel's start; add the node's 2 pi n
    for (std::size_t k = 0; k < m_cheb.size(); ++k)
        m_cheb[k].c[0][kPhi] += wraps[k];

    // constant ds/du and curvature: lines and circles get closed forms
    const PathNode& first = m_nodes.front();
    double kappaTol = 1e-12 * std::max(std::fabs(first.kappa), 1.0 / lengthScale);
    auto same = [&](double speed, double kappa) {
        return std::fabs(speed - first.speed) <= 1e-12 * first.speed &&
               std::fabs(kappa - first.kappa) <= kappaTol;
    };
    m_uniform = true;
    for (std::size_t k = 0; k < m_panels.size() && m_uniform; ++k) {
        m_uniform = same(m_nodes[k + 1].speed, m_nodes[k + 1].kappa);
        gauss::Mapped m = gauss::mapTo(m_nodes[k].u, m_nodes[k + 1].u);
        for (int i = 0; i < gauss::kPoints && m_uniform; ++i)
            m_uniform = same(m_panels[k].weight[i] / m.w[i], m_panels[k].kappa[i]);
    }
}

void PathTable::indexNodes() {
    m_nodeU.clear();
    m_nodeU.reserve(m_nodes.size());
    for (const PathNode& n : m_nodes)
        m_nodeU.push_back(n.u);
}

int PathTable::panelOf(double u) const {
    // an integrator asks for nearby u in turn: try this thread's last answer first
    thread_local const PathTable* lastTable = nullptr;
    thread_local std::size_t lastPanel = 0;
    if (lastTable == this && lastPanel + 1 < m_nodeU.size() && u >= m_nodeU[lastPanel] &&
        u < m_nodeU[lastPanel + 1])
        return static_cast<int>(lastPanel);
    // over the contiguous u of the nodes: the lookup stays in a few cache lines
    auto it = std::upper_bound(m_nodeU.begin(), m_nodeU.end(), u);
    int k = static_cast<int>(it - m_nodeU.begin()) - 1;
    k = std::clamp(k, 0, static_cast<int>(m_panels.size()) - 1);
    lastTable = this;
    lastPanel = static_cast<std::size_t>(k);
    return k;
}

PathTable::Partial PathTable::partial(int panel, double u) const {
    Partial p;
    gauss::Mapped m = gauss::mapTo(m_nodes[panel].u, u);
    for (int i = 0; i < gauss::kPoints; ++i) {
        p.geometry[i] = geometryOf(m_curve->eval(m.x[i]));
        p.weight[i] = m.w[i];
    }
    return p;
}

PathNode PathTable::at(double u) const {
    if ((m_ends.start && u <= m_nodes.front().u) || (m_ends.end && u >= m_nodes.back().u))
        return u <= m_nodes.front().u ? m_nodes.front() : m_nodes.back();
    int k = panelOf(u);
    const PathNode& start = m_nodes[k];
    CurvePoint p = m_curve->eval(u);
    CurveGeometry g = geometryOf(p);
    PathNode n;
    n.u = u;
    n.x = p.x;
    n.y = p.y;
    n.kappa = g.kappa;
    n.dkappa = g.dkappa;
    n.speed = g.speed;
    double d = g.heading - start.phi;
    n.phi = start.phi + d - 2 * std::numbers::pi * std::round(d / (2 * std::numbers::pi));
    if (m_uniform) {
        n.s = start.s + start.speed * (u - start.u);
    } else {
        Partial part = partial(k, u);
        n.s = start.s;
        for (int i = 0; i < gauss::kPoints; ++i)
            n.s += part.weight[i] * part.geometry[i].speed;
    }
    return n;
}

PathNode PathTable::interpolatedAt(double u) const {
    int k = panelOf(u);
    const double a = m_nodes[k].u, b = m_nodes[k + 1].u;
    return interpolatedAt(k, (2 * u - (a + b)) / (b - a));
}

PathNode PathTable::interpolatedAt(int k, double xi) const {
    const PathNode &start = m_nodes[k], &end = m_nodes[k + 1];
    const double u = 0.5 * (start.u + end.u) + 0.5 * (end.u - start.u) * xi;
    if (m_uniform) {
        // constant ds/du and kappa: phi is linear in s and P moves on a line or a circle; the
        // chord 2 sin(dphi/2)/kappa is written s sinc(dphi/2) so kappa = 0 needs no case
        PathNode n = start;
        n.u = u;
        const double ds = start.speed * (u - start.u), dphi = start.kappa * ds;
        n.s = start.s + ds;
        n.phi = start.phi + dphi;
        const double h = 0.5 * dphi;
        const double chord =
            std::fabs(h) < 1e-4 ? ds * (1 - h * h / 6 * (1 - h * h / 20)) : ds * std::sin(h) / h;
        n.x = start.x + chord * std::cos(start.phi + h);
        n.y = start.y + chord * std::sin(start.phi + h);
        return n;
    }
    if (m_cheb.empty() || !m_cheb[k].certified)
        return at(u);
    double f[kQuantities];
    cheb::evaluateMany(m_cheb[k].c, xi, f);
    PathNode n;
    n.u = u;
    n.s = start.s + f[kS];
    n.x = f[kX];
    n.y = f[kY];
    n.phi = f[kPhi];
    n.kappa = f[kKappa];
    n.dkappa = f[kDkappa];
    n.speed = f[kSpeed];
    return n;
}

double PathTable::uAtArcLength(double s) const {
    if (s <= 0)
        return m_nodes.front().u;
    if (s >= length())
        return m_nodes.back().u;
    auto it = std::upper_bound(m_nodes.begin(), m_nodes.end(), s,
                               [](double v, const PathNode& n) { return v < n.s; });
    int k = std::clamp(static_cast<int>(it - m_nodes.begin()) - 1, 0,
                       static_cast<int>(m_panels.size()) - 1);
    const PathNode &lo = m_nodes[k], &hi = m_nodes[k + 1];
    if (m_uniform)
        return lo.u + (s - lo.s) / lo.speed;
    double a = lo.u, b = hi.u;
    double u = a + (b - a) * (s - lo.s) / (hi.s - lo.s);
    for (int iter = 0; iter < 30; ++iter) {
        Partial part = partial(k, u);
        double f = lo.s - s;
        for (int i = 0; i < gauss::kPoints; ++i)
            f += part.weight[i] * part.geometry[i].speed;
        (f > 0 ? b : a) = u;
        double step = f / geometryOf(m_curve->eval(u)).speed;
        if (std::fabs(step) <= 1e-15 * (std::fabs(u) + (hi.u - lo.u))) {
            u -= step;
            break;
        }
        u = (u - step > a && u - step < b) ? u - step : 0.5 * (a + b);
    }
    return u;
}

} // namespace chaplygin
