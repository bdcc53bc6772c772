#pragma once
#include "paths/curve.h"
#include "paths/expression.h"

namespace chaplygin {

/// The graph y = f(x) on [x0, x1]: r(x) = (x, f(x)).
class GraphCurve final : public Curve {
  public:
    GraphCurve(Expression y, double x0, double x1);
    CurvePoint eval(double u) const override;
    double u0() const override { return m_x0; }
    double u1() const override { return m_x1; }
    std::string parameterName() const override { return "x"; }

  private:
    Expression m_y;
    double m_x0, m_x1;
};

/// The parametric curve r(u) = (x(u), y(u)) on [u0, u1].
class ParametricCurve final : public Curve {
  public:
    ParametricCurve(Expression x, Expression y, double u0, double u1);
    CurvePoint eval(double u) const override;
    double u0() const override { return m_u0; }
    double u1() const override { return m_u1; }
    std::string parameterName() const override { return "u"; }

  private:
    Expression m_x, m_y;
    double m_u0, m_u1;
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
