#include "shell/playback.h"

#include <algorithm>

namespace chaplygin::ui {

namespace {
constexpr int kFrameMs = 16; // about 60 Hz
}

Playback::Playback(QObject* parent) : QObject(parent) {
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(kFrameMs);
    connect(&m_timer, &QTimer::timeout, this, &Playback::tick);
}

double Playback::stepSize() const {
    return kFrameMs / 1000.0 * m_factor;
}

void Playback::stepBy(double dt) {
    pause();
    seek(m_time + dt);
}

void Playback::goToStart() {
    pause();
    seek(0);
}

void Playback::goToEnd() {
    pause();
    seek(m_tEnd);
}

void Playback::setTEnd(double tEnd) {
    m_tEnd = std::max(tEnd, 0.0);
    if (m_time > m_tEnd)
        seek(m_tEnd);
}

void Playback::seek(double t) {
    t = std::clamp(t, 0.0, m_tEnd);
    if (t == m_time)
        return;
    m_time = t;
    emit timeChanged(m_time);
}

void Playback::play() {
    if (isPlaying())
        return;
    if (m_time >= m_tEnd)
        seek(0);
    m_clock.start();
    m_timer.start();
    emit playingChanged(true);
}

void Playback::pause() {
    if (!isPlaying())
        return;
    m_timer.stop();
    emit playingChanged(false);
}

void Playback::togglePlay() {
    isPlaying() ? pause() : play();
}

void Playback::stepForward() {
    pause();
    seek(m_time + stepSize());
}

void Playback::stepBackward() {
    pause();
    seek(m_time - stepSize());
}

void Playback::setLoop(bool loop) {
    m_loop = loop;
}

void Playback::setSpeedFactor(double factor) {
    m_factor = std::clamp(factor, 0.01, 100.0);
}

void Playback::advance(double dtReal) {
    double t = m_time + dtReal * m_factor;
    if (t >= m_tEnd) {
        if (m_loop && m_tEnd > 0) {
            t = 0;
        } else {
            seek(m_tEnd);
            pause();
            return;
        }
    }
    seek(t);
}

void Playback::tick() {
    double dt = m_clock.restart() / 1000.0;
    advance(std::min(dt, 0.1));
}

} // namespace chaplygin::ui
