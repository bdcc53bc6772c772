#pragma once
#include <QString>
#include <QTimer>
#include <QWidget>

#include <optional>

class QFormLayout;
class QLabel;
class QToolButton;

namespace chaplygin::ui {

class SceneDocument;

/// What the accuracy readout shows at one time; every number compares values the core gives.
struct AccuracyValues {
    double t = 0;                     ///< [s]
    double trackingResidual = 0;      ///< |P(t) - path(s(t))|, the path at the same arc length [m]
    std::optional<double> paperError; ///< |P(t) - P_paper(t)| on the line and circle presets [m]
    QString paperEquations;           ///< which closed form, e.g. "eqs. (93)-(94)"
    std::optional<double> controlledDrift; ///< |T - T0|/T0, constant-energy mode only
    double freeDrift = 0;                  ///< |T - T0|/T0 of the free motion
};

/// The Plan tool's chosen motion as the accuracy readout shows it (docs/physics.md §10).
struct PlanAccuracy {
    int index = 0, count = 0; ///< motion index + 1 of count
    double t = 0;             ///< its arrival time [s]
    double cutTime = 0;       ///< its cut time [s] (infinite on a line and the separatrix)
    double endError = 0;      ///< |dx|/b + |dy|/b + |dphi mod 2 pi| at t
    bool optimal = false;     ///< a least-time motion, certified by t <= cutTime
};

/// The live accuracy readout beside the animation: at the shown time, the
/// controlled body's distance from the prescribed path at the same arc length, its error
/// against the paper's closed form where one exists, the energy drift of the controlled and
/// the free motion, the models and methods in use, and a note (a gallery scene's explanation).
/// The t shown is the canvas's, set every frame; the numbers beside it change at a meter's pace.
/// The models are named in plain words, their technical description behind "Details".
/// In plan mode, the chosen planned motion's end error on the target and whether it is
/// certified optimal, above the scene's numbers.
class AccuracyReadout : public QWidget {
    Q_OBJECT
  public:
    explicit AccuracyReadout(SceneDocument* document, QWidget* parent = nullptr);

    const AccuracyValues& values() const { return m_values; }
    /// The shown text of the note (empty when there is none).
    QString noteText() const;
    /// The technical description of the models (behind "Details").
    QString modelsText() const;
    /// The plain one-line summary shown on screen.
    QString plainModelsText() const;
    /// The shown time, e.g. "2.760 s".
    QString timeText() const;
    QToolButton* detailsButton() const { return m_details; }
    /// The planned motion shown (showPlan), and its end error's and optimality's texts (empty
    /// when none is shown).
    const std::optional<PlanAccuracy>& plan() const { return m_plan; }
    QString planEndErrorText() const;
    QString planOptimalText() const;

  public slots:
    /// Shows t at once and marks the numbers for an update (latest value wins).
    void setTime(double t);
    /// Updates now at the last time set.
    void refresh();
    /// A note above the numbers; warning draws it as a refusal. Empty text hides it.
    void setNote(const QString& title, const QString& text, bool warning = false);
    /// The chosen planned motion's accuracy; nullopt hides it (out of plan mode).
    void showPlan(const std::optional<PlanAccuracy>& plan);

  protected:
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;

  private:
    void onSolutionChanged();
    /// The time label keeps one size, so that a new time lays out nothing.
    void fixTimeSize();
    /// The plan's rows from m_plan.
    void fillPlan();

    SceneDocument* m_document;
    QLabel* m_note;
    QFormLayout* m_form;
    QLabel* m_planTitle;
    QLabel* m_planEndError;
    QLabel* m_planOptimal;
    std::optional<PlanAccuracy> m_plan;
    QLabel* m_time;
    QLabel* m_tracking;
    QLabel* m_paper;
    QLabel* m_controlledDrift;
    QLabel* m_freeDrift;
    QLabel* m_plainModels;
    QToolButton* m_details;
    QLabel* m_models;
    QTimer m_refresh;
    double m_t = 0;
    double m_controlledT0 = 0, m_freeT0 = 0;
    AccuracyValues m_values;
};

} // namespace chaplygin::ui
