#pragma once
// Drawing with the pen in the GUI tests: synthetic drags of the left button and the colour test
// of a pixel.
#include <QApplication>
#include <QColor>
#include <QMouseEvent>
#include <QtTest>

#include <cstdlib>

namespace chaplygin::ui::test {

inline void sendMove(QWidget* w, QPointF at, Qt::MouseButtons buttons, Qt::KeyboardModifiers keys) {
    QMouseEvent move(QEvent::MouseMove, at, w->mapToGlobal(at), Qt::NoButton, buttons, keys);
    QApplication::sendEvent(w, &move);
}

/// A drag of the left button between two whole pixels in `steps` moves.
inline void drag(QWidget* w, QPoint from, QPoint to, int steps = 20,
                 Qt::KeyboardModifiers keys = Qt::NoModifier) {
    QTest::mousePress(w, Qt::LeftButton, keys, from);
    for (int i = 1; i <= steps; ++i)
        sendMove(w, QPointF(from) + QPointF(to - from) * (double(i) / steps), Qt::LeftButton, keys);
    QTest::mouseRelease(w, Qt::LeftButton, keys, to);
}

/// Whether two colours differ by at most `tolerance` in each of red, green and blue.
inline bool near(QColor a, QColor b, int tolerance = 12) {
    return std::abs(a.red() - b.red()) <= tolerance &&
           std::abs(a.green() - b.green()) <= tolerance &&
           std::abs(a.blue() - b.blue()) <= tolerance;
}

} // namespace chaplygin::ui::test
