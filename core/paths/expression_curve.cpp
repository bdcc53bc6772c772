#include "paths/expression_curve.h"

#include <cmath>

namespace chaplygin {

namespace {

// r(sign u) differentiated in u: odd derivatives change sign with the direction
CurvePoint oriented(const Jet3& x, const Jet3& y, double sign) {
    return {x.v, y.v, sign * x.d1, sign * y.d1, x.d2, y.d2, sign * x.d3, sign * y.d3};
}

} // namespace

GraphCurve::GraphCurve(Expression y, double x0, double x1)
    : m_y(std::move(y)), m_x0(x0), m_x1(x1), m_sign(x0 > x1 ? -1.0 : 1.0) {}

CurvePoint GraphCurve::eval(double u) const {
    double x = m_sign * u;
    return oriented({x, 1, 0, 0}, m_y.jet(x), m_sign);
}

ParametricCurve::ParametricCurve(Expression x, Expression y, double u0, double u1)
    : m_x(std::move(x)), m_y(std::move(y)), m_u0(u0), m_u1(u1), m_sign(u0 > u1 ? -1.0 : 1.0) {}

CurvePoint ParametricCurve::eval(double u) const {
    double v = m_sign * u;
    return oriented(m_x.jet(v), m_y.jet(v), m_sign);
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
