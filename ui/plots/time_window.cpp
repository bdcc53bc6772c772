#include "plots/time_window.h"

#include <algorithm>
#include <cmath>

namespace chaplygin::ui {

void TimeWindow::setRun(const QCPRange& whole, double sampleInterval) {
    if (!std::isfinite(whole.lower) || !std::isfinite(whole.upper) || !(whole.upper > whole.lower))
        return;
    m_whole = whole;
    const double size = whole.size();
    const double interval =
        std::isfinite(sampleInterval) && sampleInterval > 0 ? sampleInterval : size / 1000;
    // at least a millionth of the run, so that the span stays many doubles wide
    m_minSpan = std::min(size, std::max(kMinSamples * interval, 1e-6 * size));
    if (m_mode != Mode::WholeRun)
        show(m_range.lower, m_range.size());
}

void TimeWindow::show(double lower, double span) {
    const double size = m_whole.size();
    if (std::isnan(span))
        return;
    span = std::clamp(span, m_minSpan, size);
    if (std::isnan(lower))
        lower = m_range.lower;
    lower = std::clamp(lower, m_whole.lower, m_whole.upper - span);
    m_range = span >= size ? m_whole : QCPRange(lower, lower + span);
    if (m_mode == Mode::WholeRun)
        m_mode = Mode::Zoomed;
    if (m_mode == Mode::Zoomed && span >= size)
        m_mode = Mode::WholeRun;
}

void TimeWindow::zoomAbout(double at, double factor) {
    if (!std::isfinite(at) || !std::isfinite(factor) || !(factor > 0))
        return;
    const QCPRange now = range();
    at = std::clamp(at, now.lower, now.upper);
    const double span = std::clamp(now.size() * factor, m_minSpan, m_whole.size());
    show(at - (at - now.lower) * span / now.size(), span);
}

void TimeWindow::wheel(double at, double angleDelta) {
    if (!std::isfinite(angleDelta))
        return;
    // a burst of any size: the span saturates at its limits long before pow over- or underflows
    const double notches = std::clamp(angleDelta / 120.0, -200.0, 200.0);
    zoomAbout(at, std::pow(kWheelZoom, notches));
}

void TimeWindow::pan(const QCPRange& from, double dt) {
    if (!std::isfinite(dt) || !std::isfinite(from.lower) || !std::isfinite(from.upper))
        return;
    if (m_mode == Mode::Following)
        m_mode = Mode::Zoomed;
    show(from.lower + dt, from.size());
}

void TimeWindow::showWholeRun() {
    m_mode = Mode::WholeRun;
    m_range = m_whole;
}

void TimeWindow::setFollowing(bool on, double t) {
    if (!on) {
        if (m_mode == Mode::Following)
            m_mode = m_range.size() >= m_whole.size() ? Mode::WholeRun : Mode::Zoomed;
        return;
    }
    const double span = m_mode == Mode::Zoomed ? m_range.size() : kFollowPart * m_whole.size();
    m_mode = Mode::Following;
    m_range = m_whole;
    show(std::isfinite(t) ? t - kFollowLead * span : m_whole.lower, span);
    followCursor(t);
}

bool TimeWindow::followCursor(double t) {
    if (m_mode != Mode::Following || !std::isfinite(t))
        return false;
    const double span = m_range.size();
    // on before the cursor reaches the frame's right edge, where it would be hidden
    if (t >= m_range.lower && t <= m_range.upper - 0.02 * span)
        return false;
    const QCPRange before = m_range;
    show(t - kFollowLead * span, span);
    return m_range != before;
}

} // namespace chaplygin::ui
