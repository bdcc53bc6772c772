#pragma once
#include "canvas/canvas_tool.h"

#include <QPointF>

#include <utility>
#include <vector>

namespace chaplygin::ui {

class CanvasView;
struct CanvasStyle;

/// Draw mode's stroke: the left button drags a new path, sampled every 10 px.
class DrawTool : public CanvasTool {
    Q_OBJECT
  public:
    DrawTool(const CanvasView& view, const CanvasStyle& style, QObject* parent);

    bool press(const QMouseEvent& e) override;
    bool move(const QMouseEvent& e) override;
    void release(const QMouseEvent& e) override;
    bool active() const override { return !m_stroke.empty(); }
    void cancel() override { m_stroke.clear(); }
    Qt::CursorShape cursor() const override { return Qt::CrossCursor; }
    void paint(QPainter& p) const override;

  signals:
    /// The stroke finished: its points in metres, in order (at least three).
    void pathDrawn(const std::vector<std::pair<double, double>>& points);

  private:
    const CanvasView& m_view;
    const CanvasStyle& m_style;
    std::vector<QPointF> m_stroke; // world points of the stroke being drawn
};

} // namespace chaplygin::ui
