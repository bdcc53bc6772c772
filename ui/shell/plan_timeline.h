#pragma once
#include "shell/playback.h"

#include <QObject>

namespace chaplygin::ui {

class SceneCanvas;
class TimelineBar;

/// The timeline of a planned motion (docs/physics.md §10): while a motion is chosen in plan mode
/// the timeline bar shows and drives the plan's own clock, which runs over the chosen motion's
/// duration and keeps its played time (the Play plan action and a click on a plot move it; the
/// bar's play, steps and slider move the played bodies). Out of plan mode the bar is the scene's
/// clock again, which the plan never moved.
class PlanTimeline : public QObject {
    Q_OBJECT
  public:
    PlanTimeline(SceneCanvas& canvas, TimelineBar& timeline, Playback& sceneClock, QObject* parent);

    /// The plan's clock.
    Playback& clock() { return m_clock; }
    /// Whether the timeline bar shows the plan's clock.
    bool follows() const;

  private:
    /// The bar on the plan's clock with the chosen motion's duration, or on the scene's.
    void update();

    SceneCanvas& m_canvas;
    TimelineBar& m_timeline;
    Playback& m_sceneClock;
    Playback m_clock;
    bool m_steering = false; // the clock moved to the played time, not by the bar
};

} // namespace chaplygin::ui
