#pragma once
// The corners of a drawn stroke: the points where the hand turned sharply, told apart from the
// jitter of the samples (docs/numerics.md, Corners of a drawn path).
#include <cstddef>
#include <utility>
#include <vector>

namespace chaplygin {

/// The default corner threshold [degrees]: a hand-drawn zig-zag turns by 60 degrees or more at
/// its corners, while pixel jitter and a drawn arc turn the stroke's direction by well under 35
/// degrees over the chords below.
inline constexpr double kDefaultCornerAngleDeg = 35.0;

/// The indices of the interior points where the stroke turns by more than thresholdDeg. The
/// direction arriving at point i is the chord from up to kCornerReach points before it, the
/// direction leaving it the chord to up to kCornerReach points after it; a chord stops short
/// where a point inside it lies farther than 0.35 of its length from it (a sharp corner
/// of a sparse polyline ends it). The turn is the angle between the two chords. A point inside
/// the chords of a point that turns more (or as much, and comes first) is no corner of its own,
/// so a corner the hand rounded over two samples counts once. Points must be distinct in turn.
std::vector<std::size_t> findCorners(const std::vector<std::pair<double, double>>& points,
                                     double thresholdDeg);

/// Points on either side over which the stroke's direction is taken.
inline constexpr std::size_t kCornerReach = 3;

} // namespace chaplygin
