#include "paths/path.h"

#include "common/input_error.h"
#include "paths/corner_finder.h"
#include "paths/expression_curve.h"
#include "paths/spline_curve.h"
#include "paths/sub_curve.h"

#include <cmath>
#include <numbers>

namespace chaplygin {
namespace {

constexpr double kStraight = 1e-12; // rad: smaller turns at a vertex are no corner

double wrapAngle(double d) {
    return d - 2 * std::numbers::pi * std::round(d / (2 * std::numbers::pi));
}

std::vector<std::pair<double, double>> distinctPoints(const PathSource& source) {
    std::vector<std::pair<double, double>> pts;
    for (std::size_t i = 0; i < source.points.size(); ++i) {
        auto [x, y] = source.points[i];
        if (!std::isfinite(x) || !std::isfinite(y))
            throw InputError("point " + std::to_string(i + 1),
                             "coordinates must be finite numbers");
        if (!pts.empty() && x == pts.back().first && y == pts.back().second)
            continue;
        pts.emplace_back(x, y);
    }
    if (pts.size() < 2)
        throw InputError("points", "a drawn path needs at least 2 distinct points");
    return pts;
}

// the stretch of a stroke from point a to point b: a segment, or the smoothing spline through
// its points with its ends pinned to the corners
std::shared_ptr<const Curve> stretch(const std::vector<std::pair<double, double>>& pts,
                                     std::size_t a, std::size_t b, double smoothing) {
    if (b == a + 1)
        return std::make_shared<SegmentCurve>(pts[a].first, pts[a].second, pts[b].first,
                                              pts[b].second);
    std::vector<double> xs, ys;
    for (std::size_t i = a; i <= b; ++i) {
        xs.push_back(pts[i].first);
        ys.push_back(pts[i].second);
    }
    return std::make_shared<SplineCurve>(xs, ys, smoothing, SplineCurve::Ends::Pinned);
}

// A stroke with pivot corners: the body pivots where the hand turned by more than the corner
// angle (findCorners) and follows a smooth stretch between them (docs/numerics.md, Corners of a
// drawn path)
std::vector<PathPiece> pivotPolyline(const std::vector<std::pair<double, double>>& pts,
                                     double cornerAngleDeg, double smoothing,
                                     std::size_t halvingBudget) {
    std::vector<std::size_t> ends = findCorners(pts, cornerAngleDeg);
    ends.push_back(pts.size() - 1);
    std::vector<PathPiece> pieces;
    double phi = 0; // the body's heading at the end of the last stretch
    std::size_t a = 0;
    for (std::size_t b : ends) {
        auto table = std::make_shared<const PathTable>(stretch(pts, a, b, smoothing),
                                                       PathTable::CuspEnds{}, halvingBudget);
        const double heading = table->nodes().front().phi;
        if (a == 0) {
            phi = heading;
        } else {
            double turn = wrapAngle(heading - phi);
            if (std::fabs(std::fabs(turn) - std::numbers::pi) < kStraight)
                turn = std::numbers::pi; // a reversal: turn left by convention
            if (std::fabs(turn) > kStraight) {
                PathPiece pivot;
                pivot.kind = PathPiece::Kind::Pivot;
                pivot.x = pts[a].first;
                pivot.y = pts[a].second;
                pivot.phiFrom = phi;
                pivot.phiTo = phi + turn;
                pieces.push_back(pivot);
            }
            phi += turn;
        }
        PathPiece piece;
        piece.table = table;
        piece.phiOffset = phi - heading;
        pieces.push_back(piece);
        phi += table->nodes().back().phi - heading;
        a = b;
    }
    return pieces;
}

std::vector<PathPiece> singleCurve(std::shared_ptr<const Curve> curve, std::size_t halvingBudget) {
    PathPiece piece;
    piece.table =
        std::make_shared<const PathTable>(std::move(curve), PathTable::CuspEnds{}, halvingBudget);
    return {piece};
}

} // namespace

std::vector<PathPiece> piecesThroughCusps(const std::shared_ptr<const Curve>& curve,
                                          int firstDirection, std::size_t halvingBudget) {
    std::vector<Cusp> cusps = findCusps(*curve);
    if (cusps.empty() && firstDirection > 0)
        return singleCurve(curve, halvingBudget);
    std::vector<PathPiece> pieces;
    double ua = curve->u0(), psiEnd = 0;
    for (std::size_t k = 0; k <= cusps.size(); ++k) {
        const double ub = k < cusps.size() ? cusps[k].u : curve->u1();
        PathTable::CuspEnds ends;
        if (k > 0)
            ends.start = cusps[k - 1];
        if (k < cusps.size())
            ends.end = cusps[k];
        PathPiece piece;
        piece.table = std::make_shared<const PathTable>(std::make_shared<SubCurve>(curve, ua, ub),
                                                        std::move(ends), halvingBudget);
        piece.direction = k % 2 == 0 ? firstDirection : -firstDirection;
        const double heading = piece.table->nodes().front().phi;
        if (k == 0) {
            piece.phiOffset = piece.direction < 0 ? std::numbers::pi : 0.0;
        } else {
            const PathPiece& prev = pieces.back();
            const double prevEnd = prev.table->nodes().back().phi + prev.phiOffset;
            // the body's heading is the table's, turned by pi when backing up
            const double target = prevEnd - (piece.direction < 0 ? std::numbers::pi : 0.0);
            piece.phiOffset =
                (piece.direction < 0 ? std::numbers::pi : 0.0) +
                2 * std::numbers::pi * std::round((target - heading) / (2 * std::numbers::pi));
            const double start = psiAtCusp(cusps[k - 1], piece.direction);
            piece.psiOffset =
                2 * std::numbers::pi * std::round((psiEnd - start) / (2 * std::numbers::pi));
        }
        if (k < cusps.size())
            psiEnd = psiAtCusp(cusps[k], piece.direction) + piece.psiOffset;
        pieces.push_back(piece);
        ua = ub;
    }
    return pieces;
}

Path::Path(std::vector<PathPiece> pieces) : m_pieces(std::move(pieces)) {
    double s = 0;
    for (PathPiece& p : m_pieces) {
        p.s0 = s;
        if (p.kind == PathPiece::Kind::Curve)
            s += p.table->length();
    }
    m_length = s;
}

namespace {

// a path that is one pivot (the pivoting geodesic, docs/physics.md §10) has its geometry there
PathNode pivotNode(const PathPiece& p, double phi) {
    PathNode n;
    n.x = p.x;
    n.y = p.y;
    n.phi = phi;
    n.kappa = std::copysign(INFINITY, p.phiTo - p.phiFrom);
    return n;
}

} // namespace

PathNode Path::start() const {
    const PathPiece& p = m_pieces.front();
    if (p.kind == PathPiece::Kind::Pivot)
        return pivotNode(p, p.phiFrom);
    PathNode n = p.table->nodes().front();
    n.phi += p.phiOffset;
    return n;
}

PathNode Path::end() const {
    const PathPiece& p = m_pieces.back();
    if (p.kind == PathPiece::Kind::Pivot) {
        PathNode n = pivotNode(p, p.phiTo);
        n.s = m_length;
        return n;
    }
    PathNode n = p.table->nodes().back();
    n.phi += p.phiOffset;
    n.s = m_length;
    return n;
}

int Path::pivotCount() const {
    int n = 0;
    for (const PathPiece& p : m_pieces)
        n += p.kind == PathPiece::Kind::Pivot;
    return n;
}

std::shared_ptr<const Path> buildPath(const PathSource& source, std::size_t halvingBudget) {
    switch (source.kind) {
    case PathKind::Graph: {
        Expression y = Expression::compile(source.y, "x", "y(x)");
        return std::make_shared<const Path>(
            singleCurve(std::make_shared<GraphCurve>(y, source.from, source.to), halvingBudget));
    }
    case PathKind::Parametric: {
        Expression x = Expression::compile(source.xOfU, "u", "x(u)");
        Expression y = Expression::compile(source.yOfU, "u", "y(u)");
        return std::make_shared<const Path>(piecesThroughCusps(
            std::make_shared<ParametricCurve>(x, y, source.from, source.to), 1, halvingBudget));
    }
    case PathKind::Polyline: {
        auto pts = distinctPoints(source);
        if (!(source.smoothing >= 0) || !std::isfinite(source.smoothing))
            throw InputError("smoothing",
                             "must be a finite number >= 0, got " + formatNumber(source.smoothing));
        if (!(source.cornerAngle >= 0 && source.cornerAngle <= 180))
            throw InputError("corner_angle", "must be between 0 and 180 degrees, got " +
                                                 formatNumber(source.cornerAngle));
        if (source.corners == CornerMode::Pivot || pts.size() == 2)
            return std::make_shared<const Path>(
                pivotPolyline(pts, source.cornerAngle, source.smoothing, halvingBudget));
        std::vector<double> xs, ys;
        for (auto [x, y] : pts) {
            xs.push_back(x);
            ys.push_back(y);
        }
        return std::make_shared<const Path>(
            singleCurve(std::make_shared<SplineCurve>(xs, ys, source.smoothing), halvingBudget));
    }
    case PathKind::Geodesic:
        throw InputError("path", "a geodesic track is built with its closed form (buildScenePath)");
    }
    throw InputError("path", "unknown path kind");
}

CornerMode cornerModeFromName(const std::string& name) {
    if (name == "pivot")
        return CornerMode::Pivot;
    if (name == "smooth")
        return CornerMode::Smooth;
    throw InputError("corners", "unknown corner mode '" + name + "' (use pivot or smooth)");
}

std::string cornerModeName(CornerMode mode) {
    return mode == CornerMode::Pivot ? "pivot" : "smooth";
}

namespace {

std::string trimmed(const std::string& s) {
    auto b = s.find_first_not_of(" \t");
    auto e = s.find_last_not_of(" \t");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

} // namespace

void setPathExpressions(PathSource& path, const std::string& text, const std::string& where) {
    const auto semicolon = text.find(';');
    const bool parametric = semicolon != std::string::npos;
    if (parametric && text.find(';', semicolon + 1) != std::string::npos)
        throw InputError(where, "use \"y=EXPR\" or \"x=EXPR;y=EXPR\"");
    auto rhs = [&](const std::string& part, char name) {
        const std::string t = trimmed(part);
        if (t.size() < 2 || t[0] != name || trimmed(t.substr(1)).rfind('=', 0) != 0)
            throw InputError(where, std::string("expected ") + name + "=EXPR, got '" + t + "'");
        return trimmed(trimmed(t.substr(1)).substr(1));
    };
    if (parametric) {
        path.kind = PathKind::Parametric;
        path.xOfU = rhs(text.substr(0, semicolon), 'x');
        path.yOfU = rhs(text.substr(semicolon + 1), 'y');
    } else {
        path.kind = PathKind::Graph;
        path.y = rhs(text, 'y');
    }
}

} // namespace chaplygin
