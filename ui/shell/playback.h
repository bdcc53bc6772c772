#pragma once
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <array>

namespace chaplygin::ui {

/// The playback speeds offered, simulated seconds per real second: the powers of two from 1/16
/// (a fast turn slowed down to be seen) to 64 (a long path, 2,700 s along y = sin x, in 43 s).
constexpr std::array<double, 11> kPlaybackSpeeds = {1.0 / 16, 1.0 / 8, 1.0 / 4, 1.0 / 2, 1, 2,
                                                    4,        8,       16,      32,      64};

/// The animation clock: the shown time t in [0, tEnd], advanced in real time times a speed
/// factor while playing, at most once per display frame.
class Playback : public QObject {
    Q_OBJECT
  public:
    explicit Playback(QObject* parent = nullptr);

    double time() const { return m_time; }
    double tEnd() const { return m_tEnd; }
    bool isPlaying() const { return m_timer.isActive(); }
    bool loops() const { return m_loop; }
    double speedFactor() const { return m_factor; }
    /// Simulated seconds per single step: one display frame at the current speed.
    double stepSize() const;
    /// Simulated seconds per large step (Shift with the step keys).
    static constexpr double kLargeStep = 1.0;

  public slots:
    void setTEnd(double tEnd);
    void seek(double t);
    void play();
    void pause();
    void togglePlay();
    void stepForward();
    void stepBackward();
    /// Pauses and moves by dt simulated seconds (clamped to [0, tEnd]).
    void stepBy(double dt);
    void goToStart();
    void goToEnd();
    void setLoop(bool loop);
    void setSpeedFactor(double factor);
    /// Advances by dt real seconds (what one tick does); public for benchmarks and tests.
    void advance(double dtReal);

  signals:
    void timeChanged(double t);
    void playingChanged(bool playing);

  private:
    void tick();

    QTimer m_timer;
    QElapsedTimer m_clock;
    double m_time = 0, m_tEnd = 0, m_factor = 1;
    bool m_loop = false;
};

} // namespace chaplygin::ui
