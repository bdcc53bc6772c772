#pragma once
#include "canvas/canvas_tool.h"

#include <QPointF>

#include <functional>

namespace chaplygin::ui {

class CanvasView;
struct CanvasStyle;

/// Grab and push (docs/physics.md §9): the left button on the controlled body drags a push;
/// the drag's component along the heading's left normal is the push's size.
class PushTool : public CanvasTool {
    Q_OBJECT
  public:
    /// The body grabbed at a pixel, if any: the time [s] and the heading φ [rad] it had there.
    struct Grab {
        bool onBody = false;
        double t = 0, phi = 0;
    };
    PushTool(const CanvasView& view, const CanvasStyle& style, std::function<Grab(QPointF)> grab,
             QObject* parent);

    bool press(const QMouseEvent& e) override;
    bool move(const QMouseEvent& e) override;
    void release(const QMouseEvent& e) override;
    bool active() const override { return m_pushing; }
    void cancel() override { m_pushing = false; }
    Qt::CursorShape cursor() const override { return Qt::SizeAllCursor; }
    void paint(QPainter& p) const override;

  signals:
    /// The body was pushed at time t by pushDy [m] to the left of its heading.
    void pushDragged(double t, double pushDy);

  private:
    const CanvasView& m_view;
    const CanvasStyle& m_style;
    std::function<Grab(QPointF)> m_grab;
    bool m_pushing = false;
    QPointF m_from; // world point pressed
    QPointF m_to;   // pixel under the mouse
    Grab m_grabbed;
};

} // namespace chaplygin::ui
