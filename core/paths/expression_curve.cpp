#include "paths/expression_curve.h"

#include <cmath>

namespace chaplygin {

GraphCurve::GraphCurve(Expression y, double x0, double x1)
    : m_y(std::move(y)), m_x0(x0), m_x1(x1) {}

CurvePoint GraphCurve::eval(double u) const {
    Jet3 f = m_y.jet(u);
    CurvePoint p;
    p.x = u;
    p.y = f.v;
    p.dx = 1;
    p.dy = f.d1;
    p.ddy = f.d2;
    p.dddy = f.d3;
    return p;
}

ParametricCurve::ParametricCurve(Expression x, Expression y, double u0, double u1)
    : m_x(std::move(x)), m_y(std::move(y)), m_u0(u0), m_u1(u1) {}

CurvePoint ParametricCurve::eval(double u) const {
    Jet3 fx = m_x.jet(u), fy = m_y.jet(u);
    return {fx.v, fy.v, fx.d1, fy.d1, fx.d2, fy.d2, fx.d3, fy.d3};
}

SegmentCurve::SegmentCurve(double x0, double y0, double x1, double y1)
    : m_x0(x0), m_y0(y0), m_length(std::hypot(x1 - x0, y1 - y0)) {
    m_cos = (x1 - x0) / m_length;
    m_sin = (y1 - y0) / m_length;
}

CurvePoint SegmentCurve::eval(double u) const {
    CurvePoint p;
    p.x = m_x0 + u * m_cos;
    p.y = m_y0 + u * m_sin;
    p.dx = m_cos;
    p.dy = m_sin;
    return p;
}

} // namespace chaplygin
