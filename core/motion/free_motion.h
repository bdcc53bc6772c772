#pragma once
#include "systems/system.h"

#include <array>
#include <complex>
#include <string>
#include <vector>

namespace chaplygin {

/// Initial state of the free motion (the controlled motion's state at t = 0).
struct FreeInitial {
    double x = 0, y = 0, phi = 0, sdot = 0, phidot = 0;
};

struct FreeState {
    double x = 0, y = 0, phi = 0, sdot = 0, phidot = 0;
    double energy = 0; ///< T = (m/2)(sdot^2 + b^2 phidot^2) [J]
};

/// The free (Lagrange-d'Alembert / Neimark-Fufaev) sleigh, paper (D12)-(D15):
/// sddot = a phidot^2, phiddot = -a sdot phidot/b^2. Velocities and heading in closed form
/// (docs/physics.md §4): sdot = V tanh(kt + c), phidot = sigma (V/b) sech(kt + c),
/// phi = phi0 + sigma (b/a)(gd(kt + c) - gd(c)), k = aV/b^2, c = asinh(sdot0/(b|phidot0|)),
/// with gd(kt + c) - gd(c) = 2 atan(sinh(kt/2)/cosh(c + kt/2)) (no cancellation).
/// Position: z = x + iy integrates sdot e^{i phi} by 8-point Gauss-Legendre panels narrower than
/// both time scales (1/k and b/V), so it is exact to rounding; inside a panel z is the integral of
/// the integrand's degree-16 Chebyshev interpolant (certified by its tail to 1e-15 of the panel's
/// displacement, else Gauss-Legendre over the partial panel); past |kt + c| > 40 the heading is
/// constant to 1e-17 and the body moves on a straight line, also in closed form.
class FreeMotion {
  public:
    FreeMotion(const DerivedSystem& system, const FreeInitial& initial, double horizon);
    FreeState at(double t) const;
    double horizon() const { return m_horizon; }
    /// The heading's change phi(t) - phi0 [rad], to full relative precision however small.
    double turn(double t) const;
    /// The heading's whole change phi(inf) - phi0 [rad] (+-inf on a uniform circle).
    double totalTurn() const;
    /// The model used for the velocities and for the position, for the Solution's report.
    std::string velocityModel() const;
    std::string positionModel() const;
    /// The closed form's constants (physics.md sec. 1): V, k = aV/b^2, c = atanh(sdot0/V) and
    /// sigma = sign(phidot0); general is false for rest, a line or a circle (then k = c = 0).
    struct Constants {
        double v = 0, k = 0, c = 0, sigma = 1;
        bool general = false;
    };
    Constants constants() const { return {m_v, m_k, m_c, m_sigma, m_case == Case::General}; }

  private:
    enum class Case { Rest, Line, Circle, General };
    void velocities(double t, double* sdot, double* phidot, double* phi) const;
    std::complex<double> panelIntegral(double t0, double t1) const;
    void buildInterpolants();

    DerivedSystem m_sys;
    FreeInitial m_init;
    double m_horizon;
    Case m_case = Case::General;
    double m_v = 0, m_k = 0, m_c = 0, m_sigma = 1, m_beta = 0;
    double m_expC = 1, m_expMinusC = 1; // e^c, e^-c
    double m_tail = 0;                  // time after which the heading is constant
    std::vector<double> m_panelT;
    std::vector<std::complex<double>> m_panelZ;
    // per panel: Chebyshev coefficients of z - z(panel start) in the panel's local variable
    // (the integral of the degree-16 interpolant of sdot e^{i phi}), when certified
    std::vector<std::array<std::array<double, 2>, 18>> m_panelCheb;
    std::vector<char> m_chebCertified;
};

} // namespace chaplygin
