#pragma once
#include "scene/scene.h"
#include "scene/solution.h"

#include <QString>
#include <QStringList>

namespace chaplygin::ui {

/// File > Open: the scene in path; throws InputError naming the file (missing, a directory) or
/// the JSON path.
Scene openSceneFile(const QString& path);

/// File > Save: the scene as versioned JSON (the CLI's --scene format), written atomically.
/// Throws IoError.
void saveSceneFile(const QString& path, const Scene& scene);

/// File > Export CSV: samples rows evenly on [0, t_end] in the CLI's columns (one header row),
/// and the run's parameters and methods as the CLI's --summary JSON beside it
/// (csvSummaryPath). Each written atomically; throws IoError.
void exportCsvFile(const QString& path, const Solution& solution, int rows = 501);
/// The summary beside a CSV: "run.csv" -> "run.summary.json".
QString csvSummaryPath(const QString& csvPath);

/// The recent-files list kept in QSettings (most recent first, at most 8).
QStringList recentFiles();
void addRecentFile(const QString& path);

} // namespace chaplygin::ui
