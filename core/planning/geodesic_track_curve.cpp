#include "planning/geodesic_track_curve.h"

#include <cmath>
#include <complex>

namespace chaplygin {

GeodesicTrackCurve::GeodesicTrackCurve(const GeodesicTrack& track)
    : m_track(track), m_unit(track.psi0, track.lambda0) {}

CurvePoint GeodesicTrackCurve::eval(double u) const {
    using C = std::complex<double>;
    const UnitGeodesicPoint q = m_unit.at(u);
    const double s = q.sinPsi, c = q.cosPsi;
    const double lambda =
        m_track.lambda0 * std::cos(q.phi) - std::sin(m_track.psi0) * std::sin(q.phi);
    const C frame = m_track.b * std::polar(1.0, m_track.phi);
    const C heading = std::polar(1.0, q.phi);
    // z'' = A e^{i theta}, z''' = (A' + i cos Psi A) e^{i theta}
    const C a(c * lambda, s * c);
    const C da(-s * lambda * lambda - s * c * c, (c * c - s * s) * lambda);
    const C z = C(m_track.x, m_track.y) + frame * C(q.x, q.y);
    const C d1 = frame * s * heading;
    const C d2 = frame * a * heading;
    const C d3 = frame * (da + C(0, c) * a) * heading;
    return {z.real(), z.imag(), d1.real(), d1.imag(), d2.real(), d2.imag(), d3.real(), d3.imag()};
}

} // namespace chaplygin
