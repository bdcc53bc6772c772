#include "canvas/draw_tool.h"

#include "canvas/canvas_style.h"
#include "canvas/canvas_view.h"

#include <QLineF>
#include <QMouseEvent>
#include <QPainter>
#include <QPolygonF>

namespace chaplygin::ui {

namespace {

constexpr double kStrokeSpacingPx = 10; // drawn points closer than this are dropped

} // namespace

DrawTool::DrawTool(const CanvasView& view, const CanvasStyle& style, QObject* parent)
    : CanvasTool(parent), m_view(view), m_style(style) {}

bool DrawTool::press(const QMouseEvent& e) {
    if (e.button() != Qt::LeftButton)
        return false;
    m_stroke = {m_view.toWorld(e.position())};
    return true;
}

bool DrawTool::move(const QMouseEvent& e) {
    if (m_stroke.empty() || !(e.buttons() & Qt::LeftButton))
        return false;
    if (QLineF(m_view.toPixel(m_stroke.back()), e.position()).length() >= kStrokeSpacingPx) {
        m_stroke.push_back(m_view.toWorld(e.position()));
        emit changed();
    }
    return true;
}

void DrawTool::release(const QMouseEvent& e) {
    if (e.button() != Qt::LeftButton || m_stroke.empty())
        return;
    if (QLineF(m_view.toPixel(m_stroke.back()), e.position()).length() >= kStrokeSpacingPx / 2)
        m_stroke.push_back(m_view.toWorld(e.position()));
    std::vector<std::pair<double, double>> points;
    for (QPointF w : m_stroke)
        points.emplace_back(w.x(), w.y());
    m_stroke.clear();
    emit changed();
    if (points.size() >= 3)
        emit pathDrawn(points);
}

void DrawTool::paint(QPainter& p) const {
    if (m_stroke.size() < 2)
        return;
    QPolygonF line;
    for (QPointF w : m_stroke)
        line << m_view.toPixel(w);
    p.setPen(m_style.pen(QColor(40, 40, 40), 2));
    p.drawPolyline(line);
}

} // namespace chaplygin::ui
