#pragma once
// Internal to paths/ (path_table.cpp): the certification of a path table's per-panel Chebyshev
// interpolants (docs/numerics.md §7).
#include "paths/panel_geometry.h"

#include <array>
#include <cstddef>
#include <vector>

namespace chaplygin {

/// A panel's interpolants while they are built and certified, before the table packs them
/// (PathTable::ChebPanel: the same coefficients and samples, degree + 2 and degree + 1 of them).
/// Only the first degree + 2 rows and degree + 1 samples are written.
struct Interpolant {
    std::array<PathTable::Row, cheb::kPoints + 1> c;
    std::array<PathTable::Sample, cheb::kPoints> samples;
    PathTable::ChebPanel panel;
};

/// The per-panel Chebyshev interpolants of a path table (PathTable::ChebPanel), certified
/// against the exact curve; panels that miss their tolerance are halved (docs/numerics.md §7).
struct Certifier {
    const Curve& curve;
    bool piecewise; // the curve has breakpoints
    double lengthScale;
    double cuspStart, cuspEnd;      // u of a cusp at either end, or NaN
    std::size_t halvingsLeft;       // of the table's budget; when none are left, panels stay exact
    std::vector<PanelSums>& leaves; // the kept panels' sums (empty at the start)
    std::vector<PathTable::ChebPanel> cheb{};
    std::vector<PathTable::Row> rows{};
    std::vector<PathTable::Sample> samples{};
    PathTable::Bounds bounds{};

    // Splits a panel whose interpolants miss their tolerance. A resolved function's error falls
    // by orders of magnitude per halving; when a halving gains less than a factor 4 the error is
    // the rounding noise of the exact evaluation itself (a jittery interpolating spline), which
    // no panel can beat: the panel is kept with that measured bound (noiseLimited). A panel that
    // needs halving when the budget is spent is left to exact evaluation.
    void certify(const PanelData& d, int depth, double parentScore);

    // Takes a knot interval of a piecewise curve as one panel, without the refinement's
    // comparison against its halves, when its interpolants are certified and the stiff time-law
    // integrand (PanelData::stiff) is resolved to `stiffTolerance`: the Chebyshev tails then bound
    // the error of the panel's Gauss sums. Returns false, keeping nothing, otherwise.
    bool acceptWhole(const PanelData& d, double stiffTolerance);

  private:
    void keep(const PanelData& d, const Interpolant& in, const PathTable::Bounds& b);
};

} // namespace chaplygin
