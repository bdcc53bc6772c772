#include "paths/corner_finder.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace chaplygin {
namespace {

using Point = std::pair<double, double>;

constexpr double kChordStraightness = 0.35; // largest distance inside a chord / its length

bool straightChord(const std::vector<Point>& pts, std::size_t a, std::size_t b) {
    const double dx = pts[b].first - pts[a].first, dy = pts[b].second - pts[a].second;
    const double length = std::hypot(dx, dy);
    for (std::size_t k = a + 1; k < b; ++k) {
        const double ex = pts[k].first - pts[a].first, ey = pts[k].second - pts[a].second;
        if (std::fabs(dx * ey - dy * ex) > kChordStraightness * length * length)
            return false;
    }
    return true;
}

// the farthest point, up to kCornerReach away towards `step` (-1 or +1), whose chord to i is
// straight
std::size_t chordEnd(const std::vector<Point>& pts, std::size_t i, int step) {
    std::size_t end = i + step;
    for (std::size_t k = 2; k <= kCornerReach; ++k) {
        if (step < 0 ? i < k : i + k >= pts.size())
            break;
        const std::size_t next = step < 0 ? i - k : i + k;
        if (!straightChord(pts, std::min(i, next), std::max(i, next)))
            break;
        end = next;
    }
    return end;
}

} // namespace

std::vector<std::size_t> findCorners(const std::vector<Point>& pts, double thresholdDeg) {
    const std::size_t n = pts.size();
    if (n < 3)
        return {};
    std::vector<double> turn(n, 0.0);
    std::vector<std::size_t> from(n, 0), to(n, 0);
    for (std::size_t i = 1; i + 1 < n; ++i) {
        from[i] = chordEnd(pts, i, -1);
        to[i] = chordEnd(pts, i, +1);
        const double in =
            std::atan2(pts[i].second - pts[from[i]].second, pts[i].first - pts[from[i]].first);
        const double out =
            std::atan2(pts[to[i]].second - pts[i].second, pts[to[i]].first - pts[i].first);
        double d = out - in;
        d -= 2 * std::numbers::pi * std::round(d / (2 * std::numbers::pi));
        turn[i] = std::fabs(d);
    }
    const double threshold = thresholdDeg * std::numbers::pi / 180;
    std::vector<std::size_t> corners;
    for (std::size_t i = 1; i + 1 < n; ++i) {
        if (!(turn[i] > threshold))
            continue;
        bool strongest = true;
        const std::size_t last = std::min(n - 2, i + kCornerReach);
        for (std::size_t j = i > kCornerReach ? i - kCornerReach : 1; j <= last && strongest; ++j)
            if (j != i && (turn[j] > turn[i] || (turn[j] == turn[i] && j < i)) && from[j] < i &&
                i < to[j])
                strongest = false;
        if (strongest)
            corners.push_back(i);
    }
    return corners;
}

} // namespace chaplygin
