#pragma once
// The curve of starts (docs/physics.md §10): the initial data (Psi0, Lambda0) from which a geodesic
// of the normalised problem can reach a target, traced on a grid, and the pieces of it where Newton
// starts.
#include <limits>
#include <vector>

namespace chaplygin {

/// The angle in (-pi, pi].
double wrapAngle(double a);

/// The target in the start's frame, lengths in b: the normalised problem (docs/physics.md §10).
struct UnitTarget {
    double X = 0, Y = 0, Phi = 0;
};

/// A geodesic of the normalised problem: Psi0, Lambda0 = b Psidot0 / v_T and t v_T / b.
struct UnitSolution {
    double psi0 = 0, lambda0 = 0, t = 0;
    /// 1 - k^2 when it is carried exactly (next to the separatrix, where Lambda0 is then rounded
    /// from +-sqrt(cos^2 Psi0 - gap)); NaN: from Psi0 and Lambda0
    double gap = std::numeric_limits<double>::quiet_NaN();
};

/// A point (Psi0, Lambda0) of the curve G = 0 with its passages: the n-th passage through the
/// target's pendulum state comes at t + n period and misses the target along P by along + n drift.
/// Not valid where the pendulum never passes that state (another orbit, the separatrix level).
struct StartPoint {
    double psi0 = 0, lambda0 = 0;
    bool valid = false;
    double t = 0, period = 0, along = 0, drift = 0;
    double k = 0; ///< the pendulum's modulus
};

/// The point's passages, for (psi0, lambda0) on the curve (G = 0 to rounding).
StartPoint startPoint(double psi0, double lambda0, const UnitTarget& tg);

/// A piece of the curve over which the n-th passage of a and the m-th of b miss on opposite
/// sides along P, and the time interpolated there.
struct SeedPiece {
    StartPoint a;
    int n = 0;
    StartPoint b;
    int m = 0;
    double t = 0;
};

/// The tracing's resolution: columns over Psi0 in (-pi, pi], and pieces of the curve at most du
/// long in asinh Lambda0 (halved otherwise; the rows of the grid where one is used).
struct GridSize {
    int columns = 96;
    double du = 0.05;
};

/// Seeds for Newton: where the along-P miss of one passage arriving by tMax changes sign between
/// two neighbouring points of the curve G = 0, traced column by column over Psi0 (G is quadratic
/// in Lambda0: each column holds the curve's points exactly) out to |Lambda0| = kMax, its rough
/// pieces halved; sorted by their time.
std::vector<SeedPiece> curveSeeds(const UnitTarget& tg, double tMax, double kMax, GridSize size);

/// Newton's start from a piece: halve it (its middle put back on the curve) while the passage
/// continues, then interpolate. Done only for the pieces Newton is run from.
UnitSolution refineSeed(SeedPiece piece, const UnitTarget& tg);

} // namespace chaplygin
