// The path table's interpolants against the exact curve and closed forms, the time law's
// interpolant against its exact quadrature, and panel counts that do not waste.
#include "gsl_quadrature.h"
#include "paths/expression_curve.h"
#include "paths/path.h"
#include "paths/spline_curve.h"
#include "scene/presets.h"
#include "scene/solution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <numbers>
#include <random>

using namespace chaplygin;

namespace {

double wrap(double d) {
    return d - 2 * std::numbers::pi * std::round(d / (2 * std::numbers::pi));
}

int panelCount(const Path& path) {
    int n = 0;
    for (const PathPiece& p : path.pieces())
        if (p.kind == PathPiece::Kind::Curve)
            n += static_cast<int>(p.table->panels().size());
    return n;
}

// the interpolated geometry against the exact curve at random u; returns the largest errors
struct Errors {
    double position = 0, phi = 0, kappa = 0, dkappa = 0, s = 0;
};
Errors interpolationErrors(const PathTable& table, int samples = 4000) {
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> dist(table.curve().u0(), table.curve().u1());
    Errors e;
    for (int i = 0; i < samples; ++i) {
        double u = dist(gen);
        PathNode a = table.interpolatedAt(u), x = table.at(u);
        e.position = std::max(e.position, std::hypot(a.x - x.x, a.y - x.y));
        e.phi = std::max(e.phi, std::fabs(a.phi - x.phi));
        e.kappa = std::max(e.kappa, std::fabs(a.kappa - x.kappa));
        e.dkappa = std::max(e.dkappa, std::fabs(a.dkappa - x.dkappa));
        e.s = std::max(e.s, std::fabs(a.s - x.s));
    }
    return e;
}

// GSL's adaptive Gauss-Kronrod (21 points) on [a, b]
double qag(const std::function<double(double)>& f, double a, double b) {
    return test::gslIntegral(f, a, b, 0, 2e-14, test::GslRule::GaussKronrod21, 200);
}

} // namespace

TEST(PathTable, CatenaryInterpolantsMatchEqs97To99) {
    // arc-length parametrised: x = sqrt(s^2 + 1), y = asinh s, kappa = -1/(s^2 + 1) (errata)
    auto path = buildPath(presetScene("catenary").path);
    const PathTable& table = *path->pieces().front().table;
    ASSERT_FALSE(table.uniform());
    EXPECT_EQ(table.bounds().exactPanels, 0);
    for (double u = 0; u <= 5; u += 0.0037) {
        PathNode n = table.interpolatedAt(u);
        const double q = u * u + 1;
        EXPECT_NEAR(n.x, std::sqrt(q), 1e-14) << u;
        EXPECT_NEAR(n.y, std::asinh(u), 1e-14) << u;
        EXPECT_NEAR(n.s, u, 1e-14) << u;
        EXPECT_NEAR(n.kappa, -1 / q, 1e-14) << u;
        EXPECT_NEAR(n.dkappa, 2 * u / (q * q), 1e-13) << u;
        // the heading of (u/sqrt(q), 1/sqrt(q))
        EXPECT_NEAR(wrap(n.phi - std::atan2(1, u)), 0, 1e-14) << u;
    }
    std::cout << "catenary: " << table.panels().size() << " panels, bounds position "
              << table.bounds().position << " heading " << table.bounds().heading << " kappa "
              << table.bounds().kappa << " dkappa " << table.bounds().dkappa << "\n";
}

TEST(PathTable, InterpolantsStayWithinTheirBoundsOnEveryKindOfCurve) {
    std::vector<PathSource> sources;
    sources.push_back(presetScene("sinusoid").path);
    PathSource spiral;
    spiral.kind = PathKind::Parametric;
    spiral.xOfU = "u*cos(u)";
    spiral.yOfU = "u*sin(u)";
    spiral.from = 0.5;
    spiral.to = 20;
    sources.push_back(spiral);
    PathSource stroke; // a shaky hand-drawn arc, smoothed
    stroke.kind = PathKind::Polyline;
    stroke.corners = CornerMode::Smooth;
    stroke.smoothing = 2;
    for (int i = 0; i < 60; ++i) {
        double a = 0.05 * i;
        stroke.points.push_back({3 * std::cos(a) + 0.01 * std::sin(7.0 * i),
                                 3 * std::sin(a) + 0.01 * std::cos(5.0 * i)});
    }
    sources.push_back(stroke);
    for (const PathSource& source : sources) {
        auto path = buildPath(source);
        const PathTable& table = *path->pieces().front().table;
        Errors e = interpolationErrors(table);
        const PathTable::Bounds& b = table.bounds();
        std::cout << table.panels().size() << " panels, exact " << b.exactPanels << ": position "
                  << e.position << " (bound " << b.position << "), phi " << e.phi << " ("
                  << b.heading << "), kappa " << e.kappa << " (" << b.kappa << "), dkappa "
                  << e.dkappa << " (" << b.dkappa << "), s " << e.s << "\n";
        EXPECT_EQ(b.exactPanels, 0);
        // the certified bound, with a factor 4 for estimating it from the tail and 8 points
        EXPECT_LE(e.position, 4 * b.position + 1e-15);
        EXPECT_LE(e.phi, 4 * b.heading + 1e-15);
        EXPECT_LE(e.kappa, 4 * b.kappa + 1e-15);
        EXPECT_LE(e.dkappa, 4 * b.dkappa + 1e-14);
        EXPECT_LE(e.s, 4 * b.arcLength + 16 * 2.2e-16 * table.length());
        EXPECT_LE(e.position, 1e-13);
    }
}

