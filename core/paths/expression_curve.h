#pragma once
// The curves of typed expressions, a graph y(x) and a parametric x(u), y(u), and the straight
// segment.
#include "paths/curve.h"
#include "paths/expression.h"

namespace chaplygin {

/// The graph y = f(x) from x0 to x1: r(x) = (x, f(x)). With x0 > x1 it is traversed from right
/// to left, through the increasing parameter u = -x.
class GraphCurve final : public Curve {
  public:
    GraphCurve(Expression y, double x0, double x1);
    CurvePoint eval(double u) const override;
    double u0() const override { return m_sign * m_x0; }
    double u1() const override { return m_sign * m_x1; }
    std::string parameterName() const override { return "x"; }
    double parameterValue(double u) const override { return m_sign * u + 0.0; } // no -0

  private:
    Expression m_y;
    double m_x0, m_x1;
    double m_sign; // +1, or -1 for a reversed range
};

/// The parametric curve r(u) = (x(u), y(u)) from u0 to u1 (from right to left if u0 > u1,
/// through the increasing parameter -u).
class ParametricCurve final : public Curve {
  public:
    ParametricCurve(Expression x, Expression y, double u0, double u1);
    CurvePoint eval(double u) const override;
    double u0() const override { return m_sign * m_u0; }
    double u1() const override { return m_sign * m_u1; }
    std::string parameterName() const override { return "u"; }
    double parameterValue(double u) const override { return m_sign * u + 0.0; } // no -0

  private:
    Expression m_x, m_y;
    double m_u0, m_u1;
    double m_sign; // +1, or -1 for a reversed range
};

/// The straight segment from (x0, y0) to (x1, y1), u in [0, length].
class SegmentCurve final : public Curve {
  public:
    SegmentCurve(double x0, double y0, double x1, double y1);
    CurvePoint eval(double u) const override;
    double u0() const override { return 0; }
    double u1() const override { return m_length; }
    std::string parameterName() const override { return "s"; }
    bool straight() const override { return true; }

  private:
    double m_x0, m_y0, m_cos, m_sin, m_length;
};

} // namespace chaplygin
