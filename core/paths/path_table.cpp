#include "paths/path_table.h"

#include "common/input_error.h"
#include "numerics/safeguarded_newton.h"
#include "paths/panel_certifier.h"
#include "paths/panel_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

namespace chaplygin {
namespace {

constexpr int kInitialPanels = 32;
constexpr int kMaxDepth = 40;
constexpr double kPanelTolerance = 1e-11; // parent-versus-halves difference, relative to the whole
constexpr double kRounding = 1e-15;       // the same difference at rounding: keep the parent
constexpr double kMaxTurnPerPanel = 1.0;  // rad; keeps the unwrapping of phi unambiguous

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

// 50000 -> "50,000"
std::string groupedThousands(std::size_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0)
            out += ',';
        out += digits[i];
    }
    return out;
}

struct Refiner {
    const Curve& curve;
    double lengthScale, totalWidth, lengthRef, weightedRef, stiffRef;
    std::size_t budget; // halvings allowed
    std::vector<PanelData> leaves{};
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
                throw InputError(pathPlace(curve, mid),
                                 "the curvature varies too fast here to be tabulated "
                                 "(a singular point or a near-corner)");
            if (leaves.size() > budget || splits > budget)
                throw InputError(pathPlace(curve, mid),
                                 "the path needs more than " + groupedThousands(budget) +
                                     " panels to be tabulated (its curvature varies too fast or "
                                     "too often); shorten the range or smooth the expression");
            refine(left, depth + 1);
            refine(right, depth + 1);
        }
    }
};

