// The certification of a panel's Chebyshev interpolants (docs/numerics.md §7) against the exact
// curve: an ellipse's position, curvature and arc length from its closed forms and GSL's
// quadrature; the certified bound holds where it was not checked; a panel that needs halving
// when the budget is spent is left to exact evaluation; a cusp's panel gets no interpolant.
#include "gsl_quadrature.h"
#include "numerics/chebyshev.h"
#include "paths/expression_curve.h"
#include "paths/panel_certifier.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace chaplygin;

namespace {

// r(u) = (2 cos u, sin u): |r'| = sqrt(4 sin²u + cos²u), kappa = 2/|r'|³ (x'y'' - y'x'' = 2)
ParametricCurve ellipse(double u0, double u1) {
    return ParametricCurve(Expression::compile("2*cos(u)", "u", "x(u)"),
                           Expression::compile("sin(u)", "u", "y(u)"), u0, u1);
}

double ellipseSpeed(double u) {
    return std::sqrt(4 * std::sin(u) * std::sin(u) + std::cos(u) * std::cos(u));
}

struct Certification {
    std::vector<PanelSums> leaves;
    Certifier certifier;
    explicit Certification(const Curve& c, std::size_t halvings)
        : certifier{.curve = c,
                    .piecewise = false,
                    .lengthScale = 2.0,
                    .cuspStart = NAN,
                    .cuspEnd = NAN,
                    .halvingsLeft = halvings,
                    .leaves = leaves} {}
};

// quantity q of kept panel k at xi in [-1, 1]
double interpolated(const Certifier& c, std::size_t k, PathTable::Quantity q, double xi) {
    const PathTable::ChebPanel& p = c.cheb[k];
    std::vector<double> series;
    for (int i = 0; i < p.degree + 2; ++i)
        series.push_back(c.rows[p.row + i][q]);
    return cheb::evaluate(series.data(), static_cast<int>(series.size()), xi);
}

} // namespace

TEST(PanelCertifier, EllipseInterpolantsMeetTheirCertifiedBounds) {
    const ParametricCurve c = ellipse(0, 1.5);
    Certification run(c, 16);
    run.certifier.certify(computePanel(c, 0, 1.5, 2.0), 0, INFINITY);
    const Certifier& cert = run.certifier;
    ASSERT_FALSE(cert.cheb.empty());
    ASSERT_EQ(cert.cheb.size(), run.leaves.size());
    EXPECT_EQ(cert.bounds.exactPanels, 0);
    // the kept panels tile [0, 1.5] in order
    EXPECT_EQ(run.leaves.front().a, 0.0);
    EXPECT_EQ(run.leaves.back().b, 1.5);
    for (std::size_t k = 1; k < run.leaves.size(); ++k)
        EXPECT_EQ(run.leaves[k].a, run.leaves[k - 1].b);
    double worstPosition = 0, worstKappa = 0, worstLength = 0;
    for (std::size_t k = 0; k < cert.cheb.size(); ++k) {
        ASSERT_TRUE(cert.cheb[k].certified) << k;
        EXPECT_LE(cert.cheb[k].bound, 1.0);
        const double a = run.leaves[k].a, b = run.leaves[k].b;
        for (int j = 0; j <= 40; ++j) { // points between the Chebyshev nodes as well
            const double xi = -1 + j / 20.0, u = 0.5 * (a + b) + 0.5 * (b - a) * xi;
            const double speed = ellipseSpeed(u);
            worstPosition =
                std::max({worstPosition,
                          std::fabs(interpolated(cert, k, PathTable::kX, xi) - 2 * std::cos(u)),
                          std::fabs(interpolated(cert, k, PathTable::kY, xi) - std::sin(u))});
            worstKappa =
                std::max(worstKappa, std::fabs(interpolated(cert, k, PathTable::kKappa, xi) -
                                               2 / (speed * speed * speed)));
            const double s =
                test::gslIntegral(ellipseSpeed, a, u, 1e-14, 0, test::GslRule::GaussKronrod61, 100);
            worstLength =
                std::max(worstLength, std::fabs(interpolated(cert, k, PathTable::kS, xi) - s));
        }
    }
    // the certified bounds (twice the coefficient tail or the deviation at the checked points,
    // docs/numerics.md §7) hold off the points they were checked at, to rounding
    EXPECT_LE(worstPosition, cert.bounds.position + 8e-16);
    EXPECT_LE(worstKappa, cert.bounds.kappa + 8e-15);
    EXPECT_LE(worstLength, cert.bounds.arcLength + 1e-14); // GSL to 1e-14
    EXPECT_LT(cert.bounds.position, 1e-10);
    EXPECT_LT(worstPosition, 1e-10);
}

TEST(PanelCertifier, APanelThatNeedsHalvingWithNoBudgetStaysExact) {
    // sin(40 u) over [0, 3]: 19 periods in one panel; no degree resolves it
    const ParametricCurve c(Expression::compile("u", "u", "x(u)"),
                            Expression::compile("sin(40*u)", "u", "y(u)"), 0, 3);
    Certification run(c, 0);
    run.certifier.certify(computePanel(c, 0, 3, 2.0), 0, INFINITY);
    ASSERT_EQ(run.certifier.cheb.size(), 1u);
    EXPECT_FALSE(run.certifier.cheb[0].certified);
    EXPECT_EQ(run.certifier.bounds.exactPanels, 1);
    EXPECT_EQ(run.certifier.halvingsLeft, 0u);
    // with a budget the same panel is halved until it is certified
    Certification halved(c, 64);
    halved.certifier.certify(computePanel(c, 0, 3, 2.0), 0, INFINITY);
    EXPECT_GT(halved.certifier.cheb.size(), 1u);
    EXPECT_EQ(halved.certifier.bounds.exactPanels, 0);
    EXPECT_EQ(halved.leaves.size(), halved.certifier.cheb.size());
    EXPECT_EQ(64u - halved.certifier.halvingsLeft, halved.leaves.size() - 1);
}

TEST(PanelCertifier, ACuspsPanelHasNoInterpolant) {
    const ParametricCurve c = ellipse(0, 1.5);
    Certification run(c, 16);
    run.certifier.cuspStart = 0;
    run.certifier.certify(computePanel(c, 0, 1.5, 2.0), 0, INFINITY);
    ASSERT_EQ(run.certifier.cheb.size(), 1u);
    EXPECT_FALSE(run.certifier.cheb[0].certified);
    EXPECT_EQ(run.certifier.halvingsLeft, 16u);
}
