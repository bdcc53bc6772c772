#pragma once
#include "lab/work_precision.h"
#include "scene/scene.h"

#include <QString>
#include <QWidget>

#include <atomic>
#include <memory>
#include <optional>

class QCustomPlot;
class QMenu;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace chaplygin::ui {

class JobRunner;
class SceneDocument;

/// The Methods dock: the work-precision diagram of the current scene, computed on
/// demand in a worker thread with a progress bar and a Cancel button; then the references and
/// the app's chosen configurations, each marked on or off the Pareto front. A scene change while
/// the sweep runs cancels it.
class MethodsPanel : public QWidget {
    Q_OBJECT
  public:
    explicit MethodsPanel(SceneDocument* document, QWidget* parent = nullptr);
    /// Cancels a running sweep and waits for the worker (it stops after its configuration).
    ~MethodsPanel() override;

    bool isRunning() const;
    /// The last finished sweep (complete or cancelled), if any.
    const std::optional<WorkPrecisionReport>& report() const { return m_report; }
    QCustomPlot* plot() const { return m_plot; }
    /// The diagram's context menu ("Export this plot…").
    QMenu* plotMenu() const { return m_plotMenu; }
    QProgressBar* progressBar() const { return m_progress; }
    QPushButton* runButton() const { return m_run; }
    QPushButton* cancelButton() const { return m_cancel; }
    QTableWidget* chosenTable() const { return m_table; }
    QString statusText() const;

  public slots:
    /// Starts a sweep for the document's current valid scene (no-op while one runs).
    void start();
    /// Asks the running sweep to stop after the configuration under way; never blocks.
    void cancel();
    /// Waits for a running sweep and shows its result (for tests and screenshots).
    void waitForFinished();

  signals:
    /// A sweep has ended and its result is shown (cancelled or not).
    void finished();

  private:
    struct Outcome {
        WorkPrecisionReport report;
        QString error;
    };
    void onProgress(int done, int total);
    void onFinished();
    void fitColumns();
    void onSceneChanged();
    void showReport(const WorkPrecisionReport& report);
    void clearReport();

    SceneDocument* m_document;
    QPushButton* m_run;
    QPushButton* m_cancel;
    QProgressBar* m_progress;
    QLabel* m_status;
    QLabel* m_references;
    QCustomPlot* m_plot;
    QMenu* m_plotMenu;
    QTableWidget* m_table;
    std::optional<WorkPrecisionReport> m_report;
    Scene m_runScene;
    QString m_cancelReason;
    JobRunner* m_runner;                // the worker, shared with the other long jobs
    std::shared_ptr<Outcome> m_outcome; // filled by the running job
};

} // namespace chaplygin::ui