// the Gauss nodes alone already show constant ds/du and kappa (lines, circles)
bool uniformAtGaussNodes(const std::vector<PanelData>& leaves) {
    const double speed0 = leaves.front().geometry[0].speed;
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

// The temporaries of a tabulation, kept per thread from one table to the next: a stroke's knot
// intervals would otherwise be written to fresh pages every time (page faults were a third of
// its tabulation). Memory beyond kScratchKeep panels is given back.
struct Scratch {
    std::vector<PanelData> initial;
    std::vector<PanelSums> leaves;
};
constexpr std::size_t kScratchKeep = 4096;

struct ScratchLease {
    Scratch& scratch = instance();
    ScratchLease() {
        scratch.initial.clear();
        scratch.leaves.clear();
    }
    ~ScratchLease() {
        if (scratch.initial.capacity() > kScratchKeep)
            scratch.initial = {};
        if (scratch.leaves.capacity() > kScratchKeep)
            scratch.leaves = {};
    }
    ScratchLease(const ScratchLease&) = delete;
    ScratchLease& operator=(const ScratchLease&) = delete;
    static Scratch& instance() {
        thread_local Scratch s;
        return s;
    }
};

// The curve's parameter range [u0, u1], checked
struct Range {
    double u0 = 0, u1 = 0;
};

Range checkedRange(const Curve& c) {
    const double u0 = c.u0(), u1 = c.u1();
    if (!std::isfinite(u0) || !std::isfinite(u1) || !(u0 < u1))
        throw InputError(c.parameterName() + "-range",
                         "needs two different finite numbers " + c.parameterName() + "0, " +
                             c.parameterName() + "1, got " + formatNumber(c.parameterValue(u0)) +
                             ", " + formatNumber(c.parameterValue(u1)));
    return {u0, u1};
}

// The nodes and Gauss panels of a table, with the 2 pi n added to each node's phi
struct Assembly {
    std::vector<PathNode> nodes;
    std::vector<PathTable::GaussPanel> panels;
    std::vector<double> wraps;
};

// A straight segment: one panel, closed form; no scales to find, nothing to refine
Assembly straightPanel(const Curve& c, Range range) {
    const double u0 = range.u0, u1 = range.u1;
    PanelData d = computePanel(c, u0, u1, u1 - u0);
    Assembly a;
    for (double u : {u0, u1}) {
        CurvePoint p = c.eval(u);
        CurveGeometry g = geometryOf(p);
        a.nodes.push_back({.u = u,
                           .s = u == u0 ? 0.0 : d.length,
                           .x = p.x,
                           .y = p.y,
                           .phi = g.heading,
                           .speed = g.speed});
    }
    a.panels.push_back(d.gauss);
    return a;
}

// A coarse look at the whole curve: the length scale of the refinement, and whether ds/du and
// kappa are the same at every sample (a line or a circular arc)
struct CoarseLook {
    double lengthScale = 0;
    bool uniform = true;
    CurveGeometry first; // at u0 (zero when a cusp starts the curve)
};

CoarseLook lookAt(const Curve& c, const PathTable::CuspEnds& ends) {
    const double u0 = c.u0(), u1 = c.u1();
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    CoarseLook look;
    for (int i = ends.start ? 1 : 0; i <= (ends.end ? 63 : 64); ++i) {
        double u = u0 + (u1 - u0) * i / 64.0;
        CurvePoint p;
        CurveGeometry g = checkedGeometry(c, u, &p);
        if (i == 0)
            look.first = g;
        const CurveGeometry& g0 = look.first;
        look.uniform = look.uniform && std::fabs(g.speed - g0.speed) <= 1e-12 * g0.speed &&
                       std::fabs(g.kappa - g0.kappa) <= 1e-12 * std::fabs(g0.kappa) + 1e-300;
        xmin = std::min(xmin, p.x);
        xmax = std::max(xmax, p.x);
        ymin = std::min(ymin, p.y);
        ymax = std::max(ymax, p.y);
    }
    look.lengthScale = std::max({xmax - xmin, ymax - ymin, 1e-300});
    return look;
}

// The panels the refinement starts from, and the sums over them that scale its tolerances
struct Start {
    bool piecewise = false; // the panels are the curve's knot intervals
    double lengthRef = 0, weightedRef = 0, stiffRef = 0;
};

// The source scanned into panels: a piecewise curve's knot intervals, else kInitialPanels, or as
// few as the turn per panel allows on a line or a circular arc. Written into `initial`, the
// thread's scratch.
Start startPanels(const Curve& c, const CoarseLook& look, std::vector<PanelData>& initial) {
    const double u0 = c.u0(), u1 = c.u1();
    Start start;
    std::vector<double> edges = c.breakpoints();
    start.piecewise = edges.size() >= 2;
    initial.reserve(std::max<std::size_t>(edges.size(), kInitialPanels));
    if (edges.size() < 2) {
        edges.clear();
        int count = kInitialPanels;
        if (look.uniform)
            count = std::clamp(
                static_cast<int>(std::ceil(std::fabs(look.first.kappa) * look.first.speed *
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
        initial.push_back(computePanel(c, a, b, look.lengthScale));
        start.lengthRef += initial.back().length;
        start.weightedRef += initial.back().weighted;
        start.stiffRef += initial.back().stiff;
    }
    return start;
}

// The start panels refined and the refined panels' interpolants certified (split where they cannot
// be), within one budget of halvings counted in refiner.splits. A spline's knot intervals are each
// certified as they are, and refined only where that fails.
void refineAndCertify(const std::vector<PanelData>& initial, const Start& start,
                      std::size_t halvingBudget, Refiner& refiner, Certifier& certifier) {
    auto certifyRefined = [&] {
        certifier.halvingsLeft = halvingBudget - std::min(halvingBudget, refiner.splits);
        for (const PanelData& d : refiner.leaves)
            certifier.certify(d, 0, INFINITY);
        refiner.splits = halvingBudget - certifier.halvingsLeft;
    };
    if (start.piecewise && !uniformAtGaussNodes(initial)) {
        certifier.leaves.reserve(initial.size());
        certifier.cheb.reserve(initial.size());
        certifier.rows.reserve(initial.size() * (cheb::kLowDegree + 2));
        certifier.samples.reserve(initial.size() * (cheb::kLowDegree + 1));
        for (const PanelData& p : initial) {
            const double stiffTolerance =
                kPanelTolerance * start.stiffRef * ((p.b - p.a) / refiner.totalWidth);
            if (p.absTurn <= kMaxTurnPerPanel && certifier.acceptWhole(p, stiffTolerance))
                continue;
            refiner.leaves.clear();
            refiner.refine(p, 0);
            certifyRefined();
        }
    } else {
        refiner.leaves.reserve(2 * initial.size());
        for (const PanelData& p : initial)
            refiner.refine(p, 0);
        // a line or a circle needs no interpolants
        if (!uniformAtGaussNodes(refiner.leaves)) {
            certifier.leaves.reserve(refiner.leaves.size());
            certifier.cheb.reserve(refiner.leaves.size());
            certifyRefined();
        }
    }
}

// The table's nodes at the ends of its panels, with the exact geometry; phi is unwrapped by the
// quadrature of kappa ds, and wraps[k] is the 2 pi n added at node k
template <class Leaf>
Assembly assemble(const Curve& c, const PathTable::CuspEnds& ends,
                  const std::vector<Leaf>& leaves) {
    const double u0 = c.u0(), u1 = c.u1();
    // the exact geometry at u, or the limits at a cusp end
    auto exactNode = [&](double u) {
        const std::optional<Cusp>& cusp = u == u0 ? ends.start : ends.end;
        if ((u == u0 || u == u1) && cusp)
            return cuspNode(c, *cusp, u == u0);
        CurvePoint p;
        CurveGeometry g = checkedGeometry(c, u, &p);
        return PathNode{.u = u,
                        .x = p.x,
                        .y = p.y,
                        .phi = g.heading,
                        .kappa = g.kappa,
                        .dkappa = g.dkappa,
                        .speed = g.speed};
    };
    Assembly a;
    a.nodes.reserve(leaves.size() + 1);
    a.panels.reserve(leaves.size());
    a.wraps.reserve(leaves.size() + 1);
    a.nodes.push_back(exactNode(u0));
    a.wraps.push_back(0.0);
    for (const PanelSums& leaf : leaves) {
        PathNode n = exactNode(leaf.b);
        const PathNode& prev = a.nodes.back();
        n.s = prev.s + leaf.length;
        double predicted = prev.phi + leaf.turn;
        double wrap =
            2 * std::numbers::pi * std::round((predicted - n.phi) / (2 * std::numbers::pi));
        n.phi += wrap;
        a.wraps.push_back(wrap);
        a.nodes.push_back(n);
        a.panels.push_back(leaf.gauss);
    }
    return a;
}

// Constant ds/du and curvature at every node and Gauss node: lines and circles get closed forms
bool constantSpeedAndCurvature(const std::vector<PathNode>& nodes,
                               const std::vector<PathTable::GaussPanel>& panels,
                               double lengthScale) {
    const PathNode& first = nodes.front();
    double kappaTol = 1e-12 * std::max(std::fabs(first.kappa), 1.0 / lengthScale);
    auto same = [&](double speed, double kappa) {
        return std::fabs(speed - first.speed) <= 1e-12 * first.speed &&
               std::fabs(kappa - first.kappa) <= kappaTol;
    };
    bool uniform = true;
    for (std::size_t k = 0; k < panels.size() && uniform; ++k) {
        uniform = same(nodes[k + 1].speed, nodes[k + 1].kappa);
        gauss::Mapped m = gauss::mapTo(nodes[k].u, nodes[k + 1].u);
        for (int i = 0; i < gauss::kPoints && uniform; ++i)
            uniform = same(panels[k].weight[i] / m.w[i], panels[k].kappa[i]);
    }
    return uniform;
}

} // namespace

PathTable::PathTable(std::shared_ptr<const Curve> curve, CuspEnds ends, std::size_t halvingBudget)
    : m_curve(std::move(curve)), m_ends(std::move(ends)) {
    const Curve& c = *m_curve;
    const Range range = checkedRange(c);
    if (c.straight()) {
        Assembly a = straightPanel(c, range);
        m_nodes = std::move(a.nodes);
        m_panels = std::move(a.panels);
        indexNodes();
        m_uniform = true;
        return;
    }
    const CoarseLook look = lookAt(c, m_ends);
    ScratchLease lease;
    std::vector<PanelData>& initial = lease.scratch.initial;
    const Start start = startPanels(c, look, initial);
    const double u0 = range.u0, u1 = range.u1;
    Refiner refiner{.curve = c,
                    .lengthScale = look.lengthScale,
                    .totalWidth = u1 - u0,
                    .lengthRef = start.lengthRef,
                    .weightedRef = start.weightedRef,
                    .stiffRef = start.stiffRef,
                    .budget = halvingBudget};
    Certifier certifier{.curve = c,
                        .piecewise = start.piecewise,
                        .lengthScale = look.lengthScale,
                        .cuspStart = m_ends.start ? u0 : NAN,
                        .cuspEnd = m_ends.end ? u1 : NAN,
                        .halvingsLeft = 0,
                        .leaves = lease.scratch.leaves};
    refineAndCertify(initial, start, halvingBudget, refiner, certifier);
    m_halvings = refiner.splits;
    m_cheb = std::move(certifier.cheb);
    m_chebRows = std::move(certifier.rows);
    m_chebSamples = std::move(certifier.samples);
    m_bounds = certifier.bounds;
    // with interpolants the certifier's panels are the table's (it may have halved the refined
    // ones), without them the refiner's
    Assembly nodes = m_cheb.empty() ? assemble(c, m_ends, refiner.leaves)
                                    : assemble(c, m_ends, certifier.leaves);
    // the interpolated phi starts from atan2 at the panel's start; add the node's 2 pi n
    for (std::size_t k = 0; k < m_cheb.size(); ++k)
        if (m_cheb[k].certified)
            m_chebRows[m_cheb[k].row][kPhi] += nodes.wraps[k];
    m_nodes = std::move(nodes.nodes);
    m_panels = std::move(nodes.panels);
    indexNodes();
    m_uniform = constantSpeedAndCurvature(m_nodes, m_panels, look.lengthScale);
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
    // xi = +-1 are the panel's ends exactly: within rounding of a cusp end, where r' is rounding,
    // the heading would be atan2's of noise
    const double u = xi == 1    ? end.u
                     : xi == -1 ? start.u
                                : 0.5 * (start.u + end.u) + 0.5 * (end.u - start.u) * xi;
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
    cheb::evaluateMany(coefficients(k), static_cast<std::size_t>(m_cheb[k].degree) + 2, xi, f);
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
    // Newton on s(u) = s with ds/du exact, safeguarded by bisection on the panel: converged at a
    // step below 1e-15 of |u| plus the panel's width (the rounding of the Gauss sum); on the smooth
    // s(u) Newton takes a few steps, and 30 only bound a bisection
    const NewtonCaps caps{
        .maxIterations = 30,
        .newtonStep = {.value = 1e-15, .relativeToX = true, .scale = hi.u - lo.u}};
    auto arcLength = [&](double u) {
        Partial part = partial(k, u);
        double f = lo.s - s;
        for (int i = 0; i < gauss::kPoints; ++i)
            f += part.weight[i] * part.geometry[i].speed;
        return NewtonValue{f, geometryOf(m_curve->eval(u)).speed};
    };
    const double u0 = lo.u + (hi.u - lo.u) * (s - lo.s) / (hi.s - lo.s);
    return safeguardedNewton(arcLength, u0, {lo.u, hi.u}, caps).x;
}

} // namespace chaplygin