TEST(PathTable, StraightSegmentsTakeOnePanel) {
    PathSource square;
    square.kind = PathKind::Polyline;
    square.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    auto path = buildPath(square);
    EXPECT_EQ(panelCount(*path), 3);
    PathSource zigzag; // a hand-drawn zig-zag of 45 segments with pivots
    zigzag.kind = PathKind::Polyline;
    for (int i = 0; i <= 45; ++i)
        zigzag.points.push_back({0.3 * i, (i % 2) * 0.7 + 0.01 * i});
    EXPECT_EQ(panelCount(*buildPath(zigzag)), 45);
    // y = 0.5 x + 1 (the line preset): one panel, closed form
    auto line = buildPath(presetScene("line").path);
    EXPECT_EQ(panelCount(*line), 1);
    EXPECT_TRUE(line->pieces().front().table->uniform());
    // a full circle: panels of at most 1 rad of turn
    auto circle = buildPath(presetScene("circle").path);
    EXPECT_TRUE(circle->pieces().front().table->uniform());
    EXPECT_LE(panelCount(*circle), 8);
    EXPECT_GE(panelCount(*circle), 7);
}

TEST(PathTable, ClosedFormGeometryOnLinesAndCirclesMatchesTheCurve) {
    for (const char* name : {"line", "circle"}) {
        auto path = buildPath(presetScene(name).path);
        const PathTable& table = *path->pieces().front().table;
        ASSERT_TRUE(table.uniform());
        EXPECT_TRUE(table.chebPanels().empty());
        Errors e = interpolationErrors(table, 2000);
        EXPECT_LE(e.position, 1e-14) << name;
        EXPECT_LE(e.phi, 1e-14) << name;
        EXPECT_LE(e.s, 1e-14) << name;
    }
}

TEST(TimeLawTable, InterpolatedTimeLawMatchesTheExactQuadrature) {
    for (const char* name : {"catenary", "sinusoid"}) {
        for (double b : {0.5, 1.0, 4.0}) {
            Scene scene = presetScene(name);
            scene.system.params["b"] = b;
            Solution sol = Solution::compute(scene);
            TimeLaw law(sol.path(), sol.params());
            EXPECT_EQ(law.exactPanels(), 0) << name << " b = " << b;
            const PathTable& table = *sol.path()->pieces().front().table;
            for (int i = 0; i <= 500; ++i) {
                double t = law.duration() * i / 500.0;
                PathLocation fast = law.locate(t), exact = law.locateExact(t);
                EXPECT_NEAR(fast.u, exact.u, 1e-13) << name << " b = " << b << " t = " << t;
                double u = table.nodes().front().u +
                           (table.nodes().back().u - table.nodes().front().u) * i / 500.0;
                EXPECT_NEAR(law.timeAt(0, u), law.timeAtExact(0, u), 1e-13) << name;
                CurveGeometry g = geometryOf(table.curve().eval(u));
                double rate = g.speed * std::sqrt(1 + b * b * g.kappa * g.kappa) / scene.speed;
                EXPECT_NEAR(law.rateAt(0, u), rate, 1e-13 * rate) << name;
            }
        }
    }
}

// a smoothed stroke is one cubic per knot interval: one panel each; an interpolating spline
// through jittery points has rounding noise in its derivatives that the bounds report
TEST(PathTable, DrawnStrokesAreCertifiedWithFewPanels) {
    for (double smoothing : {10.0, 0.0}) {
        PathSource p;
        p.kind = PathKind::Polyline;
        p.corners = CornerMode::Smooth;
        p.smoothing = smoothing;
        const int n = 500;
        for (int i = 0; i <= n; ++i) {
            double th = std::numbers::pi * i / n;
            double wobble = 0.01 * ((i * 7919) % 13 - 6) / 6.0;
            p.points.emplace_back((3 + wobble) * std::cos(th), (3 + wobble) * std::sin(th));
        }
        auto path = buildPath(p);
        const PathTable& table = *path->pieces().front().table;
        Errors e = interpolationErrors(table, 2000);
        std::cout << "stroke smoothing " << smoothing << ": " << table.panels().size()
                  << " panels, exact " << table.bounds().exactPanels << ", position " << e.position
                  << " bound " << table.bounds().position << " dkappa " << e.dkappa << " bound "
                  << table.bounds().dkappa << "\n";
        EXPECT_EQ(table.bounds().exactPanels, 0);
        EXPECT_LE(e.position, 1e-13);
        EXPECT_LE(e.position, 4 * table.bounds().position + 1e-15);
        EXPECT_LE(e.dkappa, 4 * table.bounds().dkappa + 1e-14);
        if (smoothing > 0) {
            EXPECT_LE(table.panels().size(), 510u); // 500 knot intervals
        }
    }
}

