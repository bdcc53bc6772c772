#pragma once
#include "lab/parameter_sweep.h"
#include "scene/scene.h"

#include <QString>
#include <QWidget>

#include <memory>
#include <optional>

class QComboBox;
class QCustomPlot;
class QLabel;
class QProgressBar;
class QPushButton;

namespace chaplygin::ui {

class NumberField;

class JobRunner;
class SceneDocument;

/// The Sweep dock: one parameter of the current scene over a range, a quantity (duration, max
/// |lambda|, max |tau|, max |N|, max |power|, final separation) plotted against it. The sweep
/// runs in a JobRunner with a progress bar and Cancel; a bad range is refused before any work
/// with the core's message, and a scene change cancels a running sweep. Clicking a point asks to
/// load that value (sceneEdited, so the owner pushes it on the undo stack).
class SweepPanel : public QWidget {
    Q_OBJECT
  public:
    explicit SweepPanel(SceneDocument* document, QWidget* parent = nullptr);
    ~SweepPanel() override;

    QComboBox* parameterBox() const { return m_parameter; }
    NumberField* fromBox() const { return m_from; }
    NumberField* toBox() const { return m_to; }
    NumberField* countBox() const { return m_count; }
    QComboBox* quantityBox() const { return m_quantity; }
    QPushButton* runButton() const { return m_run; }
    QPushButton* cancelButton() const { return m_cancel; }
    QProgressBar* progressBar() const { return m_progress; }
    QCustomPlot* plot() const { return m_plot; }
    QString statusText() const;
    bool isRunning() const;
    /// The last sweep shown (complete or cancelled).
    const std::optional<SweepReport>& report() const { return m_report; }

  public slots:
    /// Starts a sweep of the current scene with the chosen range (no-op while one runs).
    void start();
    void cancel();
    /// Waits for a running sweep and shows it (tests, screenshots).
    void waitForFinished();
    /// Loads the value of the report's row (what clicking its point does).
    void loadRow(int row);

  signals:
    void sceneEdited(const Scene& scene, const QString& description, const QString& mergeKey);
    void finished();

  private:
    struct Outcome {
        std::optional<SweepReport> report;
        QString error;
    };
    void onSceneChanged();
    void onFinished();
    void onParameterChosen();
    void redraw();
    void onPlotClicked(QMouseEvent* event);

    SceneDocument* m_document;
    JobRunner* m_runner;
    QComboBox* m_parameter;
    NumberField* m_from;
    NumberField* m_to;
    NumberField* m_count;
    QComboBox* m_quantity;
    QPushButton* m_run;
    QPushButton* m_cancel;
    QProgressBar* m_progress;
    QLabel* m_status;
    QCustomPlot* m_plot;
    std::optional<SweepReport> m_report;
    Scene m_runScene;
    std::shared_ptr<Outcome> m_outcome;
    SystemKind m_shownKind = SystemKind::Sleigh;
    SpeedMode m_shownMode = SpeedMode::Energy;
    bool m_namesShown = false;
    bool m_sceneChanged = false; // the running sweep was cancelled by a scene change
};

} // namespace chaplygin::ui
