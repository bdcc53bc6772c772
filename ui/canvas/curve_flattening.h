#pragma once
#include "scene/solution.h"

#include <QPointF>
#include <QRectF>

#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <vector>

namespace chaplygin::ui {

/// A curve flattened for the screen: world points [m] in order with the parameter at each (arc
/// length or time, non-decreasing) and, for a path, the curvature there.
struct FlatCurve {
    std::vector<double> param;
    std::vector<QPointF> points;
    std::vector<double> kappa; ///< a path's only
    /// The budget ended the curve at its last point: what follows is not drawn.
    bool truncated = false;
    /// How many points have param <= limit.
    std::size_t countUpTo(double limit) const;
    /// Whether the curve is drawn up to limit, so that a body there joins its last point.
    bool reaches(double limit) const {
        return !truncated || (!param.empty() && limit <= param.back());
    }
};

/// How far a curve is refined: to tolerance [m] where it can be seen (inside `seen`, world
/// coordinates; a null rectangle is everywhere), only to its seeds elsewhere, and to at most
/// `budget` points in all. A point closer than a quarter of tolerance to the one before is left
/// out.
/// `exceeded` is set when the budget stopped a refinement.
struct FlattenLimits {
    double tolerance = 0;
    QRectF seen;
    std::size_t budget = std::numeric_limits<std::size_t>::max();
    bool exceeded = false;
    /// At the budget the curve ends (`stopped` is then set) instead of going on through its seeds.
    bool truncate = false;
    bool stopped = false;
};

/// Appends f on (a, b] to out: the chord [a, b] is halved while the curve's midpoint lies more
/// than tolerance [m] from the chord's midpoint, to at most maxDepth halvings.
void flattenInto(FlatCurve& out, const std::function<QPointF(double)>& f, double a, double b,
                 QPointF fa, QPointF fb, FlattenLimits& limits, int maxDepth = 10);

/// The path's curve pieces from their interpolants (the same evaluation as the body's pose),
/// seeded at the panel ends; param is the arc length from the path's start. A pivot is one point.
FlatCurve flattenPath(const Path& path, FlattenLimits& limits);

/// f over [0, tEnd] seeded at `seeds` evenly spaced times; param is the time.
FlatCurve flattenInTime(const std::function<QPointF(double)>& f, double tEnd, FlattenLimits& limits,
                        int seeds = 400);

/// A body's path through its integrator's accepted steps up to tEnd, by the cubic Hermite
/// interpolant of the position and velocity at each (a step of zero length is a jump).
FlatCurve flattenThroughKnots(const std::vector<TrailKnot>& knots, double tEnd,
                              FlattenLimits& limits);

/// build(limits) made within kPointBudget points: at the tolerance asked for when it fits, else
/// at a tolerance 16 times coarser, else at the tolerance asked for up to where the budget ends it
/// (FlatCurve::truncated): a curve too dense for the screen, such as hundreds of laps of one
/// circle, is drawn exactly as far as the budget goes and never stalls a frame. Its seeds alone
/// would be chords across the view (a 600-lap circle drawn as heptagons, a ring 20 px wide).
/// The tolerance used is left in limits.
FlatCurve flattenWithinBudget(const std::function<FlatCurve(FlattenLimits&)>& build,
                              FlattenLimits& limits);

/// The most points one curve is flattened to, unless its seeds alone are more (a path of more
/// panels, bounded by the table's halving budget): a frame's work is bounded by it.
inline constexpr std::size_t kPointBudget = 8192;

/// Every curve the canvas draws, flattened to kTolerancePx device pixels at one scale (docs/
/// architecture.md, ui/: the desktop application, Canvas) where it can be seen, each within
/// kPointBudget points: made anew when the solution or the scale changes or the view leaves the
/// region flattened, and for each pinned run on first use at that scale.
class CanvasCurves {
  public:
    static constexpr double kTolerancePx = 0.25;
    /// devicePxPerMetre: the canvas's scale times its device pixel ratio. view: the world
    /// rectangle shown [m]; the curves are exact within it and a view's size around it (null:
    /// exact everywhere).
    void update(const std::shared_ptr<const Solution>& solution, double devicePxPerMetre,
                const QRectF& view = {});
    /// Whether the budget ended one of the body's curves (the path, a trail) at this scale.
    bool truncated() const {
        return m_path.truncated || m_free.truncated || m_vak.truncated || m_openLoop.truncated ||
               m_closedLoop.truncated;
    }
    const FlatCurve& path() const { return m_path; }
    const FlatCurve& free() const { return m_free; }
    const FlatCurve& vakonomic() const { return m_vak; }
    /// The pushed bodies' paths (empty without a perturbation).
    const FlatCurve& openLoop() const { return m_openLoop; }
    const FlatCurve& closedLoop() const { return m_closedLoop; }
    /// A pinned run's path, flattened at the current scale.
    const FlatCurve& pinnedPath(const std::shared_ptr<const Solution>& run);
    /// The world region the curves are exact in (null: everywhere).
    const QRectF& seen() const { return m_seen; }

  private:
    std::shared_ptr<const Solution> m_solution;
    double m_scale = 0;
    QRectF m_seen;
    FlatCurve m_path, m_free, m_vak, m_openLoop, m_closedLoop;
    std::map<const Solution*, std::pair<std::shared_ptr<const Solution>, FlatCurve>> m_pins;
};

} // namespace chaplygin::ui
