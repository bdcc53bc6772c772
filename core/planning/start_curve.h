#pragma once
// The curve of starts (docs/physics.md §10): the initial data (Psi0, Lambda0) from which a geodesic
// of the normalised problem can reach a target, traced on a grid, and the pieces of it where Newton
// starts.
#include <vector>

namespace chaplygin {

// (-pi, pi]
double wrapAngle(double a);

// the target in the start's frame, lengths in b: the normalised problem (docs/physics.md §10)
struct Target {
    double X = 0, Y = 0, Phi = 0;
};

// a geodesic of the normalised problem: Psi0, Lambda0 = b Psidot0 / v_T and t v_T / b
struct UnitSolution {
    double psi0 = 0, lambda0 = 0, t = 0;
};

// a point of the curve with the passages' along-P misses: at the n-th passage,
// t = t + n period and the miss is along + n drift
struct CurvePoint {
    double psi0 = 0, lambda0 = 0;
    bool valid = false;
    double t = 0, period = 0, along = 0, drift = 0;
    double k = 0;
};

CurvePoint curvePoint(double psi0, double lambda0, const Target& tg);

// A piece of the curve over which the n-th passage of a and the m-th of b miss on opposite
// sides along P, and the time interpolated there.
struct SeedPiece {
    CurvePoint a;
    int n = 0;
    CurvePoint b;
    int m = 0;
    double t = 0;
};

// The grid: columns over Psi0 in (-pi, pi], rows du apart in asinh Lambda0.
struct GridSize {
    int columns = 96;
    double du = 0.05;
};

// Seeds for Newton: where the along-P miss of one passage changes sign between two neighbouring
// points of the curve G = 0, traced cell by cell on a grid in (Psi0, asinh Lambda0).
std::vector<SeedPiece> curveSeeds(const Target& tg, double tMax, double kMax, GridSize size);

// Newton's start from a piece: halve it (its middle put back on the curve) while the passage
// continues, then interpolate. Done only for the pieces Newton is run from.
UnitSolution refineSeed(SeedPiece piece, const Target& tg);

} // namespace chaplygin
