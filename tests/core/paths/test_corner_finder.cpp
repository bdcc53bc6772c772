// Corners of a drawn stroke: pixel jitter, a drawn arc and a corner rounded between two samples
// make no extra pivot; the sharp turns of a zig-zag and of a sparse polyline do.
#include "common/input_error.h"
#include "paths/corner_finder.h"
#include "paths/path.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <vector>

using namespace chaplygin;

namespace {

using Points = std::vector<std::pair<double, double>>;
constexpr double kPi = std::numbers::pi;

// The vertices of a polyline through `corners`, sampled every `spacing` along it starting
// `offset` past the first vertex, each moved by up to `jitter` in x and y (uniform, seeded)
Points sampled(const Points& corners, double spacing, double offset, double jitter, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> shake(-jitter, jitter);
    Points out;
    double along = 0, next = offset;
    if (offset > 0)
        out.push_back(corners.front());
    for (std::size_t k = 0; k + 1 < corners.size(); ++k) {
        const auto [x0, y0] = corners[k];
        const auto [x1, y1] = corners[k + 1];
        const double len = std::hypot(x1 - x0, y1 - y0);
        for (; next <= along + len + 1e-9; next += spacing) {
            const double f = (next - along) / len;
            out.emplace_back(x0 + f * (x1 - x0), y0 + f * (y1 - y0));
        }
        along += len;
    }
    if (std::hypot(out.back().first - corners.back().first,
                   out.back().second - corners.back().second) > 1e-9)
        out.push_back(corners.back());
    for (auto& [x, y] : out) {
        x += shake(rng);
        y += shake(rng);
    }
    return out;
}

// four straight strokes of 1 m turning by `turnDeg` alternately left and right
Points zigZag(double turnDeg) {
    const double half = turnDeg / 2 * kPi / 180;
    Points c = {{0, 0}};
    for (int k = 0; k < 4; ++k) {
        const double a = k % 2 == 0 ? half : -half;
        c.emplace_back(c.back().first + std::cos(a), c.back().second + std::sin(a));
    }
    return c;
}

// a half circle of radius 1 through n + 1 points, each moved by up to `jitter`
Points halfCircle(int n, double jitter, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> shake(-jitter, jitter);
    Points out;
    for (int i = 0; i <= n; ++i) {
        const double th = kPi * i / n;
        out.emplace_back(std::cos(th) + shake(rng), std::sin(th) + shake(rng));
    }
    return out;
}

PathSource stroke(const Points& points) {
    PathSource p;
    p.kind = PathKind::Polyline;
    p.points = points;
    return p;
}

} // namespace

// 81 points on four straight strokes (every 5 cm, the corners among them), each shaken by up to
// a tenth of the spacing: the three corners and nothing else, for turns of 60, 90 and 120 degrees
TEST(CornerFinder, AJitteredZigZagHasItsThreeCorners) {
    for (double turn : {60.0, 90.0, 120.0}) {
        for (unsigned seed = 1; seed <= 20; ++seed) {
            const Points pts = sampled(zigZag(turn), 0.05, 0, 0.005, seed);
            ASSERT_EQ(pts.size(), 81u);
            const auto corners = findCorners(pts, kDefaultCornerAngleDeg);
            ASSERT_EQ(corners.size(), 3u) << "turn " << turn << ", seed " << seed;
            for (std::size_t k = 0; k < 3; ++k)
                EXPECT_EQ(corners[k], 20 * (k + 1)) << "turn " << turn << ", seed " << seed;
        }
    }
}

// The same strokes sampled with no point on the corners (the mouse crossed each between two
// samples), with jitter: still one corner each, at one of the two samples beside it
TEST(CornerFinder, ACornerRoundedBetweenTwoSamplesCountsOnce) {
    for (double jitter : {0.0, 0.005}) {
        for (unsigned seed = 1; seed <= 20; ++seed) {
            const Points pts = sampled(zigZag(90), 0.05, 0.025, jitter, seed);
            const auto corners = findCorners(pts, kDefaultCornerAngleDeg);
            ASSERT_EQ(corners.size(), 3u) << "jitter " << jitter << ", seed " << seed;
            for (std::size_t k = 0; k < 3; ++k) {
                // the corner lies between samples 20 (k + 1) and 20 (k + 1) + 1
                EXPECT_GE(corners[k], 20 * (k + 1)) << seed;
                EXPECT_LE(corners[k], 20 * (k + 1) + 1) << seed;
            }
        }
    }
}

// A half circle of 41 points turns by 4.5 degrees at each: no corner, with or without jitter
TEST(CornerFinder, AJitteredArcHasNoCorner) {
    for (unsigned seed = 1; seed <= 20; ++seed)
        EXPECT_TRUE(findCorners(halfCircle(40, 0.1 * kPi / 40, seed), 35).empty()) << seed;
    // a smaller threshold finds the arc's steady turn (3 points of 4.5 degrees either side)
    EXPECT_FALSE(findCorners(halfCircle(40, 0, 1), 10).empty());
}

