#include "scene/finite_results.h"

#include "common/input_error.h"
#include "scene/csv_columns.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace chaplygin {
namespace {

// the curvature is left out: it is infinite at a cusp by design (docs/physics.md §3)
bool finiteNode(const PathNode& n) {
    return std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.phi) && std::isfinite(n.s);
}

std::string place(double x, double y) {
    return "path at (" + formatNumber(x) + ", " + formatNumber(y) + ")";
}

// what a path this far out does to double precision, when that is the likely cause
std::string sizeHint(double x, double y) {
    if (std::fabs(x) < 1e100 && std::fabs(y) < 1e100)
        return "";
    return "; coordinates this large (" + formatNumber(std::max(std::fabs(x), std::fabs(y))) +
           " m) overflow double precision in the path's arithmetic";
}

// a path far out: its body's positions are rounded to more than the canvas's smallest pixel,
// and its pixels overflow at the canvas's zooms
void requireWithinReach(double x, double y) {
    const double far = std::max(std::fabs(x), std::fabs(y));
    if (far > kMaxPathExtent)
        throw InputError(place(x, y), "lies " + formatNumber(far) +
                                          " m from the origin; a path must lie within " +
                                          formatNumber(kMaxPathExtent) +
                                          " m of it (beyond, double precision cannot resolve "
                                          "the body's motion and the canvas cannot draw it)");
}

bool includes(const MotionParts& parts, const MotionParts& column) {
    return (column.controlled && parts.controlled) || (column.free && parts.free) ||
           (column.vakonomic && parts.vakonomic) || (column.perturbed && parts.perturbed) ||
           !(column.controlled || column.free || column.vakonomic || column.perturbed);
}

std::string parametersOf(const Scene& scene) {
    std::string out;
    for (const auto& [name, value] : scene.system.params)
        out += (out.empty() ? "" : ", ") + name + " = " + formatNumber(value);
    return out;
}

} // namespace

void requireFinitePath(const Path& path) {
    for (const PathPiece& piece : path.pieces()) {
        if (piece.kind == PathPiece::Kind::Pivot) {
            if (!std::isfinite(piece.x) || !std::isfinite(piece.y) ||
                !std::isfinite(piece.phiFrom) || !std::isfinite(piece.phiTo))
                throw InputError(place(piece.x, piece.y),
                                 "the corner's position or turn is not finite");
            continue;
        }
        const PathTable& table = *piece.table;
        const auto& nodes = table.nodes();
        for (std::size_t k = 0; k < nodes.size(); ++k) {
            const PathNode& n = nodes[k];
            if (!finiteNode(n))
                throw InputError(place(n.x, n.y),
                                 "the tabulated path is not finite here" + sizeHint(n.x, n.y));
            if (k + 1 == nodes.size())
                break;
            // the interpolant the body's pose and the canvas read (PathTable::interpolatedAt)
            for (double xi : {-1.0, 0.0, 1.0}) {
                const PathNode m = table.interpolatedAt(int(k), xi);
                if (!finiteNode(m))
                    throw InputError(place(n.x, n.y), "the path's interpolant is not finite here" +
                                                          sizeHint(n.x, n.y));
            }
        }
    }
    // finite, and within reach
    for (const PathPiece& piece : path.pieces()) {
        if (piece.kind == PathPiece::Kind::Pivot)
            requireWithinReach(piece.x, piece.y);
        else
            for (const PathNode& n : piece.table->nodes())
                requireWithinReach(n.x, n.y);
    }
}

void requireFiniteSample(const MotionSample& m, const MotionParts& parts,
                         const std::string& context) {
    for (const CsvColumn& c : csvColumnsWritten(m.perturbed)) {
        if (!includes(parts, csvColumnParts(c)))
            continue;
        const double v = c.value(m);
        if (!std::isfinite(v))
            throw InputError(
                "", "column " + std::string(c.name) + " is not finite at t = " + formatNumber(m.t) +
                        " s: " + std::string(c.meaning) + " is " + formatNumber(v) + context);
    }
}

void requireFiniteSolution(const Solution& solution) {
    requireFinitePath(*solution.path());
    const std::string context = " (the scene's parameters: " + parametersOf(solution.scene()) +
                                "; speed " + formatNumber(solution.scene().speed) + ")";
    const MotionParts controlled{true, false, false, false};
    for (const MotionSample& m : solution.controlledAtNodes())
        requireFiniteSample(m, controlled, context);
    for (const MotionSample& m : solution.sample(kFiniteCheckTimes))
        requireFiniteSample(m, {}, context);
}

} // namespace chaplygin
