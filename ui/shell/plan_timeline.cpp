#include "shell/plan_timeline.h"

#include "canvas/plan_tool.h"
#include "canvas/scene_canvas.h"
#include "shell/timeline_bar.h"

#include <algorithm>

namespace chaplygin::ui {

PlanTimeline::PlanTimeline(SceneCanvas& canvas, TimelineBar& timeline, Playback& sceneClock,
                           QObject* parent)
    : QObject(parent), m_canvas(canvas), m_timeline(timeline), m_sceneClock(sceneClock) {
    PlanTool* tool = canvas.planTool();
    connect(tool, &PlanTool::planChanged, this, &PlanTimeline::update);
    connect(&canvas, &SceneCanvas::planModeChanged, this, &PlanTimeline::update);
    // the played time (the Play plan action, a click on a plot) is the clock's
    connect(tool, &PlanTool::playTimeChanged, this, [this, tool](double t) {
        if (t < 0 || !follows())
            return;
        if (tool->playing())
            m_clock.pause();
        m_steering = true;
        m_clock.seek(t);
        m_steering = false;
    });
    // and the bar's play, steps and slider move the played bodies
    connect(&m_clock, &Playback::timeChanged, this, [this, tool](double t) {
        if (m_steering || !follows())
            return;
        if (tool->playing())
            tool->stopPlaying();
        tool->showAt(t);
    });
}

bool PlanTimeline::follows() const {
    return m_timeline.playback() == &m_clock;
}

void PlanTimeline::update() {
    const PlanTool* tool = m_canvas.planTool();
    const int i = m_canvas.planMode() ? tool->chosen() : -1;
    if (i < 0) {
        if (follows()) {
            m_timeline.setPlayback(&m_sceneClock);
            m_clock.seek(0);
        }
        return;
    }
    m_steering = true;
    m_clock.setTEnd(tool->planned().geodesics[std::size_t(i)].t);
    m_clock.seek(std::max(tool->playTime(), 0.0));
    m_steering = false;
    if (!follows())
        m_timeline.setPlayback(&m_clock);
    else
        m_timeline.sync(); // a new duration
}

} // namespace chaplygin::ui
