#pragma once
#include <QString>

#include <functional>

class QAction;
class QCustomPlot;
class QMenu;

namespace chaplygin::ui {

/// Writes the plot as shown to path; the format follows the extension (png, pdf or svg), the
/// file is written atomically. Throws InputError for another extension, IoError when the file
/// cannot be written.
void exportPlotFile(QCustomPlot& plot, const QString& path);

/// Gives the plot a context menu "Export this plot…" (a save dialog proposing stem()).
/// onError receives the message when the export fails.
void installPlotExportMenu(QCustomPlot* plot, std::function<QString()> stem,
                           std::function<void(const QString&)> onError);

/// Adds "Fit all curves" to the plot's context menu (after installPlotExportMenu): checked, the
/// value axis holds every curve, not only the controlled ones (fitTimeAxes); the choice is the
/// plot's and outlives its redrawing.
void installFitAllAction(QCustomPlot* plot);
/// That action (for tests), or null.
QAction* fitAllAction(QCustomPlot* plot);

/// The context menu installPlotExportMenu shows (for tests).
QMenu* plotExportMenu(QCustomPlot* plot);

} // namespace chaplygin::ui
