#include "planning/plan_track.h"

#include "common/input_error.h"
#include "planning/geodesic_track_curve.h"

#include <cmath>
#include <numbers>

namespace chaplygin {
namespace {

using std::numbers::pi;

void checkTrack(const GeodesicTrack& g) {
    auto finite = [](double v, const char* name) {
        if (!std::isfinite(v))
            throw InputError(std::string("path ") + name,
                             "must be a finite number, got " + formatNumber(v));
    };
    finite(g.x, "from x");
    finite(g.y, "from y");
    finite(g.phi, "from phi");
    finite(g.b, "b");
    finite(g.psi0, "psi0");
    finite(g.lambda0, "lambda0");
    finite(g.length, "length");
    if (!(g.b > 0))
        throw InputError("path b", "must be > 0, got " + formatNumber(g.b));
    if (!(g.length > 0))
        throw InputError("path length", "must be > 0, got " + formatNumber(g.length));
}

} // namespace

PathSource planTrack(const PlanRequest& request, const PlannedGeodesic& motion) {
    if (motion.family == GeodesicFamily::Rest || !(motion.t > 0))
        throw InputError("plan", "the target is the start (t = 0): there is no track to follow");
    PathSource source;
    source.kind = PathKind::Geodesic;
    GeodesicTrack& g = source.geodesic;
    g.x = request.from.x;
    g.y = request.from.y;
    g.phi = request.from.phi;
    g.b = request.system.b;
    g.psi0 = motion.psi0;
    g.lambda0 = motion.family == GeodesicFamily::Pivot || motion.family == GeodesicFamily::Line
                    ? 0.0
                    : g.b * motion.psidot0 / request.vT;
    g.length = request.vT * motion.t;
    return source;
}

std::shared_ptr<const Path> buildGeodesicTrack(const GeodesicTrack& track,
                                               std::size_t halvingBudget) {
    checkTrack(track);
    const double sinPsi0 = std::fabs(track.psi0) == pi ? 0.0 : std::sin(track.psi0);
    if (sinPsi0 == 0 && track.lambda0 == 0) {
        // Psi stays at 0 (turning left) or pi (right): a pivot about P by length/b
        PathPiece pivot;
        pivot.kind = PathPiece::Kind::Pivot;
        pivot.x = track.x;
        pivot.y = track.y;
        pivot.phiFrom = track.phi;
        pivot.phiTo = track.phi + std::copysign(track.length / track.b, std::cos(track.psi0));
        return std::make_shared<const Path>(std::vector<PathPiece>{pivot});
    }
    std::vector<PathPiece> pieces = piecesThroughCusps(std::make_shared<GeodesicTrackCurve>(track),
                                                       sinPsi0 < 0 ? -1 : 1, halvingBudget);
    // the tables' headings are atan2's: turn every stretch by the same 2 pi n so that the body
    // starts at the track's phi
    const PathPiece& first = pieces.front();
    const double start = first.table->nodes().front().phi + first.phiOffset;
    const double shift = 2 * pi * std::round((track.phi - start) / (2 * pi));
    for (PathPiece& p : pieces)
        p.phiOffset += shift;
    return std::make_shared<const Path>(std::move(pieces));
}

} // namespace chaplygin
