// Path tabulation: arc length, unwrapped heading, curvature, domain errors with their place,
// drawn polylines (pivots and smoothing splines).
#include "common/input_error.h"
#include "paths/path.h"
#include "paths/spline_curve.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

using namespace chaplygin;

namespace {

PathSource graph(const std::string& y, double x0, double x1) {
    PathSource p;
    p.kind = PathKind::Graph;
    p.y = y;
    p.from = x0;
    p.to = x1;
    return p;
}

std::string errorOf(const PathSource& p, std::size_t halvingBudget = PathTable::kHalvingBudget) {
    try {
        buildPath(p, halvingBudget);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(Paths, ParabolaArcLengthCurvatureAndHeading) {
    auto path = buildPath(graph("x^2", -1, 2));
    const PathTable& t = *path->pieces().front().table;
    // arc length of y = x^2: [x sqrt(1+4x^2)/2 + asinh(2x)/4]
    auto arc = [](double x) { return x * std::sqrt(1 + 4 * x * x) / 2 + std::asinh(2 * x) / 4; };
    EXPECT_NEAR(path->length(), arc(2) - arc(-1), 1e-12);
    for (double x : {-0.7, 0.0, 0.31, 1.9}) {
        PathNode n = t.at(x);
        EXPECT_NEAR(n.s, arc(x) - arc(-1), 1e-12);
        EXPECT_NEAR(n.kappa, 2 / std::pow(1 + 4 * x * x, 1.5), 1e-13);
        EXPECT_NEAR(n.dkappa, -24 * x / std::pow(1 + 4 * x * x, 3), 1e-12); // dkappa/dx / (ds/dx)
        EXPECT_NEAR(n.phi, std::atan(2 * x), 1e-14);
        EXPECT_NEAR(t.uAtArcLength(n.s), x, 1e-13);
    }
}

// x0 > x1: the same parabola from right to left, so the parameter is u = -x; heading,
// curvature and arc length change with the direction, dkappa/ds does not
TEST(Paths, ReversedGraphRunsFromRightToLeft) {
    auto path = buildPath(graph("x^2", 1, -1));
    const PathTable& t = *path->pieces().front().table;
    auto arc = [](double x) { return x * std::sqrt(1 + 4 * x * x) / 2 + std::asinh(2 * x) / 4; };
    EXPECT_NEAR(path->length(), arc(1) - arc(-1), 1e-12);
    EXPECT_EQ(path->start().x, 1);
    EXPECT_EQ(path->end().x, -1);
    const double phi0 = path->start().phi; // the tangent (-1, -2)/sqrt(5)
    EXPECT_NEAR(std::cos(phi0), -1 / std::sqrt(5.0), 1e-15);
    EXPECT_NEAR(std::sin(phi0), -2 / std::sqrt(5.0), 1e-15);
    for (double x : {0.8, 0.31, 0.0, -0.7}) {
        PathNode n = t.at(-x);
        EXPECT_NEAR(n.x, x, 1e-15);
        EXPECT_NEAR(n.y, x * x, 1e-15);
        EXPECT_NEAR(n.s, arc(1) - arc(x), 1e-12);
        EXPECT_NEAR(n.kappa, -2 / std::pow(1 + 4 * x * x, 1.5), 1e-13); // a right turn
        EXPECT_NEAR(n.dkappa, -24 * x / std::pow(1 + 4 * x * x, 3), 1e-12);
        EXPECT_NEAR(n.phi - phi0, std::atan(2 * x) - std::atan(2.0), 1e-14);
        EXPECT_NEAR(t.uAtArcLength(n.s), -x, 1e-13);
    }
    // messages name the x of the graph, not the internal parameter
    EXPECT_NE(
        errorOf(graph("sqrt(x)", 1, -1)).find("path at x = 0: the path has no finite tangent"),
        std::string::npos)
        << errorOf(graph("sqrt(x)", 1, -1));
    // a reversed parametric range: the unit circle clockwise from u = pi to u = 0
    PathSource p;
    p.kind = PathKind::Parametric;
    p.xOfU = "cos(u)";
    p.yOfU = "sin(u)";
    p.from = std::numbers::pi;
    p.to = 0;
    auto circle = buildPath(p);
    EXPECT_NEAR(circle->length(), std::numbers::pi, 1e-12);
    EXPECT_NEAR(circle->start().x, -1, 1e-15);
    EXPECT_NEAR(circle->end().x, 1, 1e-15);
    EXPECT_NEAR(circle->end().phi - circle->start().phi, -std::numbers::pi, 1e-12);
    EXPECT_NEAR(circle->pieces().front().table->at(-std::numbers::pi / 2).kappa, -1, 1e-13);
}

TEST(Paths, HeadingIsUnwrappedAroundSeveralTurns) {
    PathSource p;
    p.kind = PathKind::Parametric;
    p.xOfU = "cos(u)";
    p.yOfU = "sin(u)";
    p.from = 0;
    p.to = 6 * std::numbers::pi;
    auto path = buildPath(p);
    EXPECT_NEAR(path->end().phi - path->start().phi, 6 * std::numbers::pi, 1e-12);
    EXPECT_NEAR(path->pieces().front().table->at(5 * std::numbers::pi).phi, 5.5 * std::numbers::pi,
                1e-12);
    EXPECT_TRUE(path->pieces().front().table->uniform());
}

// A curve whose curvature the table cannot resolve within its budget (50,000 panel halvings) is
// refused quickly, naming a place: a cosine 3,500 m tall and 0.8 m wide has tips of radius 4 um.
// y = sin(20 x) on [0, 100] (42,000 panels) stays within it.
TEST(Paths, UnresolvableCurvatureRefusedWithinTheBudget) {
    const std::string e = errorOf(graph("exp(3*e)*cos(3*e*x)", -1, 1));
    EXPECT_NE(e.find("path at x = "), std::string::npos) << e;
    EXPECT_NE(e.find("needs more than 50,000 panels"), std::string::npos) << e;
    EXPECT_EQ(errorOf(graph("sin(20*x)", 0, 30)), "");
}

TEST(Paths, DomainProblemsNameTheirPlace) {
    EXPECT_NE(errorOf(graph("1/x", -1, 1)).find("path at x = "), std::string::npos)
        << errorOf(graph("1/x", -1, 1));
    EXPECT_NE(errorOf(graph("1/x", 0, 1)).find("path at x = 0:"), std::string::npos)
        << errorOf(graph("1/x", 0, 1));
    EXPECT_NE(errorOf(graph("sqrt(x)", -1, 1)).find("path at x = -1:"), std::string::npos);
    EXPECT_NE(errorOf(graph("ln(x)", 0, 2)).find("path at x = 0:"), std::string::npos);
    EXPECT_NE(errorOf(graph("exp(x)", 0, 800)).find("path at x = "), std::string::npos)
        << errorOf(graph("exp(x)", 0, 800));
    // a vertical tangent at the end of a y(x) graph
    EXPECT_NE(errorOf(graph("sqrt(1 - x^2)", -1, 1))
                  .find("path at x = -1: the path has no finite tangent"),
              std::string::npos)
        << errorOf(graph("sqrt(1 - x^2)", -1, 1));
    EXPECT_NE(errorOf(graph("x", 1, 1)).find("x-range"), std::string::npos);
    // a cusp at the end of the range has no direction to start or end with
    PathSource cusp;
    cusp.kind = PathKind::Parametric;
    cusp.xOfU = "u^2";
    cusp.yOfU = "u^3";
    cusp.from = 0;
    cusp.to = 1;
    EXPECT_NE(errorOf(cusp).find("path at u = 0: the path stops here"), std::string::npos)
        << errorOf(cusp);
}

TEST(Paths, PolylineWithPivotsHasSegmentsAndCorners) {
    PathSource p;
    p.kind = PathKind::Polyline;
    p.points = {{0, 0}, {1, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}};
    auto path = buildPath(p);
    EXPECT_EQ(path->pivotCount(), 2); // collinear and repeated points are no corner
    EXPECT_NEAR(path->length(), 4, 1e-14);
    EXPECT_NEAR(path->end().phi, std::numbers::pi, 1e-14);
    p.points = {{0, 0}, {0, 0}};
    EXPECT_NE(errorOf(p).find("at least 2 distinct points"), std::string::npos);
    p.points = {{0, 0}, {NAN, 1}};
    EXPECT_NE(errorOf(p).find("point 2"), std::string::npos);
}

// The smoothing spline is the minimiser of sum (p_i - g(t_i))^2 + alpha \int g''^2
// (spline_curve.h): a natural cubic spline (g'' = 0 at the ends, C2 at the knots) whose residual at
// each knot is alpha times the jump of g''' there (set the first variation to zero and integrate by
// parts twice). Checked per coordinate for a jittery stroke with uneven spacing, and for
// interpolation; with pinned ends (infinite weights there) the first and last residuals vanish.
TEST(Paths, SmoothingSplineMinimisesItsCriterion) {
    std::vector<double> xs, ys;
    for (int i = 0; i < 300; ++i) {
        const double t = 0.02 * i + 0.007 * ((i * 37) % 11); // uneven spacing
        xs.push_back(3 * std::cos(t) + 0.01 * ((i * 7919) % 13 - 6) / 6.0);
        ys.push_back(2 * std::sin(1.3 * t) + 0.01 * ((i * 104729) % 7 - 3) / 3.0);
    }
    for (auto [bandwidth, ends] :
         {std::pair{10.0, SplineCurve::Ends::Free}, std::pair{2.0, SplineCurve::Ends::Free},
          std::pair{0.0, SplineCurve::Ends::Free}, std::pair{10.0, SplineCurve::Ends::Pinned},
          std::pair{2.0, SplineCurve::Ends::Pinned}}) {
        SplineCurve spline(xs, ys, bandwidth, ends);
        // pinned ends weigh their points infinitely: the curve passes through them
        const bool pinned = ends == SplineCurve::Ends::Pinned;
        const int n = static_cast<int>(xs.size());
        std::vector<double> t(n, 0.0); // the knots: cumulative chord length
        for (int i = 1; i < n; ++i)
            t[i] = t[i - 1] + std::hypot(xs[i] - xs[i - 1], ys[i] - ys[i - 1]);
        const double h = t.back() / (n - 1);
        const double alpha = std::pow(bandwidth * h, 4) / h;
        ASSERT_EQ(spline.u0(), 0);
        ASSERT_NEAR(spline.u1(), t.back(), 1e-12 * t.back());
        std::vector<CurvePoint> piece(n - 1); // each piece at its interval's midpoint
        for (int i = 0; i + 1 < n; ++i)
            piece[i] = spline.eval(0.5 * (t[i] + t[i + 1]));
        // residuals against alpha times the jumps; g, g', g'' from both sides of each knot
        // (relative to the largest of each over the knots)
        double worst = 0;
        std::array<double, 3> gap{}, size{};
        for (int i = 0; i < n; ++i) {
            const CurvePoint right = spline.eval(i + 1 < n ? t[i] : std::nextafter(t[i], 0.0));
            const CurvePoint left = spline.eval(i > 0 ? std::nextafter(t[i], 0.0) : t[i]);
            const double jumpX = (i + 1 < n ? piece[i].dddx : 0) - (i > 0 ? piece[i - 1].dddx : 0);
            const double jumpY = (i + 1 < n ? piece[i].dddy : 0) - (i > 0 ? piece[i - 1].dddy : 0);
            const double weight = pinned && (i == 0 || i + 1 == n) ? 0.0 : alpha;
            worst = std::max({worst, std::fabs(xs[i] - right.x - weight * jumpX),
                              std::fabs(ys[i] - right.y - weight * jumpY)});
            const std::array<std::array<double, 4>, 3> d = {{
                {right.x, left.x, right.y, left.y},
                {right.dx, left.dx, right.dy, left.dy},
                {right.ddx, left.ddx, right.ddy, left.ddy},
            }};
            for (int k = 0; k < 3; ++k) {
                gap[k] =
                    std::max({gap[k], std::fabs(d[k][0] - d[k][1]), std::fabs(d[k][2] - d[k][3])});
                size[k] = std::max({size[k], std::fabs(d[k][0]), std::fabs(d[k][2])});
            }
        }
        EXPECT_LT(worst, 1e-12) << "bandwidth " << bandwidth;
        // continuity holds as far as the linear solve does: rounding times the condition of
        // R + alpha Q^T Q (a fourth difference, ~1e5 here)
        for (int k = 0; k < 3; ++k)
            EXPECT_LT(gap[k], 1e-10 * size[k]) << "derivative " << k << ", bandwidth " << bandwidth;
        const CurvePoint first = spline.eval(t.front()), last = spline.eval(t.back());
        EXPECT_LT(std::max({std::fabs(first.ddx), std::fabs(first.ddy), std::fabs(last.ddx),
                            std::fabs(last.ddy)}),
                  1e-13 * size[2])
            << "natural ends, bandwidth " << bandwidth;
    }
}

TEST(Paths, SmoothingSplineGivesSmoothCurvatureForAShakyCircle) {
    PathSource p;
    p.kind = PathKind::Polyline;
    p.corners = CornerMode::Smooth;
    p.smoothing = 10; // jitter of a fifth of the point spacing needs a wide bandwidth
    const int n = 200;
    const double R = 3;
    for (int i = 0; i <= n; ++i) {
        double th = std::numbers::pi * i / n;
        double wobble = 0.01 * ((i * 7919) % 13 - 6) / 6.0; // deterministic "hand" jitter of 1 cm
        p.points.emplace_back((R + wobble) * std::cos(th), (R + wobble) * std::sin(th));
    }
    auto path = buildPath(p);
    const PathTable& t = *path->pieces().front().table;
    double u0 = t.nodes().front().u, u1 = t.nodes().back().u;
    // away from the natural ends (kappa = 0 there) the curvature is that of the circle,
    // and along the whole path it varies smoothly: no jitter from the noisy points
    std::vector<double> kappa;
    for (int i = 0; i <= 400; ++i)
        kappa.push_back(t.at(u0 + (u1 - u0) * i / 400.0).kappa);
    for (int i = 1; i < 400; ++i) {
        if (i >= 80 && i <= 320) {
            EXPECT_NEAR(kappa[i], 1 / R, 0.05 / R) << i;
        }
        EXPECT_LT(std::fabs(kappa[i + 1] - 2 * kappa[i] + kappa[i - 1]), 0.005 / R) << i;
    }
    // with no smoothing the spline interpolates the points, and the jitter shows in kappa
    p.smoothing = 0;
    auto exact = buildPath(p);
    double rough = 0;
    for (int i = 1; i < 400; ++i) {
        auto k = [&](int j) {
            return exact->pieces().front().table->at(u0 + (u1 - u0) * j / 400.0).kappa;
        };
        rough = std::max(rough, std::fabs(k(i + 1) - 2 * k(i) + k(i - 1)));
    }
    EXPECT_GT(rough, 100 * 0.005 / R);
    CurvePoint q = exact->pieces().front().table->curve().eval(0);
    EXPECT_NEAR(q.x, p.points[0].first, 1e-12);
    EXPECT_NEAR(q.y, p.points[0].second, 1e-12);
}

// The certification of the interpolants shares the budget: when it is spent, the panels that
// still miss their tolerance are left to exact evaluation, which keeps every value exact.
TEST(Paths, CertificationStopsAtTheBudgetAndLeavesPanelsExact) {
    const PathSource tall = graph("100*cos(10*x)", -1, 1);
    auto full = buildPath(tall);
    const PathTable& whole = *full->pieces().front().table;
    ASSERT_EQ(whole.bounds().exactPanels, 0);
    const std::size_t budget = whole.halvings() - 10;
    auto limited = buildPath(tall, budget);
    const PathTable& t = *limited->pieces().front().table;
    EXPECT_LE(t.halvings(), budget);
    EXPECT_GT(t.bounds().exactPanels, 0);
    EXPECT_LT(t.nodes().size(), whole.nodes().size());
    for (int i = 0; i <= 2000; ++i) {
        const double u = -1 + 2.0 * i / 2000;
        const PathNode a = t.at(u), b = t.interpolatedAt(u), c = whole.at(u);
        EXPECT_NEAR(b.x, a.x, 1e-12) << u;
        EXPECT_NEAR(b.y, a.y, 1e-12 * 100) << u;
        EXPECT_NEAR(b.kappa, a.kappa, 1e-12 * std::fabs(a.kappa) + 1e-12) << u;
        EXPECT_NEAR(b.s, c.s, 1e-12 * full->length()) << u;
    }
    EXPECT_NEAR(limited->length(), full->length(), 1e-13 * full->length());
    // a budget the refinement alone exceeds is refused, naming the budget
    const std::string e = errorOf(tall, 100);
    EXPECT_NE(e.find("path at x = "), std::string::npos) << e;
    EXPECT_NE(e.find("needs more than 100 panels"), std::string::npos) << e;
}
