#pragma once
// What the user gave for a path (a graph, a parametric curve or a polyline), before any
// tabulation.
#include "paths/corner_finder.h"

#include <string>
#include <utility>
#include <vector>

namespace chaplygin {

enum class PathKind { Graph, Parametric, Polyline, Geodesic };
enum class CornerMode { Pivot, Smooth };

/// The knife track of a genuine vakonomic motion, a geodesic of the sub-Riemannian problem on
/// SE(2) (docs/physics.md §10): from the start pose, the unit geodesic (Psi0, Lambda0) scaled by
/// b, followed for the sub-Riemannian length (v_T t). Built by buildScenePath (core/planning).
struct GeodesicTrack {
    double x = 0, y = 0, phi = 0; ///< the start pose [m, m, rad]
    double b = 1;                 ///< the length scale of the metric ds^2 + b^2 dphi^2 [m]
    double psi0 = 0;              ///< Psi(0) = atan2(sdot, b phidot) in (-pi, pi] [rad]
    double lambda0 = 0;           ///< b Psidot(0)/v_T, the normalised Lambda0
    double length = 0;            ///< v_T t [m]

    bool operator==(const GeodesicTrack&) const = default;
};

/// What the user gave for the path, before any tabulation. Plain data with defaults.
struct PathSource {
    PathKind kind = PathKind::Graph;
    std::string y = "-sin(x)";                     ///< graph y = f(x)
    std::string xOfU, yOfU;                        ///< parametric x(u), y(u)
    double from = 0, to = 12.566370614359172;      ///< x-range or u-range
    std::vector<std::pair<double, double>> points; ///< polyline vertices, in order
    CornerMode corners = CornerMode::Pivot;
    double smoothing = 10.0; ///< polylines: spline bandwidth in point spacings (0 interpolates)
    /// pivot corners: the least turn of the stroke [degrees] that is a corner (findCorners);
    /// smaller turns are smoothed
    double cornerAngle = kDefaultCornerAngleDeg;
    GeodesicTrack geodesic; ///< the geodesic track (kind Geodesic)

    bool operator==(const PathSource&) const = default;
};

/// "pivot" | "smooth" <-> CornerMode; throws InputError("corners") otherwise.
CornerMode cornerModeFromName(const std::string& name);
std::string cornerModeName(CornerMode mode);

/// Sets the path's kind and expressions from the text the command line and the Python module
/// take: "y=EXPR" (a graph y(x)) or "x=EXPR;y=EXPR" (a parametric curve x(u), y(u)); the range
/// and the polyline are left as they are. Throws InputError(where) for any other text.
void setPathExpressions(PathSource& path, const std::string& text, const std::string& where);

} // namespace chaplygin
