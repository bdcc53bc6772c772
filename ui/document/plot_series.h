#pragma once
#include "planning/pose_planner.h"
#include "scene/solution.h"

#include <QString>
#include <QVector>

namespace chaplygin::ui {

/// The time series the plots draw, gathered from a Solution once per recompute.
/// Controlled quantities come from the path table's nodes (exact values at uneven times);
/// the free motion is sampled evenly in t.
struct PlotSeries {
    QVector<double> t, s, x, y, psi, chi, lambda, energy;
    QVector<double> freeT, freeX, freeY, freePsi, freeChi, freeEnergy;
    /// the genuine vakonomic body, at the free motion's times
    QVector<double> vakT, vakX, vakY, vakPsi, vakChi, vakLambda, vakEnergy;
    /// with a perturbation only (docs/physics.md §9): the open-loop and the closed-loop bodies
    /// and their tracking errors, at the free motion's times
    bool perturbed = false;
    QVector<double> pertT, pertX, pertY, fbX, fbY;
    QVector<double> openE, openTheta, fbE, fbTheta;
    QVector<double> pathX, pathY; ///< the prescribed path, whole
    double tEnd = 0;
    /// A planned motion's series (collectPlanSeries): no controlled body, the vakonomic columns
    /// are the planned genuine vakonomic body, the free ones its ghost.
    bool planned = false;
};

/// freeSamples: how many evenly spaced times for the free motion. exactSamples > 0 samples the
/// controlled motion evenly in t as well (exact, slower: for exported figures); 0 takes the
/// path table's nodes (cheap: for live plots).
PlotSeries collectSeries(const Solution& solution, int freeSamples = 400, int exactSamples = 0);

/// A planned motion (docs/physics.md §10) over [0, motion.t] at `samples` evenly spaced times:
/// the genuine vakonomic body along it in the vakonomic columns and the free ghost from the same
/// start in the free ones, from the core's closed forms (samplePlannedMotion).
PlotSeries collectPlanSeries(const PlanRequest& request, const PlannedGeodesic& motion,
                             int samples = 400);

/// Throws InputError naming the series and the time of its first non-finite value. The tracking
/// errors are left out: NaN there marks a lost closest point, and the plots leave it out.
void requireFiniteSeries(const PlotSeries& series);
/// One line that states the scene's parameters, for captions and exported files.
QString sceneCaption(const Solution& solution);
/// The same for a planned motion of the scene's system, in two lines: its start and target
/// poses, its time, Psi(0) and k; the system's parameters with v_T.
QString planCaption(const Solution& solution, const PlanRequest& request,
                    const PlannedGeodesic& motion);

} // namespace chaplygin::ui
