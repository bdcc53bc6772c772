#pragma once
// The time law t(s) along a tabulated path and its inverse, the body's place at a time
// (docs/physics.md §2, docs/numerics.md §7).
#include "control/control_law.h"
#include "paths/path.h"

#include <array>
#include <memory>
#include <mutex>
#include <vector>

namespace chaplygin {

/// Where the body is on the path at a time: a piece, and the curve parameter u in it (Curve)
/// or the time since the pivot began (Pivot).
struct PathLocation {
    int piece = 0;
    double u = 0;
    double sincePivotStart = 0;
    int panel = 0; ///< Curve: the path table's panel holding u
    double xi = 0; ///< Curve: u in that panel, mapped to [-1, 1]
};

/// The time law t(s) and its inverse for one path and one set of control parameters.
/// Energy mode: dt/ds = sqrt(1 + b^2 kappa^2)/v_T (docs/physics.md §2), summed over the path
/// table's Gauss nodes; pivots take b |dphi|/v_T. Speed mode: t = s/v_s (App. C).
/// Building it never re-tabulates the path: it costs one pass over the stored nodes.
/// On a panel with certified interpolants (PathTable::ChebPanel) t(u) within the panel is the
/// integral of the Chebyshev interpolant of dt/du through its points (degree 8 or 16), built on the
/// panel's first use (thread-safe: an atomic flag per panel) and certified there: twice its
/// coefficient tail, and its integral over the panel against the 8-point Gauss rule, within 1e-13
/// of the panel's time. locate() inverts it by Newton on that polynomial, from the quintic Hermite
/// interpolant of the inverse. Panels that fail use the exact curve. Construction costs what it
/// did before interpolation: 8 square roots per panel.
class TimeLaw {
  public:
    /// Throws InputError when the mode cannot follow the path (a corner in Speed mode) or the
    /// speed is not a finite positive number.
    TimeLaw(std::shared_ptr<const Path> path, const ControlParams& params);

    double duration() const { return m_pieceStart.back(); }
    double pieceStart(int piece) const { return m_pieceStart[piece]; }
    /// Times at the panel ends of a Curve piece.
    const std::vector<double>& nodeTimes(int piece) const { return m_nodeTimes[piece]; }
    /// t at parameter u of a Curve piece, from the interpolant where it is certified.
    double timeAt(int piece, double u) const;
    /// The reference: exact curve evaluation, Gauss quadrature over the partial panel.
    double timeAtExact(int piece, double u) const;
    /// The inverse: where the body is at time t (clamped to [0, duration]).
    PathLocation locate(double t) const;
    /// The same by Newton on the exact timeAtExact (the reference).
    PathLocation locateExact(double t) const;
    /// dt/du at u of a Curve piece from the interpolant (the controlled ODE's right-hand side is
    /// its inverse).
    double rateAt(int piece, double u) const;
    /// True when every piece's time law is closed form (lines, circles, pivots, Speed mode).
    bool closedForm() const { return m_closedForm; }

    /// Per panel: coefficients c[k][0] of t - t(panel start) and c[k][1] of dt/dxi.
    struct TimePanel {
        std::array<std::array<double, 2>, cheb::kPoints + 1> c{};
        std::size_t rows = 0; ///< the coefficients in use (the rest are zero), once built
        double rateStart = 0, rateEnd = 0;           ///< dt/dxi at xi = -1 and 1
        double rateSlopeStart = 0, rateSlopeEnd = 0; ///< d^2t/dxi^2 there
        double bound = 0;                            ///< error bound of t over the panel [s]
        bool certified = false;
    };
    /// Whether a Curve piece has interpolated panels (not closed form, not a pivot).
    bool interpolated(int piece) const { return m_lazy[piece] != nullptr; }
    /// Panel k of a Curve piece with interpolated panels, built on first use.
    const TimePanel& timePanel(int piece, int k) const;
    /// Builds every panel: the largest error bound of t over the certified ones [s], and the
    /// number left to exact evaluation.
    double timeBound() const;
    int exactPanels() const;

  private:
    struct Lazy;
    double rate(double speed, double kappa) const;            // dt/du
    double exactRate(const PathTable& table, double u) const; // dt/du, the limit at a cusp
    void buildPanel(int piece, int k, TimePanel& out) const;
    PathLocation curveLocation(int piece, int panel, double u) const;
    // the panel holding u; with its certified interpolant (null if none) and u mapped to it
    struct CertifiedPanel {
        int index = 0;
        const TimePanel* panel = nullptr;
        double xi = 0, halfWidth = 0;
    };
    CertifiedPanel certifiedPanelOf(int piece, double u) const;
    std::shared_ptr<const Path> m_path;
    ControlParams m_params;
    std::vector<double> m_pieceStart; // size pieces + 1
    std::vector<std::vector<double>> m_nodeTimes;
    std::vector<std::shared_ptr<Lazy>> m_lazy; // per piece; shared by copies (same values)
    bool m_closedForm = true;
};

} // namespace chaplygin
