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

/// Gives the plot a context menu "Export this plot…" (a save dialog proposing stem()) and
/// returns it (the plot's child). onError receives the message when the export fails.
QMenu* installPlotExportMenu(QCustomPlot* plot, std::function<QString()> stem,
                             std::function<void(const QString&)> onError);

/// Adds "Fit all curves" to the plot's context menu `menu` (installPlotExportMenu's) and
/// returns it: checked, the value axis holds every curve, not only the controlled ones
/// (fitTimeAxes); the choice is the plot's and outlives its redrawing.
QAction* installFitAllAction(QCustomPlot* plot, QMenu& menu);

} // namespace chaplygin::ui
