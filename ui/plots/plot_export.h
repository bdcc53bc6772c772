#pragma once
#include "planning/pose_planner.h"
#include "plots/plot_figures.h"
#include "scene/solution.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

class QCustomPlot;

namespace chaplygin::ui {

class PinSet;

/// Renders a prepared plot to bytes: "png", "pdf" or "svg", at width x height pixels (points).
QByteArray renderPlot(QCustomPlot& plot, const QString& format, int width, int height);

/// Writes every plot of the solution (Psi, chi, lambda, energy, trajectory, the paper's figure)
/// into dir as <stem>.<format>, each with a title and a caption stating the parameters. Each
/// file is written atomically; throws IoError naming the file when one cannot be written.
/// Needs a QApplication (the offscreen platform is enough). With pins, the time plots carry the
/// pinned runs as the Plots dock shows them.
void exportPlots(const Solution& solution, const QString& dir, const QStringList& formats,
                 PinSet* pins = nullptr);

/// Writes the plots of a planned motion of the solution's system (docs/physics.md §10) as the
/// Plots dock shows them in plan mode: Psi, chi, lambda and the energy of its genuine vakonomic
/// body and of the free ghost from the same start, over [0, t], each with a title and a caption
/// stating the poses, the motion and the parameters. Like exportPlots otherwise.
void exportPlanPlots(const Solution& solution, const PlanRequest& request,
                     const PlannedGeodesic& motion, const QString& dir, const QStringList& formats);

} // namespace chaplygin::ui
