#pragma once
#include <QPainterPath>

#include <optional>
#include <utility>

namespace chaplygin {
class Solution;
}

namespace chaplygin::ui {

/// A body's shape and the ring its outline's pen covers, in metres (body coordinates) as
/// polygons flattened in pixels: the clips of the path drawn again over a body to scale, made
/// once per solution, zoom and pen.
class BodyClipShapes {
  public:
    /// For the solution's body at `scale` [px/m] with an outline pen of penPx [px].
    const std::pair<QPainterPath, QPainterPath>& of(const Solution& solution, double scale,
                                                    double penPx);
    /// The shape and its ring as one outline without overlaps (after `of`): one fill per frame
    /// instead of two, the ring's curves flattened at the scale's pixels. Made only when `of`
    /// was asked twice in a row for the same scale (the frames of an animation), null before:
    /// a zoom step would pay the union for one frame (a tenth of its time).
    const QPainterPath* covered();

  private:
    const Solution* m_solution = nullptr;
    double m_scale = 0, m_penPx = 0;
    int m_asked = 0; ///< how often `of` was asked for the same solution, scale and pen
    std::pair<QPainterPath, QPainterPath> m_shapes;
    std::optional<QPainterPath> m_covered;
};

} // namespace chaplygin::ui
