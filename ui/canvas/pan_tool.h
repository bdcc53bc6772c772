#pragma once
#include "canvas/canvas_tool.h"

#include <QPointF>

namespace chaplygin::ui {

class CanvasView;

/// Dragging the view: what no other tool of the mode takes pans (any button).
class PanTool : public CanvasTool {
    Q_OBJECT
  public:
    PanTool(CanvasView& view, QObject* parent);

    bool press(const QMouseEvent& e) override;
    bool move(const QMouseEvent& e) override;
    void release(const QMouseEvent& e) override;
    bool active() const override { return m_panning; }
    void cancel() override { m_panning = false; }
    Qt::CursorShape cursor() const override { return Qt::ClosedHandCursor; }

  signals:
    /// The user moved the view.
    void panned();

  private:
    CanvasView& m_view;
    bool m_panning = false;
    QPointF m_last; // the pixel of the last press or move
};

} // namespace chaplygin::ui
