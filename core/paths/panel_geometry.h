#pragma once
// The exact geometry of one panel of a path table, shared by its refinement (path_table.cpp) and
// the certification of its interpolants (panel_certifier.cpp); pathPlace names a point of a curve
// in messages.
#include "paths/path_table.h"

#include <array>
#include <cmath>
#include <string>

namespace chaplygin {

/// "path at u = ..." in the curve's own parameter, for messages.
std::string pathPlace(const Curve& c, double u);

/// The geometry at u; throws InputError naming the place where the curve is undefined, has no
/// finite tangent or curvature, or stops (r' = 0).
CurveGeometry checkedGeometry(const Curve& c, double u, CurvePoint* out = nullptr);

/// The time law sqrt(1 + b^2 kappa^2) sharpens near inflections as b grows; the table resolves it
/// for gyration radii up to this many times the path's size.
constexpr double kStiffScale = 100.0;

/// A panel [a, b] with its 8-point Gauss sums.
struct PanelSums {
    double a = 0, b = 0;
    double length = 0, turn = 0, absTurn = 0; // \int ds, \int kappa ds, \int |kappa| ds
    double weighted = 0, stiff = 0; // time-law proxies for b ~ the path's size and b >> it
    PathTable::GaussPanel gauss;
};
/// The same with the exact curve at the Gauss nodes, for certifying the interpolants.
struct PanelData : PanelSums {
    std::array<double, gauss::kPoints> x, y;
    std::array<CurveGeometry, gauss::kPoints> geometry;
};

/// sqrt(1 + x^2) without hypot's cost; |x| where x^2 would overflow.
inline double hypotOne(double x) {
    return std::fabs(x) < 1e150 ? std::sqrt(1 + x * x) : std::fabs(x);
}

PanelData computePanel(const Curve& c, double a, double b, double lengthScale);

} // namespace chaplygin
