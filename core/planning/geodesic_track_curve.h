#pragma once
// The knife track of a geodesic as a plane curve, from the closed form of the genuine vakonomic
// motion (docs/physics.md §8, §10), with exact derivatives up to the third.
#include "paths/curve.h"
#include "paths/path_source.h"
#include "planning/unit_geodesic.h"

namespace chaplygin {

/// r(u) = (x0, y0) + b R(phi0) z(u), z the unit geodesic (Psi0, Lambda0) at normalised time
/// u = v_T t / b in [0, length/b]. With P = (sin Psi0, Lambda0) and the unit heading theta:
/// z' = sin Psi e^{i theta}, theta' = cos Psi, Psi' = Lambda = P_y cos theta - P_x sin theta,
/// Lambda' = -sin Psi cos Psi; so r' vanishes exactly where the body reverses (a cusp).
class GeodesicTrackCurve final : public Curve {
  public:
    explicit GeodesicTrackCurve(const GeodesicTrack& track);
    CurvePoint eval(double u) const override;
    double u0() const override { return 0; }
    double u1() const override { return m_track.length / m_track.b; }
    std::string parameterName() const override { return "v_T t/b"; }

  private:
    GeodesicTrack m_track;
    UnitGeodesic m_unit;
};

} // namespace chaplygin
