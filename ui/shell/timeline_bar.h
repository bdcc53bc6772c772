#pragma once
#include <QFont>
#include <QToolBar>

#include <array>

class QAction;
class QComboBox;
class QLabel;
class QMenu;
class QSlider;

namespace chaplygin::ui {

class Playback;

/// The timeline toolbar: play/pause (Space), single steps, speed x1/16 ... x64 (the box, the
/// Faster and Slower keys ] and [, and the Speed menu), loop, and a scrub slider with the time
/// shown, all of one clock: the scene's, or another put in its place (setPlayback: a planned
/// motion's).
class TimelineBar : public QToolBar {
    Q_OBJECT
  public:
    explicit TimelineBar(Playback* playback, QWidget* parent = nullptr);

    QAction* playAction() const { return m_play; }
    QAction* stepForwardAction() const { return m_stepForward; }
    QAction* stepBackAction() const { return m_stepBack; }
    QAction* loopAction() const { return m_loop; }
    /// Home and End; Shift+, and Shift+. step one second.
    QAction* startAction() const { return m_start; }
    QAction* endAction() const { return m_end; }
    QAction* secondBackAction() const { return m_secondBack; }
    QAction* secondForwardAction() const { return m_secondForward; }
    QSlider* slider() const { return m_slider; }
    QComboBox* speedBox() const { return m_speed; }
    /// ] and [: the next speed up or down (kPlaybackSpeeds); Backspace: x1.
    QAction* fasterAction() const { return m_faster; }
    QAction* slowerAction() const { return m_slower; }
    QAction* normalSpeedAction() const { return m_normalSpeed; }
    /// Animation > Speed: one checkable entry per speed, kept in step with the box.
    QMenu* makeSpeedMenu(QWidget* parent);
    QLabel* timeLabel() const { return m_timeLabel; }
    /// The clock the bar shows and drives.
    Playback* playback() const { return m_playback; }
    /// Shows and drives `playback` from now on, with the bar's speed and loop; the clock shown
    /// before is paused.
    void setPlayback(Playback* playback);

  public slots:
    /// Follows the clock (and a new horizon).
    void sync();

  protected:
    /// A new font (presentation mode) sizes the time read-out anew at once, not at the next
    /// tick: its text is never cut.
    void changeEvent(QEvent* event) override;

  private:
    void connectClock();
    void showPlaying(bool playing);

    Playback* m_playback;
    std::array<QMetaObject::Connection, 2> m_clockConnections;
    QAction* m_play;
    QAction* m_stepBack;
    QAction* m_stepForward;
    QAction* m_loop;
    QAction* m_start = nullptr;
    QAction* m_end = nullptr;
    QAction* m_secondBack = nullptr;
    QAction* m_secondForward = nullptr;
    QComboBox* m_speed;
    QAction* m_faster;
    QAction* m_slower;
    QAction* m_normalSpeed;
    QSlider* m_slider;
    QLabel* m_timeLabel;
    bool m_syncing = false;
    double m_labelEnd = -1; // the end time and the font the label's fixed size was made for
    QFont m_labelFont;
};

} // namespace chaplygin::ui
