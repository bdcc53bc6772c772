#pragma once
#include "numerics/gauss_legendre.h"
#include "paths/curve.h"

#include <array>
#include <memory>
#include <vector>

namespace chaplygin {

/// Geometry of the path at one parameter value; phi is unwrapped (continuous).
struct PathNode {
    double u = 0, s = 0, x = 0, y = 0, phi = 0, kappa = 0, dkappa = 0, speed = 0;
};

/// A smooth curve tabulated once per path change: adaptive panels in u whose ends carry the
/// full geometry and whose Gauss nodes carry ds/du and kappa, so that any integral of kappa
/// along the path (arc length, the time law) is a sum over stored numbers. Values between the
/// panel ends are never interpolated: at(u) evaluates the curve exactly and integrates the
/// arc length over the partial panel with the same Gauss rule.
class PathTable {
  public:
    /// Tabulates; throws InputError naming the x or u where the curve is undefined,
    /// has no finite tangent or curvature, or stops (r' = 0).
    explicit PathTable(std::shared_ptr<const Curve> curve);

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

    /// The panel holding u (clamped to the table).
    int panelOf(double u) const;
    /// Exact geometry at u, with s by Gauss quadrature over the partial panel.
    PathNode at(double u) const;
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
    std::vector<PathNode> m_nodes;
    std::vector<GaussPanel> m_panels;
    bool m_uniform = false;
};

} // namespace chaplygin
