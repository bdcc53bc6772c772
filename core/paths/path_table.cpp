#include "paths/path_table.h"

#include "common/input_error.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace chaplygin {
namespace {

constexpr int kInitialPanels = 32;
constexpr int kMaxDepth = 40;
constexpr std::size_t kMaxPanels = 200000;
constexpr double kPanelTolerance = 1e-11; // parent-versus-halves difference, relative to the whole
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

struct PanelData {
    double a = 0, b = 0;
    double length = 0, turn = 0, absTurn = 0; // \int ds, \int kappa ds, \int |kappa| ds
    double weighted = 0, stiff = 0; // time-law proxies for b ~ the path's size and b >> it
    PathTable::GaussPanel gauss;
};

PanelData computePanel(const Curve& c, double a, double b, double lengthScale) {
    PanelData d;
    d.a = a;
    d.b = b;
    gauss::Mapped m = gauss::mapTo(a, b);
    for (int i = 0; i < gauss::kPoints; ++i) {
        CurveGeometry g = checkedGeometry(c, m.x[i]);
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

    bool close(double coarse, double fine, double ref, double width) const {
        return std::fabs(coarse - fine) <= kPanelTolerance * ref * (width / totalWidth);
    }

    void refine(const PanelData& parent, int depth) {
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
        if (ok) {
            leaves.push_back(left);
            leaves.push_back(right);
        } else {
            if (depth >= kMaxDepth || leaves.size() > kMaxPanels)
                throw InputError(place(curve, mid),
                                 "the curvature varies too fast here to be tabulated "
                                 "(a singular point or a near-corner)");
            refine(left, depth + 1);
            refine(right, depth + 1);
        }
    }
};

} // namespace

PathTable::PathTable(std::shared_ptr<const Curve> curve) : m_curve(std::move(curve)) {
    const Curve& c = *m_curve;
    double u0 = c.u0(), u1 = c.u1();
    if (!std::isfinite(u0) || !std::isfinite(u1) || !(u0 < u1))
        throw InputError(c.parameterName() + "-range",
                         "needs two different finite numbers " + c.parameterName() + "0, " +
                             c.parameterName() + "1, got " + formatNumber(c.parameterValue(u0)) +
                             ", " + formatNumber(c.parameterValue(u1)));

    // a coarse look at the whole curve sets the scales of the refinement
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int i = 0; i <= 64; ++i) {
        double u = u0 + (u1 - u0) * i / 64.0;
        CurvePoint p;
        checkedGeometry(c, u, &p);
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
        for (int k = 0; k < kInitialPanels; ++k)
            edges.push_back(u0 + (u1 - u0) * k / kInitialPanels);
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
    Refiner refiner{c, lengthScale, u1 - u0, lengthRef, weightedRef, stiffRef, {}};
    for (const PanelData& p : initial)
        refiner.refine(p, 0);

    // panel ends carry the exact geometry; phi is unwrapped by the quadrature of kappa ds
    const auto& leaves = refiner.leaves;
    m_nodes.reserve(leaves.size() + 1);
    m_panels.reserve(leaves.size());
    auto nodeAt = [&](double u) {
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
    for (const PanelData& leaf : leaves) {
        PathNode n = nodeAt(leaf.b);
        const PathNode& prev = m_nodes.back();
        n.s = prev.s + leaf.length;
        double predicted = prev.phi + leaf.turn;
        n.phi += 2 * std::numbers::pi * std::round((predicted - n.phi) / (2 * std::numbers::pi));
        m_nodes.push_back(n);
        m_panels.push_back(leaf.gauss);
    }

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

int PathTable::panelOf(double u) const {
    auto it = std::upper_bound(m_nodes.begin(), m_nodes.end(), u,
                               [](double v, const PathNode& n) { return v < n.u; });
    int k = static_cast<int>(it - m_nodes.begin()) - 1;
    return std::clamp(k, 0, static_cast<int>(m_panels.size()) - 1);
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
