#pragma once
// Solution, the one immutable result of a scene: the controlled and the free motion at any time,
// and the models behind them.
#include "control/control_law.h"
#include "motion/free_motion.h"
#include "motion/perturbed_motion.h"
#include "motion/time_law.h"
#include "motion/vakonomic_motion.h"
#include "paths/path.h"
#include "scene/scene.h"

#include <memory>
#include <string>
#include <vector>

namespace chaplygin {

/// The controlled and the free motion at one time.
struct MotionSample {
    double t = 0;
    double s = 0, x = 0, y = 0, phi = 0, kappa = 0; ///< controlled body: knife point P, heading
    ControlState control;
    FreeState free;         ///< free (Lagrange-d'Alembert) body from the same initial state
    VakonomicState vak;     ///< genuine vakonomic body from the same state and lambda(0)
    bool perturbed = false; ///< the scene has a perturbation: pert and fb are filled in
    PerturbedState pert;    ///< perturbed body under the nominal lambda(t) (open loop)
    PerturbedState fb;      ///< perturbed body under the feedback (closed loop)
};

/// The bodies Solution::at(t, parts) computes; the others keep MotionSample's defaults. A caller
/// that reads a few columns (csvColumnParts) pays only for their bodies.
struct MotionParts {
    bool controlled = true; ///< s, x, y, phi, kappa and the control state
    bool free = true;       ///< the free body
    bool vakonomic = true;  ///< the genuine vakonomic body
    bool perturbed = true;  ///< the two perturbed bodies, when the scene has a perturbation
};

/// The perturbed bodies' distance from the path and heading error at t (docs/physics.md §9),
/// each against its closest path point; NaN where that point is not found.
struct TrackingError {
    double t = 0;
    double openE = 0, openTheta = 0; ///< open loop: lateral error e (left > 0) [m], theta [rad]
    double fbE = 0, fbTheta = 0;     ///< closed loop
};

/// Which model or method produced each quantity (shown by the GUI, written to --summary).
struct ModelReport {
    std::string path;         ///< how the path was tabulated
    std::string timeLaw;      ///< t(s)
    std::string inversion;    ///< s(t)
    std::string control;      ///< Psi, chi, lambda, forces
    std::string freeVelocity; ///< free sdot, phidot, phi
    std::string freePosition; ///< free x, y
    std::string vakonomic;    ///< the genuine vakonomic body
    std::string perturbed;    ///< the open-loop perturbed body (empty without a perturbation)
    std::string feedback;     ///< the closed-loop perturbed body (empty without a perturbation)
};

/// The control parameters of a scene: its system's (m_eff, a, b), mode and speed.
/// Throws InputError naming a bad parameter.
ControlParams controlParamsOf(const Scene& scene);
/// The same with the scene's system already derived.
ControlParams controlParamsOf(const Scene& scene, const DerivedSystem& system);

/// One immutable result that the CLI, the GUI and the tests read. Values at any t are computed
/// on request from the path table's certified per-panel interpolants (no interpolation of stored
/// samples in time). Recomputing with new system
/// parameters or speed reuses the tabulated path.
class Solution {
  public:
    /// Builds the path and solves. Throws InputError for bad input.
    static Solution compute(const Scene& scene);
    /// Solves on an already tabulated path (scene.path is taken to describe it).
    static Solution compute(const Scene& scene, std::shared_ptr<const Path> path);
    /// The same with the scene's system already derived (deriveSystem(scene.system)), as a
    /// caller that vetted the parameters has it.
    static Solution compute(const Scene& scene, std::shared_ptr<const Path> path,
                            const DerivedSystem& system);

    const Scene& scene() const { return m_scene; }
    const std::shared_ptr<const Path>& path() const { return m_path; }
    const DerivedSystem& system() const { return m_params.system; }
    const ControlParams& params() const { return m_params; }
    const ModelReport& models() const { return m_models; }
    double duration() const { return m_timeLaw.duration(); } ///< time to traverse the path [s]
    double tEnd() const { return m_tEnd; }                   ///< horizon [s]

    MotionSample at(double t) const { return at(t, MotionParts{}); }
    /// Only the parts asked for (t always).
    MotionSample at(double t, const MotionParts& parts) const;
    /// The free motion alone at t (cheaper than at(t) when the controlled state is not needed).
    FreeState freeAt(double t) const { return m_free.at(t); }
    /// The genuine vakonomic body alone at t.
    VakonomicState vakonomicAt(double t) const { return m_vak.at(t); }
    const FreeMotion& freeMotion() const { return m_free; }
    /// Whether the scene has a perturbation, and its two bodies (docs/physics.md §9).
    bool perturbed() const { return m_open != nullptr; }
    const PerturbedMotion* openLoop() const { return m_open.get(); }
    const PerturbedMotion* feedback() const { return m_feedback.get(); }
    /// The tracking errors at increasing times (empty without a perturbation): each closest
    /// point found by Newton from the one before, so the times should be close together.
    std::vector<TrackingError> trackingErrors(const std::vector<double>& times) const;
    /// count samples evenly spaced on [0, tEnd] (count >= 2).
    std::vector<MotionSample> sample(int count) const;
    std::vector<MotionSample> sampleAt(const std::vector<double>& times) const;
    /// The controlled motion at the path table's panel ends (exact values, uneven times): the
    /// cheapest dense series, for plots. The free motion is not filled in.
    std::vector<MotionSample> controlledAtNodes() const;

  private:
    Solution(const Scene& scene, std::shared_ptr<const Path> path, const ControlParams& params);
    void controlledAt(double t, MotionSample& out) const;
    void pivotAt(const PathPiece& piece, double t, double sinceStart, MotionSample& out) const;

    Scene m_scene;
    std::shared_ptr<const Path> m_path;
    ControlParams m_params;
    TimeLaw m_timeLaw;
    FreeMotion m_free;
    VakonomicMotion m_vak;
    double m_tEnd = 0;
    std::shared_ptr<const PerturbedMotion> m_open, m_feedback; // with a perturbation only
    std::shared_ptr<const PathFrame> m_frame;                  // the path as their frame
    ModelReport m_models;
};

} // namespace chaplygin