// The vertices of a sparse exact polyline are corners where they turn by more than the angle
TEST(CornerFinder, SparsePolylinesTurnAtTheirVertices) {
    EXPECT_EQ(findCorners({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 35), (std::vector<std::size_t>{1, 2}));
    EXPECT_EQ(findCorners({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}}, 35),
              (std::vector<std::size_t>{2, 3}));
    // turns of 30 and 40 degrees
    const double a = 30 * kPi / 180, b = 70 * kPi / 180;
    const Points bend = {{0, 0},
                         {1, 0},
                         {1 + std::cos(a), std::sin(a)},
                         {1 + std::cos(a) + std::cos(b), std::sin(a) + std::sin(b)}};
    EXPECT_EQ(findCorners(bend, 35), (std::vector<std::size_t>{2}));
    // the gentle first bend is inside point 2's arriving chord, from point 0 at 15 degrees, so
    // point 2 turns by 55 degrees (and point 1, from 0 to the chord to point 3 at 50 degrees,
    // is inside it): a corner over 45, none over 55
    EXPECT_EQ(findCorners(bend, 45), (std::vector<std::size_t>{2}));
    EXPECT_TRUE(findCorners(bend, 55.1).empty());
}

// The path of a jittered zig-zag: three pivots at the corners turning by about the drawn
// 90 degrees, the stretches between them nearly straight and joined at the corners
TEST(CornerFinder, AJitteredZigZagPathPivotsThreeTimes) {
    const Points pts = sampled(zigZag(90), 0.05, 0, 0.005, 7);
    auto path = buildPath(stroke(pts));
    EXPECT_EQ(path->pivotCount(), 3);
    int k = 0;
    for (const PathPiece& piece : path->pieces()) {
        if (piece.kind != PathPiece::Kind::Pivot) {
            // each stretch is 1 m of nearly straight line: jitter of 5 mm smoothed away
            EXPECT_NEAR(piece.table->length(), 1.0, 0.01);
            const double phi0 = piece.table->nodes().front().phi;
            for (const PathNode& n : piece.table->nodes())
                EXPECT_NEAR(n.phi, phi0, 0.1);
            continue;
        }
        ++k;
        const auto [x, y] = zigZag(90)[static_cast<std::size_t>(k)];
        EXPECT_NEAR(piece.x, x, 0.0051);
        EXPECT_NEAR(piece.y, y, 0.0051);
        EXPECT_NEAR(std::fabs(piece.phiTo - piece.phiFrom), kPi / 2, 0.1);
    }
    // the stretches meet at the pivots: each ends where the next begins
    const auto& pieces = path->pieces();
    for (std::size_t i = 1; i + 1 < pieces.size(); ++i) {
        if (pieces[i].kind != PathPiece::Kind::Pivot)
            continue;
        const PathNode& end = pieces[i - 1].table->nodes().back();
        const PathNode& start = pieces[i + 1].table->nodes().front();
        EXPECT_NEAR(end.x, pieces[i].x, 1e-14);
        EXPECT_NEAR(end.y, pieces[i].y, 1e-14);
        EXPECT_NEAR(start.x, pieces[i].x, 1e-14);
        EXPECT_NEAR(start.y, pieces[i].y, 1e-14);
        EXPECT_NEAR(pieces[i - 1].table->nodes().back().phi + pieces[i - 1].phiOffset,
                    pieces[i].phiFrom, 1e-12);
        EXPECT_NEAR(start.phi + pieces[i + 1].phiOffset, pieces[i].phiTo, 1e-12);
    }
    // a corner angle above the drawn turns: no pivot, one smooth curve
    PathSource wide = stroke(pts);
    wide.cornerAngle = 120;
    EXPECT_EQ(buildPath(wide)->pivotCount(), 0);
}

// A jittered half circle in pivot mode, smoothed as a drawn stroke (bandwidth 3 spacings): no
// pivot, one smooth curve from the first point to the last turning by about pi with the
// circle's curvature
TEST(CornerFinder, AJitteredArcPathHasNoPivot) {
    const Points pts = halfCircle(40, 0.1 * kPi / 40, 3);
    PathSource p = stroke(pts);
    p.smoothing = 3;
    auto path = buildPath(p);
    EXPECT_EQ(path->pivotCount(), 0);
    ASSERT_EQ(path->pieces().size(), 1u);
    EXPECT_NEAR(path->start().x, pts.front().first, 1e-14);
    EXPECT_NEAR(path->end().y, pts.back().second, 1e-14);
    // the natural ends (kappa = 0) straighten the first and last few centimetres
    EXPECT_NEAR(path->end().phi - path->start().phi, kPi, 0.5);
    EXPECT_NEAR(path->length(), kPi, 0.1);
    double lo = 1e9, hi = -1e9;
    for (const PathNode& n : path->pieces().front().table->nodes())
        if (n.s > 0.5 && n.s < path->length() - 0.5) {
            lo = std::min(lo, n.kappa);
            hi = std::max(hi, n.kappa);
        }
    std::cout << "arc: length " << path->length() << ", turn "
              << path->end().phi - path->start().phi << ", kappa in [" << lo << ", " << hi << "]\n";
    EXPECT_GT(lo, 0.9);
    EXPECT_LT(hi, 1.15);
}

TEST(CornerFinder, TheCornerAngleIsChecked) {
    PathSource p = stroke({{0, 0}, {1, 0}, {1, 1}});
    for (double bad : {-1.0, 181.0, std::nan("")}) {
        p.cornerAngle = bad;
        try {
            buildPath(p);
            ADD_FAILURE() << bad;
        } catch (const InputError& e) {
            EXPECT_EQ(e.where(), "corner_angle");
        }
    }
}
