#pragma once
// A path as pieces in order of traversal: tabulated curves, driven forwards or backing up, and
// pivots at corners (docs/physics.md §3).
#include "paths/path_source.h"
#include "paths/path_table.h"

#include <memory>
#include <vector>

namespace chaplygin {

/// One piece of a path: a smooth tabulated curve, or a corner where the body pivots in place
/// about the knife point, turning from phiFrom to phiTo (docs/physics.md §3).
struct PathPiece {
    enum class Kind { Curve, Pivot };
    Kind kind = Kind::Curve;
    std::shared_ptr<const PathTable> table; ///< Curve only
    double phiOffset = 0;                   ///< Curve: 2 pi n added to the table's phi
                                            ///< (pi more when backing up)
    /// Curve: +1 when the body moves along its heading, -1 when it backs up (the stretch after
    /// a cusp; docs/physics.md §3): the heading is the table's phi + pi and sdot < 0
    int direction = 1;
    double psiOffset = 0; ///< Curve: 2 pi n keeping Psi continuous through the cusps before it
    double x = 0, y = 0, phiFrom = 0, phiTo = 0; ///< Pivot only
    double s0 = 0;                               ///< arc length at the start of the piece
};

/// A path as the core sees it: pieces in order of traversal, built once per path change.
class Path {
  public:
    explicit Path(std::vector<PathPiece> pieces);
    const std::vector<PathPiece>& pieces() const { return m_pieces; }
    double length() const { return m_length; }
    /// Geometry at the start (s = 0) and at the end.
    PathNode start() const;
    PathNode end() const;
    /// Number of pivot corners.
    int pivotCount() const;

  private:
    std::vector<PathPiece> m_pieces;
    double m_length = 0;
};

/// A curve with cusps inside as pieces, one per stretch between them, the first driven in
/// `firstDirection` (+1 forwards, -1 backing up) and the others alternating; the heading is
/// continuous (the tangent line), and so is Psi (docs/physics.md §3).
std::vector<PathPiece> piecesThroughCusps(const std::shared_ptr<const Curve>& curve,
                                          int firstDirection,
                                          std::size_t halvingBudget = PathTable::kHalvingBudget);

/// Builds and tabulates the path within a budget of panel halvings per piece (PathTable). Throws
/// InputError naming the expression position, the x or u where the path breaks, or the point of a
/// polyline. A geodesic track
/// is built by buildScenePath (core/planning).
std::shared_ptr<const Path> buildPath(const PathSource& source,
                                      std::size_t halvingBudget = PathTable::kHalvingBudget);

} // namespace chaplygin
