#pragma once
// What the user gave for a path (a graph, a parametric curve or a polyline), before any
// tabulation.
#include "paths/corner_finder.h"

#include <string>
#include <utility>
#include <vector>

namespace chaplygin {

enum class PathKind { Graph, Parametric, Polyline };
enum class CornerMode { Pivot, Smooth };

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
