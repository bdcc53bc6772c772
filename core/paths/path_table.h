#pragma once
// The adaptive path table: Gauss panels carrying every integral along a smooth curve, and
// certified per-panel Chebyshev interpolants of its geometry (docs/numerics.md §7).
#include "numerics/chebyshev.h"
#include "numerics/gauss_legendre.h"
#include "paths/curve.h"
#include "paths/cusp_finder.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace chaplygin {

/// Geometry of the path at one parameter value; phi is unwrapped (continuous).
struct PathNode {
    double u = 0, s = 0, x = 0, y = 0, phi = 0, kappa = 0, dkappa = 0, speed = 0;
};

/// A smooth curve tabulated once per path change: adaptive panels in u whose ends carry the
/// full geometry and whose Gauss nodes carry ds/du and kappa, so that any integral of kappa
/// along the path (arc length, the time law) is a sum over stored numbers.
/// Between the panel ends there are two ways to the geometry: at(u) evaluates the curve exactly
/// (the reference), interpolatedAt(u) reads per-panel Chebyshev interpolants (degree 16) of x, y,
/// phi, kappa, dkappa/ds and s, each certified at build time to a bound (tail of its
/// coefficients and a check against the exact values at the panel's 8 Gauss nodes); a panel
/// that cannot be certified after splitting falls back to exact evaluation. Lines and circles
/// (uniform()) have closed-form geometry and no interpolants.
class PathTable {
  public:
    /// A stretch of a curve that starts and/or ends at a cusp (docs/physics.md §3): the node there
    /// carries the limits (speed 0, kappa = +-inf, the tangent line's heading) and the panels
    /// touching it are left to exact evaluation.
    struct CuspEnds {
        std::optional<Cusp> start, end;
    };
    /// The work a table may do: panel halvings by the refinement and the certification together.
    /// y = sin(20 x) on [0, 100] needs 42,000.
    static constexpr std::size_t kHalvingBudget = 50000;
    /// Tabulates; throws InputError naming the x or u where the curve is undefined, has no finite
    /// tangent or curvature, or stops (r' = 0), or where the refinement exceeds `halvingBudget`.
    /// Certification that would exceed it leaves the remaining panels to exact evaluation.
    explicit PathTable(std::shared_ptr<const Curve> curve, CuspEnds ends = {},
                       std::size_t halvingBudget = kHalvingBudget);

    struct GaussPanel {
        std::array<double, gauss::kPoints> weight; ///< Gauss weight times ds/du: ds at each node
        std::array<double, gauss::kPoints> kappa;
    };

    const Curve& curve() const { return *m_curve; }
    const std::vector<PathNode>& nodes() const { return m_nodes; }
    const std::vector<GaussPanel>& panels() const { return m_panels; }
    double length() const { return m_nodes.back().s; }
    /// True when ds/du and kappa are constant (lines, circles): the time law is closed form.
    bool uniform() const { return m_uniform; }

    const CuspEnds& cuspEnds() const { return m_ends; }

    /// The panel holding u (clamped to the table).
    int panelOf(double u) const;
    /// Exact geometry at u, with s by Gauss quadrature over the partial panel.
    PathNode at(double u) const;
    /// Geometry at u from the interpolants (closed form on uniform tables; exact evaluation on a
    /// panel without certified interpolants).
    PathNode interpolatedAt(double u) const;
    /// The same at xi in [-1, 1] of panel k (u = midpoint + half width * xi).
    PathNode interpolatedAt(int panel, double xi) const;

    /// The panel's interpolants: coefficients c[k][q] of sum c_k T_k(xi) for the quantities
    /// q = x, y, phi, kappa, dkappa/ds, s - s(panel start), ds/du (degree + 2 rows: s has one
    /// degree more), and the values of ds/dxi = (half width) ds/du and kappa at the Chebyshev
    /// points of the panel's degree, x_j = cos(pi j/degree), j = 0..degree (for the time law).
    /// A panel is certified at cheb::kLowDegree where that suffices, else at cheb::kDegree; the
    /// table keeps them packed, so a short panel takes half the memory. kPadding is an eighth
    /// column, always 0, so that a row is 8 doubles (64 bytes, a cache line) and its series are
    /// summed in whole vector registers.
    enum Quantity { kX, kY, kPhi, kKappa, kDkappa, kS, kSpeed, kPadding, kQuantities };
    using Row = std::array<double, kQuantities>;
    struct Sample {
        double dsdxi = 0, kappa = 0;
    };
    struct ChebPanel {
        std::uint32_t row = 0;    ///< its first coefficient row (certified panels only)
        std::uint32_t sample = 0; ///< its first sample (certified panels only)
        int degree = cheb::kDegree;
        bool certified = false;
        bool noiseLimited = false; ///< bounds at the rounding noise of the exact evaluation
        double bound = 0;          ///< the largest ratio of a bound to its tolerance
    };
    /// One per panel, or empty on uniform tables.
    const std::vector<ChebPanel>& chebPanels() const { return m_cheb; }
    /// Panel k's coefficient rows (degree + 2) and samples (degree + 1), when it is certified.
    const Row* coefficients(int k) const { return &m_chebRows[m_cheb[k].row]; }
    const Sample* samples(int k) const { return &m_chebSamples[m_cheb[k].sample]; }
    /// The largest certified error bounds over all panels, and the panels left to exact
    /// evaluation.
    struct Bounds {
        double position = 0, heading = 0, kappa = 0, dkappa = 0, arcLength = 0;
        int exactPanels = 0;
        int noisePanels = 0; ///< certified at the rounding noise of the exact evaluation
    };
    const Bounds& bounds() const { return m_bounds; }
    /// Panel halvings done by the refinement and the certification (within the budget).
    std::size_t halvings() const { return m_halvings; }
    /// Geometry at the Gauss nodes of [u_k, u] in panel k (for partial integrals).
    struct Partial {
        std::array<CurveGeometry, gauss::kPoints> geometry;
        std::array<double, gauss::kPoints> weight; ///< Gauss weight in u
    };
    Partial partial(int panel, double u) const;
    /// The parameter u at arc length s (Newton on s(u) with ds/du exact).
    double uAtArcLength(double s) const;

  private:
    std::shared_ptr<const Curve> m_curve;
    void indexNodes();
    CuspEnds m_ends;
    std::vector<PathNode> m_nodes;
    std::vector<double> m_nodeU; // m_nodes[k].u, contiguous for panelOf
    std::vector<GaussPanel> m_panels;
    bool m_uniform = false;
    std::vector<ChebPanel> m_cheb;
    std::vector<Row> m_chebRows;
    std::vector<Sample> m_chebSamples;
    Bounds m_bounds;
    std::size_t m_halvings = 0;
};

} // namespace chaplygin
