#pragma once
#include "plots/plot_figures.h"
#include "plots/time_window.h"

#include <QWidget>

#include <array>
#include <optional>

class QAction;
class QCPAxisRect;
class QCustomPlot;
class QMenu;
class QGridLayout;
class QTimer;

namespace chaplygin::ui {

class SceneDocument;

/// The plots dock: Psi, chi, lambda and the kinetic energy against t, each drawn by drawPlot
/// (so they look like the exported plots) with the free motion alongside, and a time cursor
/// that is a thin child widget, so that moving it repaints two narrow strips. Clicking seeks.
/// The time plots share one time range (TimeWindow): the wheel zooms it about the time under the
/// mouse, a middle or Shift drag pans it, a double click shows the whole run again, and "Follow
/// the cursor" moves a window of it along with the time cursor (the wheel then zooms about the
/// cursor); the value axes fit what is shown.
class PlotsPanel : public QWidget {
    Q_OBJECT
  public:
    static constexpr std::array<PlotKind, 4> kKinds{PlotKind::Psi, PlotKind::Chi, PlotKind::Lambda,
                                                    PlotKind::Energy};

    explicit PlotsPanel(SceneDocument* document, QWidget* parent = nullptr);

    QCustomPlot* plot(int index) const { return m_plots[index]; }
    /// A time plot's context menu ("Export this plot…", "Fit all curves") and its "Fit all
    /// curves" action.
    QMenu* contextMenu(int index) const { return m_menus[index]; }
    QAction* fitAllAction(int index) const { return m_fitAll[index]; }
    /// The time the time plots show, shared by all of them.
    const TimeWindow& timeWindow() const { return m_timeWindow; }
    /// Whether a click's seek waits for the double-click interval to pass.
    bool seekPending() const;
    /// "Follow the cursor" (checkable), "Whole run", "Zoom in on the time" and "Zoom out the
    /// time" (about the time cursor): in every time plot's context menu and the View menu.
    QAction* followCursorAction() const { return m_followCursor; }
    QAction* wholeRunAction() const { return m_wholeRun; }
    QAction* zoomInTimeAction() const { return m_zoomInTime; }
    QAction* zoomOutTimeAction() const { return m_zoomOutTime; }
    /// The time the cursor shows: the scene's, or the planned motion's while one is shown.
    double cursorTime() const { return m_plan ? m_planTime : m_time; }
    /// Whether the plots show a planned motion (showPlan) rather than the scene's.
    bool showsPlan() const { return m_plan.has_value(); }
    /// The time cursor drawn over a plot.
    QWidget* cursor(int index) const { return m_cursors[index]; }
    /// The perturbed bodies' errors against t (docs/physics.md §9), shown beside a row of the
    /// four plots or under two by two when the scene has a perturbation.
    QCustomPlot* errorPlot() const { return m_errorPlot; }
    /// The time cursor over the error plot's panel (0: e, 1: theta).
    QWidget* errorCursor(int panel) const { return m_errorCursors[panel]; }

  public slots:
    /// Hands the document's series to the plots (after each recompute).
    void refresh();
    void setTime(double t);
    /// The Plan tool's chosen motion (docs/physics.md §10): its series instead of the scene's,
    /// until showScene; the cursor at setPlanTime's time (hidden while it is negative).
    void showPlan(const PlotSeries& series);
    void setPlanTime(double t);
    void showScene();
    /// Repaints every plot now (for screenshots and the benchmark).
    void replotNow();
    /// Font and line scale and palette of the plots (presentation mode).
    void setLook(const CanvasStyle& look);

  signals:
    void seekRequested(double t);
    /// A click or drag on a plot while it shows a planned motion: that time along it.
    void planSeekRequested(double t);
    /// Exporting a plot from its context menu failed.
    void exportFailed(const QString& message);

  protected:
    void resizeEvent(QResizeEvent* e) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void arrange();
    QWidget* makeCursor(QCustomPlot* plot);
    void makeSeekable(QCustomPlot* plot);
    void makeTimeZoomable(QCustomPlot* plot);
    void makeTimeActions();
    void addTimeActions(QMenu& menu);
    /// The time plots' axis rectangles (the error plot's when it is shown).
    QList<QCPAxisRect*> timeRects() const;
    /// The run's range and sample interval handed to the TimeWindow after drawing.
    void measureRun();
    /// The TimeWindow's range on every time plot, the value axes fitted to it.
    void showTimeWindow();
    void zoomTimeAboutCursor(double factor);
    void placeCursor(QCustomPlot* plot, int rect, QWidget* cursor);
    void placeCursors();

    SceneDocument* m_document;
    std::array<QCustomPlot*, 4> m_plots{};
    std::array<QMenu*, 4> m_menus{};
    std::array<QAction*, 4> m_fitAll{};
    std::array<QWidget*, 4> m_cursors{};
    QCustomPlot* m_errorPlot = nullptr;
    TimeWindow m_timeWindow;
    QAction* m_followCursor = nullptr;
    QAction* m_wholeRun = nullptr;
    QAction* m_zoomInTime = nullptr;
    QAction* m_zoomOutTime = nullptr;
    struct TimePan {
        bool active = false;
        double startX = 0;
        QCPRange from;
        double secondsPerPixel = 0;
    } m_timePan;
    /// A press seeks once the double-click interval has passed without a second press, so that
    /// a double click (the whole run) does not seek; a drag beyond the drag distance scrubs at
    /// once.
    QTimer* m_clickSeek = nullptr;
    struct PendingSeek {
        double t = 0;
        bool plan = false; ///< the planned motion's time, not the scene's
        QPointF pressedAt; ///< [px] in the plot
        bool dragging = false;
    } m_pendingSeek;
    void emitSeek(double t, bool plan);
    std::array<QWidget*, 2> m_errorCursors{};
    bool m_errorsShown = false;
    double m_time = 0;
    std::optional<PlotSeries> m_plan;
    double m_planTime = -1;
    QGridLayout* m_grid;
    int m_columns = 2;
};

} // namespace chaplygin::ui
