#pragma once
// The cubic smoothing spline through a drawn stroke's points.
#include "paths/curve.h"

#include <vector>

namespace chaplygin {

/// A parametric cubic smoothing spline through noisy points (what a mouse draws).
/// Parameter u is the cumulative chord length. Each coordinate minimises
/// sum (g_i - p_i)^2 + alpha \int g''^2 du (Reinsch; Green and Silverman, ch. 2), with
/// alpha = (w h)^4 / h for mean point spacing h and a bandwidth of w spacings, so a shaky line
/// gets a smooth, C2 curve whose curvature is continuous. w = 0 interpolates.
class SplineCurve final : public Curve {
  public:
    /// Ends::Pinned passes exactly through the first and the last point (infinite weights in
    /// Green and Silverman's weighted penalised sum of squares), so stretches between the corners
    /// of a stroke meet at them.
    enum class Ends { Free, Pinned };
    SplineCurve(const std::vector<double>& x, const std::vector<double>& y, double bandwidth,
                Ends ends = Ends::Free);
    CurvePoint eval(double u) const override;
    double u0() const override { return m_knots.front(); }
    double u1() const override { return m_knots.back(); }
    std::string parameterName() const override { return "u"; }
    std::vector<double> breakpoints() const override { return m_knots; }

  private:
    struct Coordinate {
        std::vector<double> g;     // values at the knots
        std::vector<double> gamma; // second derivatives at the knots (natural: 0 at the ends)
    };
    struct Factor {                    // R + alpha Q^T Q = L D L^T, pentadiagonal
        std::vector<double> invH;      // 1 / (t_{i+1} - t_i)
        std::vector<double> d, l1, l2; // D, and L's first and second subdiagonals
    };
    Factor factor(double alpha) const;
    Coordinate smooth(const std::vector<double>& data, double alpha, const Factor& f) const;
    // 1 / weight of knot i's point: 0 at a pinned end, else 1
    double looseness(std::size_t i) const {
        return m_ends == Ends::Pinned && (i == 0 || i + 1 == m_knots.size()) ? 0.0 : 1.0;
    }

    Ends m_ends;

    std::vector<double> m_knots;
    // the cubic of each knot interval in a = u - t_i: x = sum cx_k a^k, y = sum cy_k a^k
    struct Piece {
        double cx[4], cy[4];
    };
    std::vector<Piece> m_pieces;
};

} // namespace chaplygin
