#pragma once
#include "canvas/canvas_tool.h"

#include <QPointF>

#include <functional>
#include <utility>
#include <vector>

namespace chaplygin::ui {

class CanvasView;
struct CanvasStyle;

/// Draw mode's points: the drawn path's vertices shown as squares; the left button drags one,
/// the right button deletes one (a path keeps at least two).
class EditPointsTool : public CanvasTool {
    Q_OBJECT
  public:
    using Points = std::vector<std::pair<double, double>>;
    /// `points` gives the vertices of the current drawn path (empty for another kind of path).
    EditPointsTool(const CanvasView& view, const CanvasStyle& style, std::function<Points()> points,
                   QObject* parent);

    bool press(const QMouseEvent& e) override;
    bool move(const QMouseEvent& e) override;
    void release(const QMouseEvent& e) override;
    bool active() const override { return m_dragVertex >= 0; }
    void cancel() override { m_dragVertex = -1; }
    Qt::CursorShape cursor() const override { return Qt::CrossCursor; }
    void paint(QPainter& p) const override;

  signals:
    /// A vertex was moved or deleted: the path's new points in metres.
    void pointsEdited(const std::vector<std::pair<double, double>>& points);

  private:
    /// The vertex within a few pixels of pos, or -1.
    int vertexAt(QPointF pos) const;

    const CanvasView& m_view;
    const CanvasStyle& m_style;
    std::function<Points()> m_points;
    int m_dragVertex = -1; // the vertex being dragged, or -1
    Points m_editPoints;
};

} // namespace chaplygin::ui
