#pragma once
// Internal to paths/ (path.cpp): a stretch of a curve between its cusps.
#include "paths/curve.h"

#include <memory>

namespace chaplygin {

/// A curve restricted to [ua, ub] inside its range, with the same parameter (the stretches of a
/// path between its cusps).
class SubCurve final : public Curve {
  public:
    SubCurve(std::shared_ptr<const Curve> whole, double ua, double ub);
    CurvePoint eval(double u) const override { return m_whole->eval(u); }
    double u0() const override { return m_ua; }
    double u1() const override { return m_ub; }
    std::string parameterName() const override { return m_whole->parameterName(); }
    double parameterValue(double u) const override { return m_whole->parameterValue(u); }
    std::vector<double> breakpoints() const override;

  private:
    std::shared_ptr<const Curve> m_whole;
    double m_ua, m_ub;
};

} // namespace chaplygin
