#pragma once
#include "lab/parameter_sweep.h"

#include <QString>
#include <QStringList>

class QCustomPlot;

namespace chaplygin::ui {

/// One quantity of a parameter sweep against the parameter: a line through the values with a
/// marker at each (the marker a click selects in the Sweep dock).
void drawSweep(QCustomPlot& plot, const SweepReport& report, SweepQuantity quantity);

/// Writes sweep_<column>.<format> into dir for every quantity (atomically); throws IoError
/// naming the file.
void exportSweep(const SweepReport& report, const QString& caption, const QString& dir,
                 const QStringList& formats);

} // namespace chaplygin::ui
