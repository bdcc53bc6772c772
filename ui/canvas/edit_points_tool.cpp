#include "canvas/edit_points_tool.h"

#include "canvas/canvas_style.h"
#include "canvas/canvas_view.h"

#include <QLineF>
#include <QMouseEvent>
#include <QPainter>
#include <QPolygonF>

namespace chaplygin::ui {

namespace {

constexpr double kVertexPickPx = 8; // how near a click must be to grab a vertex

} // namespace

EditPointsTool::EditPointsTool(const CanvasView& view, const CanvasStyle& style,
                               std::function<Points()> points, QObject* parent)
    : CanvasTool(parent), m_view(view), m_style(style), m_points(std::move(points)) {}

int EditPointsTool::vertexAt(QPointF pos) const {
    const Points points = m_points();
    int best = -1;
    double bestDistance = kVertexPickPx;
    for (std::size_t i = 0; i < points.size(); ++i) {
        double d = QLineF(m_view.toPixel({points[i].first, points[i].second}), pos).length();
        if (d <= bestDistance) {
            bestDistance = d;
            best = int(i);
        }
    }
    return best;
}

bool EditPointsTool::press(const QMouseEvent& e) {
    const int vertex = vertexAt(e.position());
    if (vertex < 0)
        return false;
    if (e.button() == Qt::LeftButton) {
        m_dragVertex = vertex;
        m_editPoints = m_points();
        return true;
    }
    if (e.button() == Qt::RightButton) {
        Points points = m_points();
        if (points.size() > 2) {
            points.erase(points.begin() + vertex);
            emit pointsEdited(points);
        }
        return true;
    }
    return false;
}

bool EditPointsTool::move(const QMouseEvent& e) {
    if (m_dragVertex < 0)
        return false;
    const QPointF w = m_view.toWorld(e.position());
    m_editPoints[std::size_t(m_dragVertex)] = {w.x(), w.y()};
    emit changed();
    return true;
}

void EditPointsTool::release(const QMouseEvent& e) {
    if (m_dragVertex < 0 || e.button() != Qt::LeftButton)
        return;
    const QPointF w = m_view.toWorld(e.position());
    m_editPoints[std::size_t(m_dragVertex)] = {w.x(), w.y()};
    m_dragVertex = -1;
    emit changed();
    emit pointsEdited(m_editPoints);
}

void EditPointsTool::paint(QPainter& p) const {
    const Points points = m_dragVertex >= 0 ? m_editPoints : m_points();
    if (m_dragVertex >= 0) {
        QPolygonF line;
        for (const auto& [x, y] : points)
            line << m_view.toPixel({x, y});
        p.setPen(m_style.pen(QColor(60, 60, 60), 1, Qt::DashLine));
        p.drawPolyline(line);
    }
    p.setPen(m_style.pen(QColor(60, 60, 60), 1));
    p.setBrush(QColor(255, 255, 255, 220));
    for (const auto& [x, y] : points) {
        const QPointF c = m_view.toPixel({x, y});
        p.drawRect(QRectF(c.x() - 3, c.y() - 3, 6, 6));
    }
}

} // namespace chaplygin::ui
