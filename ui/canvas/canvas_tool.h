#pragma once
#include <QObject>

class QMouseEvent;
class QPainter;

namespace chaplygin::ui {

/// One way the mouse acts on the canvas: drawing a path, editing its points, pushing the body,
/// panning. The canvas offers a press to its mode's tools in order and the first that takes
/// it starts its gesture; moves go to the gestures under way, in the same order.
class CanvasTool : public QObject {
    Q_OBJECT
  public:
    using QObject::QObject;

    /// Takes the press when it starts this tool's gesture.
    virtual bool press(const QMouseEvent& e) = 0;
    /// A move during the gesture; false when this tool leaves it to the next.
    virtual bool move(const QMouseEvent& e) = 0;
    /// A move with no gesture under way (the canvas tracks the mouse while a tool needs it):
    /// true when this tool shows something for it.
    virtual bool hover(const QMouseEvent&) { return false; }
    /// The end of the gesture (the tool checks the button).
    virtual void release(const QMouseEvent& e) = 0;
    /// Whether a gesture is under way.
    virtual bool active() const = 0;
    /// Ends the gesture under way without its effect.
    virtual void cancel() = 0;
    /// The cursor during the gesture.
    virtual Qt::CursorShape cursor() const { return Qt::ArrowCursor; }
    /// What the tool shows over the scene [px].
    virtual void paint(QPainter&) const {}

  signals:
    /// What the tool shows changed: the canvas repaints.
    void changed();
};

} // namespace chaplygin::ui
