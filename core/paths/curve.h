#pragma once
// A parametrised plane curve with exact derivatives up to the third, and its local geometry.
#include <string>
#include <vector>

namespace chaplygin {

/// A point of a plane curve r(u) = (x(u), y(u)) with exact derivatives up to the third.
struct CurvePoint {
    double x = 0, y = 0;
    double dx = 0, dy = 0;
    double ddx = 0, ddy = 0;
    double dddx = 0, dddy = 0;
};

/// A parametrised plane curve on [u0, u1], traversed in the direction of increasing u.
class Curve {
  public:
    virtual ~Curve() = default;
    virtual CurvePoint eval(double u) const = 0;
    virtual double u0() const = 0;
    virtual double u1() const = 0;
    /// The name of the parameter in messages: "x" for a graph y(x), "u" otherwise.
    virtual std::string parameterName() const = 0;
    /// The value of that parameter at u, for messages (a reversed range runs through -x).
    virtual double parameterValue(double u) const { return u; }
    /// Parameter values where a derivative may jump (spline knots); tabulation panels end there.
    virtual std::vector<double> breakpoints() const { return {}; }
    /// True for a straight segment parametrised by arc length (tabulated as one closed-form
    /// panel).
    virtual bool straight() const { return false; }
};

/// Local geometry derived from a CurvePoint.
struct CurveGeometry {
    double speed = 0;   ///< ds/du = |r'(u)|
    double kappa = 0;   ///< signed curvature (x'y'' - y'x'')/|r'|^3, left turn > 0
    double dkappa = 0;  ///< d kappa / ds
    double heading = 0; ///< atan2(y', x') in (-pi, pi]
};
CurveGeometry geometryOf(const CurvePoint& p);

} // namespace chaplygin
