#pragma once
#include "canvas/canvas_tool.h"
#include "canvas/curve_flattening.h"
#include "planning/pose_planner.h"
#include "scene/scene.h"

#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

namespace chaplygin::ui {

class CanvasView;
class SceneDocument;
struct CanvasStyle;

/// The Plan tool (docs/physics.md §10): the target pose dragged on the canvas, a handle for its
/// position and one for its heading (Shift snaps to half the grid step and to 15 degrees), the
/// start's position dragged likewise. While a handle moves, every genuine vakonomic motion from
/// the start to the target within the horizon is planned again and drawn: the chosen one (the
/// least time while dragging) and every optimal one in full with the body's outline at both
/// ends, the others faintly, each labelled with its time. A click on a motion chooses it. The
/// plan is the document's: each drag or choice is one undo step.
class PlanTool : public CanvasTool {
    Q_OBJECT
  public:
    PlanTool(const CanvasView& view, const CanvasStyle& style, SceneDocument* document,
             QObject* parent);

    bool press(const QMouseEvent& e) override;
    bool move(const QMouseEvent& e) override;
    void release(const QMouseEvent& e) override;
    bool active() const override { return m_drag != Drag::None; }
    void cancel() override;
    Qt::CursorShape cursor() const override { return Qt::SizeAllCursor; }
    void paint(QPainter& p) const override;

    /// The plan shown: the document's, or the one being dragged.
    const ScenePlan& plan() const { return m_plan; }
    /// The planner's answer for it (empty with an error), and the request it answered (while
    /// dragging, the last pose planned on the worker).
    const Plan& planned() const { return m_planned; }
    const PlanRequest& plannedRequest() const { return m_request; }
    /// Why nothing is planned (the constant-speed mode, no motion within the horizon); empty
    /// when planned.
    const QString& error() const { return m_error; }
    /// The motion chosen (an index into planned().geodesics), -1 when none.
    int chosen() const;
    /// The knife tracks of the planned motions as drawn, flattened to kTolerancePx device
    /// pixels within the view (param: time [s]).
    const std::vector<FlatCurve>& tracks() const {
        updateTracks();
        return m_tracks.curves;
    }
    /// Where the handles are drawn [px].
    QPointF targetHandle() const;
    QPointF headingHandle() const;
    QPointF startHandle() const;
    /// The world rectangle of the start, the target and every planned track [m] (for the fit).
    QRectF worldBounds() const;
    /// The longest a plan took while dragging, on the planning thread [ms].
    double slowestPlanMs() const { return m_slowestMs; }
    /// The time along the chosen motion the played bodies are drawn at [s]; negative when
    /// nothing is played.
    double playTime() const { return m_playTime; }
    bool playing() const { return m_playTimer.isActive(); }
    /// What the canvas says about the chosen motion: its family, k, Psi0, lambda(0), t and cut
    /// time (docs/physics.md §10).
    QString chosenSummary() const;

  signals:
    /// A new plan drawn (after a change, an undo, a load, a plan made while dragging): the
    /// chosen motion may be another.
    void planChanged();
    /// The played time changed (showAt, stopPlaying): playTime().
    void playTimeChanged(double t);

  public slots:
    /// The document's plan and solution again (after a change, an undo, a load).
    void syncFromDocument();
    /// Plays the chosen motion in real time from its start: the genuine vakonomic body along
    /// it, with the free Lagrange-d'Alembert ghost from the same start.
    void play();
    /// Shows the played bodies at time t [s] along the chosen motion (clamped to it).
    void showAt(double t);
    void stopPlaying();
    /// "Track this plan": the chosen motion's knife track becomes the scene's path (one undo
    /// step), so that the controlled body and the genuine vakonomic body coincide on it.
    void trackPlan();

  private:
    enum class Drag { None, Target, Heading, Start, Choosing };
    /// Plans the document's plan now (after a change, an undo, a load).
    void replan();
    /// While dragging: plans the pose dragged to on a worker thread, the latest pose next when
    /// one is under way (a plan can take longer than a frame: docs/physics.md §10).
    void planInBackground();
    void takeBackgroundPlan();
    struct BackgroundPlan {
        PlanRequest request;
        Plan plan;
        quint64 generation;
        double ms;
        QString error;
    };
    /// Flattens the planned tracks for the view when the plan, the scale or the view changed.
    void updateTracks() const;
    void commit(const ScenePlan& plan, const QString& description);
    /// The motion whose drawn track passes within a finger's width of `pixel`, or -1.
    int motionAt(QPointF pixel) const;
    /// A pose for the plan when the scene has none: the path's end, or 2 m ahead of the start.
    ScenePlan defaultPlan() const;
    double handleRadius() const;

    const CanvasView& m_view;
    const CanvasStyle& m_style;
    SceneDocument* m_document;
    ScenePlan m_plan;
    PlanRequest m_request;
    Plan m_planned;
    QString m_error;
    Drag m_drag = Drag::None;
    QPointF m_grabOffset; // [m] from the mouse to the dragged point
    double m_slowestMs = 0;
    QFutureWatcher<BackgroundPlan> m_planWatcher;
    std::optional<PlanRequest> m_nextRequest; // the newest pose while a plan is under way
    quint64 m_generation = 0;                 // one more at each plan made on this thread
    quint64 m_planId = 0;                     // a new one for each plan made
    /// The planned motions' knife tracks as last flattened, and for what
    struct FlattenedTracks {
        quint64 planId = ~quint64(0);
        double scale = 0; // [device px/m]
        QRectF seen;      // the view [m]
        std::vector<FlatCurve> curves;
    };
    mutable FlattenedTracks m_tracks;
    double m_playTime = -1;
    QTimer m_playTimer;
    QElapsedTimer m_playClock;
};

} // namespace chaplygin::ui