// A smoothed stroke's knot intervals are each taken as one panel, without halving, when their
// interpolants certify; the Gauss sums the arc length and the time law rest on then agree with
// GSL's adaptive quadrature over every knot interval, for b from 1 to 100 times the path's size
// (the sharpest time-law integrand the table resolves, docs/numerics.md §7).
TEST(PathTable, WholeKnotIntervalsKeepTheirSumsExact) {
    PathSource p;
    p.kind = PathKind::Polyline;
    p.corners = CornerMode::Smooth;
    p.smoothing = 10;
    for (int i = 0; i < 500; ++i) {
        const double th = 3.0 * i / 500;
        p.points.emplace_back(3 * std::cos(th) + 0.01 * std::sin(7.0 * i),
                              3 * std::sin(th) + 0.01 * std::cos(5.0 * i));
    }
    auto path = buildPath(p);
    const PathTable& table = *path->pieces().front().table;
    EXPECT_EQ(table.halvings(), 0u);
    EXPECT_EQ(table.panels().size(), 499u);
    EXPECT_EQ(table.bounds().exactPanels, 0);
    const Curve& c = table.curve();
    const std::vector<double> knots = c.breakpoints();
    for (double b : {0.0, 1.0, 6.0, 600.0}) {
        auto integrand = [&](double u) {
            const CurvePoint q = c.eval(u);
            const double speed = std::hypot(q.dx, q.dy);
            const double kappa = (q.dx * q.ddy - q.dy * q.ddx) / (speed * speed * speed);
            return speed * std::hypot(1.0, b * kappa);
        };
        double reference = 0, sum = 0;
        for (std::size_t k = 0; k + 1 < knots.size(); ++k)
            reference += qag(integrand, knots[k], knots[k + 1]);
        for (const PathTable::GaussPanel& panel : table.panels())
            for (int i = 0; i < gauss::kPoints; ++i)
                sum += panel.weight[i] * std::hypot(1.0, b * panel.kappa[i]);
        std::cout << "b = " << b << ": relative error " << (sum - reference) / reference << "\n";
        EXPECT_NEAR(sum, reference, 1e-13 * reference) << "b = " << b;
    }
}

TEST(TimeLawTable, ModelsSayWhatIsInterpolatedAndToWhatBound) {
    Solution sol = Solution::compute(presetScene("catenary"));
    EXPECT_NE(sol.models().path.find("interpolated per panel"), std::string::npos)
        << sol.models().path;
    EXPECT_NE(sol.models().path.find("bounds: position"), std::string::npos);
    EXPECT_NE(sol.models().timeLaw.find("Chebyshev interpolant of dt/du"), std::string::npos)
        << sol.models().timeLaw;
    EXPECT_NE(sol.models().inversion.find("interpolated t(u)"), std::string::npos);
    Solution line = Solution::compute(presetScene("line"));
    EXPECT_NE(line.models().path.find("closed-form geometry"), std::string::npos);
    EXPECT_EQ(line.models().path.find("interpolated"), std::string::npos);
}

// the state the Solution reports comes from the interpolants and agrees with the exact curve
TEST(TimeLawTable, SolutionStateMatchesTheExactEvaluation) {
    for (const char* name : {"catenary", "sinusoid"}) {
        Solution sol = Solution::compute(presetScene(name));
        TimeLaw law(sol.path(), sol.params());
        const PathTable& table = *sol.path()->pieces().front().table;
        for (int i = 0; i <= 300; ++i) {
            double t = sol.duration() * i / 300.0;
            MotionSample m = sol.at(t);
            PathNode exact = table.at(law.locateExact(t).u);
            EXPECT_NEAR(m.x, exact.x, 1e-13) << name << " t = " << t;
            EXPECT_NEAR(m.y, exact.y, 1e-13) << name << " t = " << t;
            EXPECT_NEAR(m.phi, exact.phi, 1e-13) << name << " t = " << t;
            EXPECT_NEAR(m.kappa, exact.kappa, 1e-13) << name << " t = " << t;
            EXPECT_NEAR(m.control.psidot,
                        controlOnCurve(sol.params(), exact.kappa, exact.dkappa, exact.phi).psidot,
                        1e-12)
                << name << " t = " << t;
        }
    }
}
