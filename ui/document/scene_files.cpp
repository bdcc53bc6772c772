#include "document/scene_files.h"

#include "common/atomic_file.h"
#include "common/input_error.h"
#include "scene/csv_writer.h"
#include "scene/scene_json.h"
#include "scene/summary_json.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QSettings>

namespace chaplygin::ui {

namespace {
const QString kRecentKey = QStringLiteral("recentFiles");
constexpr int kMaxRecent = 8;
} // namespace

Scene openSceneFile(const QString& path) {
    QFileInfo info(path);
    std::string where =
        QCoreApplication::translate("SceneFiles", "cannot open '%1'").arg(path).toStdString();
    if (!info.exists())
        throw InputError(where,
                         QCoreApplication::translate("SceneFiles", "no such file").toStdString());
    if (info.isDir())
        throw InputError(
            where, QCoreApplication::translate("SceneFiles", "it is a directory, not a scene file")
                       .toStdString());
    return loadSceneFile(path.toStdString());
}

void saveSceneFile(const QString& path, const Scene& scene) {
    writeFileAtomically(path.toStdString(), sceneToJson(scene));
}

QString csvSummaryPath(const QString& csvPath) {
    QString stem = csvPath;
    if (stem.endsWith(QStringLiteral(".csv"), Qt::CaseInsensitive))
        stem.chop(4);
    return stem + QStringLiteral(".summary.json");
}

void exportCsvFile(const QString& path, const Solution& solution, int rows) {
    writeFileAtomically(path.toStdString(), formatCsv(solution.sample(rows)));
    writeFileAtomically(csvSummaryPath(path).toStdString(), formatSummary(solution));
}

QStringList recentFiles() {
    return QSettings().value(kRecentKey).toStringList();
}

void addRecentFile(const QString& path) {
    QString full = QFileInfo(path).absoluteFilePath();
    QStringList list = recentFiles();
    list.removeAll(full);
    list.prepend(full);
    while (list.size() > kMaxRecent)
        list.removeLast();
    QSettings().setValue(kRecentKey, list);
}

} // namespace chaplygin::ui
