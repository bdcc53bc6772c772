// PathFrame: the closest point of a path (radial on a circle, a brute-force minimum elsewhere),
// kappa'' against a difference quotient of the exact kappa_s, and the continuation beyond the
// ends along the osculating circle.
#include "paths/curve.h"
#include "paths/path.h"
#include "paths/path_projection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace chaplygin;
using std::numbers::pi;

namespace {

PathFrame frameOf(const PathSource& src, std::shared_ptr<const Path>* keep = nullptr) {
    auto path = buildPath(src);
    if (keep)
        *keep = path;
    const PathPiece& piece = path->pieces().front();
    return PathFrame(piece.table, piece.phiOffset);
}

PathSource circle(double to) {
    PathSource s;
    s.kind = PathKind::Parametric;
    s.xOfU = "2*cos(u)";
    s.yOfU = "2*sin(u)";
    s.from = 0;
    s.to = to;
    return s;
}

PathSource sinusoid() {
    PathSource s;
    s.y = "-sin(x)";
    s.from = 0;
    s.to = 4 * pi;
    return s;
}

} // namespace

TEST(PathFrame, ProjectionOntoACircleIsRadial) {
    const PathFrame f = frameOf(circle(6));
    for (double angle : {0.2, 1.0, 3.0, 5.5})
        for (double r : {1.4, 2.0, 2.7}) {
            const PathProjection p =
                f.project(r * std::cos(angle), r * std::sin(angle), angle + 0.1);
            EXPECT_NEAR(p.point.s, 2 * angle, 1e-13);
            EXPECT_NEAR(p.e, 2 - r, 1e-14); // left of a left turn: inwards
            EXPECT_NEAR(p.point.phi, angle + pi / 2, 1e-13);
        }
}

TEST(PathFrame, ProjectionOntoTheSinusoidIsTheNearestPoint) {
    const PathFrame f = frameOf(sinusoid());
    for (double x : {0.7, 2.0, 5.1, 9.3}) {
        const double px = x + 0.05, py = -std::sin(x) + 0.2;
        const PathProjection p = f.project(px, py, x);
        // golden-section minimum of the distance to (u, -sin u) near x
        double lo = x - 0.5, hi = x + 0.5;
        const auto d2 = [&](double u) {
            return (px - u) * (px - u) + (py + std::sin(u)) * (py + std::sin(u));
        };
        const double g = (std::sqrt(5.0) - 1) / 2;
        for (int i = 0; i < 200; ++i) {
            const double c = hi - g * (hi - lo), d = lo + g * (hi - lo);
            (d2(c) < d2(d) ? hi : lo) = d2(c) < d2(d) ? d : c;
        }
        const double u = 0.5 * (lo + hi);
        EXPECT_NEAR(p.point.u, u, 1e-7) << x;
        EXPECT_NEAR(std::fabs(p.e), std::sqrt(d2(u)), 1e-12) << x;
        EXPECT_NEAR(p.point.x, u, 1e-7);
    }
}

TEST(PathFrame, SecondCurvatureDerivativeMatchesTheExactFirst) {
    std::shared_ptr<const Path> path;
    const PathFrame f = frameOf(sinusoid(), &path);
    const PathTable& table = *path->pieces().front().table;
    for (double u : {0.3, 1.7, 4.0, 8.8, 12.1}) {
        // d kappa_s/ds by fourth-order differences of the exact kappa_s
        const double h = 1e-3;
        double k[5], s[5];
        for (int i = 0; i < 5; ++i) {
            const PathNode n = table.at(u + (i - 2) * h);
            k[i] = n.dkappa;
            s[i] = n.s;
        }
        const double want =
            (k[0] - 8 * k[1] + 8 * k[3] - k[4]) / (s[0] - 8 * s[1] + 8 * s[3] - s[4]);
        EXPECT_NEAR(f.at(u).ddkappa, want, 1e-8) << u;
        EXPECT_NEAR(f.at(u).dkappa, table.at(u).dkappa, 1e-12) << u;
    }
    EXPECT_EQ(frameOf(circle(6)).at(2.0).ddkappa, 0);
}

TEST(PathFrame, BeyondTheEndsTheOsculatingCircleContinues) {
    const PathFrame f = frameOf(circle(pi));
    for (double u : {-0.4, pi + 0.3, pi + 1.0}) {
        const PathPoint p = f.at(u);
        EXPECT_NEAR(p.x, 2 * std::cos(u), 1e-13) << u;
        EXPECT_NEAR(p.y, 2 * std::sin(u), 1e-13) << u;
        EXPECT_NEAR(p.phi, u + pi / 2, 1e-13) << u;
        EXPECT_NEAR(p.s, 2 * u, 1e-13) << u;
        EXPECT_NEAR(p.kappa, 0.5, 1e-15);
        EXPECT_EQ(p.dkappa, 0);
    }
    const PathProjection p = f.project(1.5 * std::cos(pi + 0.5), 1.5 * std::sin(pi + 0.5), pi);
    EXPECT_NEAR(p.point.s, 2 * (pi + 0.5), 1e-13);
    EXPECT_NEAR(p.e, 0.5, 1e-14);
}
