#pragma once
// The time the time plots show: the whole run, a part of it zoomed and panned by the reader, or
// a window of that width that follows the time cursor. Every range stays within the run and no
// narrower than a few samples.
#include <qcustomplot.h>

namespace chaplygin::ui {

/// One wheel notch (120 eighths of a degree) away from the reader shows kWheelZoom of the span,
/// about the time under the mouse; toward the reader 1 / kWheelZoom.
constexpr double kWheelZoom = 0.8;
/// The narrowest span shown: this many of the run's sample intervals.
constexpr double kMinSamples = 8;
/// Following the cursor from the whole run shows this part of the run.
constexpr double kFollowPart = 0.125;
/// Following: when the cursor leaves the window, the window moves on so that the cursor is this
/// part of the span from its start, and the span ahead of it is seen.
constexpr double kFollowLead = 0.1;

class TimeWindow {
  public:
    enum class Mode { WholeRun, Zoomed, Following };

    /// The run's time range (as the whole-run axes show it) and its sample interval [s]: the
    /// limits of every range. A zoomed range is kept, within the new run.
    void setRun(const QCPRange& whole, double sampleInterval);
    QCPRange whole() const { return m_whole; }
    /// The narrowest span: kMinSamples sample intervals (never more than the run).
    double minSpan() const { return m_minSpan; }

    Mode mode() const { return m_mode; }
    /// The time range shown.
    QCPRange range() const { return m_mode == Mode::WholeRun ? m_whole : m_range; }

    /// Zooms by factor (below 1: in) keeping time `at` where it is on the axis; a non-finite
    /// `at` or factor changes nothing.
    void zoomAbout(double at, double factor);
    /// The wheel's zoom: angleDelta in eighths of a degree (positive away from the reader: in).
    void wheel(double at, double angleDelta);
    /// The range `from` moved later by dt [s] (a drag); stops following.
    void pan(const QCPRange& from, double dt);
    void showWholeRun();
    /// Following the cursor at time t: the zoomed span, or kFollowPart of the run; off keeps the
    /// range shown.
    void setFollowing(bool on, double t);
    /// Following: moves the window on when t has left it; returns whether the range changed.
    bool followCursor(double t);

  private:
    void show(double lower, double span);

    Mode m_mode = Mode::WholeRun;
    QCPRange m_whole{0, 1};
    QCPRange m_range{0, 1};
    double m_minSpan = 1e-9;
};

} // namespace chaplygin::ui
