// The main window's exports: File > Export plots, Export CSV and Export animation, each a
// dialog and the writing it asks for, reported with the place written.
#include "shell/main_window.h"

#include "canvas/plan_tool.h"
#include "canvas/scene_canvas.h"
#include "document/file_dialogs.h"
#include "document/scene_document.h"
#include "document/scene_files.h"
#include "plots/plot_export.h"
#include "shell/animation_dialog.h"
#include "shell/export_report.h"
#include "shell/playback.h"

#include <QDir>
#include <QFileInfo>
#include <QStatusBar>

namespace chaplygin::ui {

bool MainWindow::exportPlotsTo(const QString& dir, const QStringList& formats) {
    m_document->flush();
    try {
        // the plots the Plots dock shows: a planned motion's while one is chosen in plan mode
        const PlanTool* plan = m_canvas->planTool();
        const int chosen = m_canvas->planMode() ? plan->chosen() : -1;
        if (chosen >= 0)
            exportPlanPlots(*m_document->solution(), plan->plannedRequest(),
                            plan->planned().geodesics.at(std::size_t(chosen)), dir, formats);
        else
            exportPlots(*m_document->solution(), dir, formats, m_document->pins());
    } catch (const std::exception& e) {
        showFileError(QString::fromStdString(e.what()));
        return false;
    }
    m_exportReport->report(tr("Plots written to %1").arg(QDir::toNativeSeparators(dir)), dir);
    return true;
}

bool MainWindow::exportCsvTo(const QString& path) {
    m_document->flush();
    try {
        m_document->exportCsv(path);
    } catch (const std::exception& e) {
        showFileError(QString::fromStdString(e.what()));
        return false;
    }
    m_exportReport->report(
        tr("CSV written to %1, its parameters to %2")
            .arg(QDir::toNativeSeparators(path), QFileInfo(csvSummaryPath(path)).fileName()),
        QFileInfo(path).absolutePath());
    return true;
}

void MainWindow::exportPlotsDialog() {
    QString dir =
        chooseFolder(this, tr("Export plots (PNG, PDF and SVG) into"), QStringLiteral("plots"));
    if (!dir.isEmpty())
        exportPlotsTo(dir, {QStringLiteral("png"), QStringLiteral("pdf"), QStringLiteral("svg")});
}

void MainWindow::exportCsvDialog() {
    QString path = chooseSaveFile(this, tr("Export CSV"), QStringLiteral("csv"),
                                  sceneFileStem(m_document->scene(), m_document->fileName()),
                                  tr("CSV (*.csv)"));
    if (!path.isEmpty())
        exportCsvTo(path);
}

void MainWindow::exportAnimationDialog() {
    AnimationSettings initial;
    initial.speedFactor = m_playback->speedFactor();
    // a file in a folder that exists, never one relative to wherever the program was started
    const QString clip =
        sceneFileStem(m_document->scene(), m_document->fileName()) +
        (findFfmpeg().isEmpty() ? QStringLiteral("-frames/") : QStringLiteral(".mp4"));
    initial.file = QDir(lastFolder(QStringLiteral("animation"))).filePath(clip);
    AnimationDialog dialog(AnimationDialog::remembered(initial), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    AnimationSettings chosen = dialog.settings();
    AnimationDialog::remember(chosen);
    chosen.look = m_canvas->look();          // the clip shows what the screen shows
    if (QFileInfo(chosen.file).isRelative()) // a typed name goes beside the proposed one
        chosen.file = QDir(lastFolder(QStringLiteral("animation"))).filePath(chosen.file);
    exportAnimationTo(chosen);
}

bool MainWindow::exportAnimationTo(const AnimationSettings& settings) {
    QString error;
    m_lastFileError.clear();
    if (exportAnimationWithProgress(this, m_document, settings, &error)) {
        const QFileInfo written(settings.file);
        const bool frames = animationFormatOf(settings.file) == AnimationFormat::PngFrames;
        const QString folder = frames ? QDir(settings.file).absolutePath() : written.absolutePath();
        rememberFolder(QStringLiteral("animation"), folder);
        m_exportReport->report(
            frames ? tr("Frames written to %1").arg(QDir::toNativeSeparators(folder))
                   : tr("Animation written to %1")
                         .arg(QDir::toNativeSeparators(written.absoluteFilePath())),
            folder);
        return true;
    }
    if (error.isEmpty())
        statusBar()->showMessage(tr("Animation export cancelled"), 5000);
    else
        showFileError(error);
    return false;
}

} // namespace chaplygin::ui
