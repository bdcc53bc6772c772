#pragma once
// Scene, the plain data a run is made from: the path, the system, the mode and speed, the horizon
// and what the view shows.
#include "control/control_law.h"
#include "paths/path_source.h"
#include "planning/pose_planner.h"
#include "scene/annotations.h"
#include "systems/system.h"

#include <optional>
#include <string>
#include <vector>

namespace chaplygin {

/// One arrow on the canvas: whether it is drawn and its length per unit of the quantity
/// ([m per m/s], [m per N] or, for the couple, [rad of arc per N m]); 0 scales automatically.
struct VectorToggle {
    bool shown = false;
    double scale = 0;

    bool operator==(const VectorToggle&) const = default;
};

/// Which arrows the canvas draws on the bodies (View > Vectors); a view setting saved with the
/// scene. The quantities are the Solution's: sdot, phidot, force_axial, force_lateral (N at P)
/// and control_couple.
struct VectorOverlay {
    VectorToggle knifeVelocity;   ///< velocity of the knife point P, sdot s-hat
    VectorToggle axialForce;      ///< control force f_s along the axis, at the centre of mass
    VectorToggle lateralReaction; ///< knife's lateral reaction N n-hat, at P
    VectorToggle controlCouple;   ///< control couple tau, a curved arrow about the centre of mass
    VectorToggle cmVelocity;      ///< velocity of the centre of mass, sdot s-hat + a phidot n-hat

    bool operator==(const VectorOverlay&) const = default;
};

/// A run kept for comparison ("Pin this run"): the parameters that define its motion. It is
/// recomputed from these when the scene is loaded.
struct PinnedRun {
    PathSource path;
    SystemSpec system;
    SpeedMode mode = SpeedMode::Energy;
    double speed = 1.0;
    std::optional<double> tEnd;

    bool operator==(const PinnedRun&) const = default;
};

/// At most this many pinned runs per scene.
constexpr std::size_t kMaxPinnedRuns = 5;
/// A scene's note is at most this many bytes (UTF-8).
constexpr std::size_t kMaxNoteBytes = 100000;

/// A push given to the perturbed bodies, or their initial offset from the controlled motion
/// (docs/physics.md §9). Both bodies, the open loop (the nominal lambda(t) as a signal) and the
/// closed loop (chained-form feedback), start from the controlled state at t = 0 moved by these.
struct Perturbation {
    double dy = 0;               ///< lateral offset of P to the left of the start tangent [m]
    double dphi = 0;             ///< heading offset [rad]
    double dpsi = 0;             ///< control angle offset, Psi(0) + dpsi at the same energy [rad]
    std::optional<double> tPush; ///< time of the push [s]
    double pushPsi = 0;          ///< the push's jump of Psi [rad]
    double pushDy = 0;           ///< the push's jump of P to the left of the heading [m]
    double feedbackRate = 1;     ///< P of the triple pole at -P in path length [1/m]
    std::optional<double> feedbackLimit; ///< bound on |Psidot| [rad/s]
    std::optional<double> controllerB; ///< the b the controller assumes [m] (default: the plant's)

    bool operator==(const Perturbation&) const = default;
};

/// A plan from pose to pose (docs/physics.md §10): the target pose, the start pose (the path's
/// start when absent), the horizon (the planner's default when absent) and the motion chosen
/// among those the planner lists, sorted by arrival time.
struct ScenePlan {
    std::optional<Pose> from;
    Pose to;
    std::optional<double> horizon; ///< [s]
    int choice = 0;                ///< index in the planner's list (0: the first, least time)

    friend bool operator==(const ScenePlan& a, const ScenePlan& b) {
        auto same = [](const Pose& p, const Pose& q) {
            return p.x == q.x && p.y == q.y && p.phi == q.phi;
        };
        return a.from.has_value() == b.from.has_value() && (!a.from || same(*a.from, *b.from)) &&
               same(a.to, b.to) && a.horizon == b.horizon && a.choice == b.choice;
    }
};

/// Everything that defines a scene: plain data with defaults, saved and loaded as JSON,
/// shared by the GUI, the CLI and the tests.
struct Scene {
    std::string preset; ///< the preset it came from, or empty
    PathSource path;
    SystemSpec system;
    SpeedMode mode = SpeedMode::Energy;
    double speed = 1.0;         ///< v_T (Energy) or v_s (Speed) [m/s]
    std::optional<double> tEnd; ///< horizon [s]; default: the time to traverse the path
    std::optional<Perturbation> perturbation; ///< the perturbed bodies, when given

    VectorOverlay vectors;         ///< arrows drawn on the bodies (view only)
    std::string note;              ///< the lecturer's Markdown note (view only)
    std::vector<PinnedRun> pins;   ///< runs kept for comparison, oldest first (view only)
    std::optional<ScenePlan> plan; ///< the Plan tool's target and chosen motion
    /// The pen's marks over the canvas (view only): in a file saved with File > Save annotations
    /// with the scene; the window's document keeps them in the pen, never in its scene.
    std::vector<AnnotationMark> annotations;

    bool operator==(const Scene&) const = default;
};

} // namespace chaplygin
