#pragma once
#include "lab/work_precision.h"

#include <QString>
#include <QStringList>

class QCustomPlot;

namespace chaplygin::ui {

/// The work-precision diagram: error against seconds per solve, log-log, one series
/// per method, controlled and free motion side by side; the app's chosen configuration is a star.
void drawWorkPrecision(QCustomPlot& plot, const WorkPrecisionReport& report);

/// Writes work_precision.<format> into dir (atomically); throws IoError naming the file.
void exportWorkPrecision(const WorkPrecisionReport& report, const QString& caption,
                         const QString& dir, const QStringList& formats);

} // namespace chaplygin::ui
