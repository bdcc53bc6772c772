#pragma once
// The free (Lagrange-d'Alembert) sleigh in closed form, its position from certified per-panel
// interpolants (docs/physics.md §4).
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
    /// The free body's control angle and chi (docs/physics.md §4): (sdot, b phidot) =
    /// V (sin psi, cos psi), psi in (-pi/2, pi/2) turning left and (pi/2, 3pi/2) turning right,
    /// continuous; chi = psi - (a/b) phi, constant since its lambda is 0.
    double psi = 0, chi = 0;
};

/// The free (Lagrange-d'Alembert / Neimark-Fufaev) sleigh, paper (D12)-(D15):
/// sddot = a phidot^2, phiddot = -a sdot phidot/b^2. Velocities and heading in closed form
/// (docs/physics.md §4): sdot = V tanh(kt + c), phidot = sigma (V/b) sech(kt + c),
/// phi = phi0 + sigma (b/a)(gd(kt + c) - gd(c)), k = aV/b^2, c = asinh(sdot0/(b|phidot0|)),
/// with gd(kt + c) - gd(c) = 2 atan(sinh(kt/2)/cosh(c + kt/2)) (no cancellation).
/// Position: z = x + iy integrates sdot e^{i phi} over panels narrower than both time scales
/// (1/k and b/V) as the integral of the integrand's degree-16 Chebyshev interpolant, certified
/// to 1e-15 of the panel's displacement by its tail and by the exact integrand at a point between
/// the interpolation points (a panel that fails is integrated by 8-point Gauss-Legendre, whole and
/// partial). Inside a panel sdot, phidot and phi come from their degree-16 interpolants,
/// certified the same way to 1e-15 of V, V/b and of phi (else from the closed forms). Past
/// |kt + c| > 40 the heading is constant to 1e-17 and the body moves on a straight line, also in
/// closed form.
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
    /// The closed form's constants (docs/physics.md §4): V, k = aV/b^2, c = atanh(sdot0/V) and
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
    // appends the panel [t0, t1] with its interpolants, halved while its position is not
    // certified (up to three times)
    void addPanel(double t0, double t1, int depth);

    DerivedSystem m_sys;
    FreeInitial m_init;
    double m_horizon;
    Case m_case = Case::General;
    double m_v = 0, m_k = 0, m_c = 0, m_sigma = 1, m_beta = 0;
    double m_expC = 1, m_expMinusC = 1; // e^c, e^-c
    double m_tail = 0;                  // time after which the heading is constant
    std::vector<double> m_panelT;
    std::vector<std::complex<double>> m_panelZ;
    // per panel, Chebyshev coefficients in the panel's local variable of: x and y - z(panel
    // start) (the integral of the degree-16 interpolant of sdot e^{i phi}), and sdot, phidot,
    // phi - phi(panel start) (degree 16); each group used where certified, else the panel is
    // integrated by the Gauss rule and the velocities are evaluated
    enum Series { kZx, kZy, kSdot, kPhidot, kPhi, kSeries = 6 };
    std::vector<std::array<std::array<double, kSeries>, 18>> m_panelCheb;
    std::vector<char> m_positionCertified, m_velocityCertified;
    std::vector<double> m_panelPhi; // phi at each panel's start: its series is of phi - that
};

} // namespace chaplygin
