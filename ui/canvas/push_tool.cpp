#include "canvas/push_tool.h"

#include "canvas/canvas_style.h"
#include "canvas/canvas_view.h"

#include <QLineF>
#include <QMouseEvent>
#include <QPainter>

#include <cmath>

namespace chaplygin::ui {

PushTool::PushTool(const CanvasView& view, const CanvasStyle& style,
                   std::function<Grab(QPointF)> grab, QObject* parent)
    : CanvasTool(parent), m_view(view), m_style(style), m_grab(std::move(grab)) {}

bool PushTool::press(const QMouseEvent& e) {
    if (e.button() != Qt::LeftButton)
        return false;
    const Grab grab = m_grab(e.position());
    if (!grab.onBody)
        return false;
    m_pushing = true;
    m_grabbed = grab;
    m_from = m_view.toWorld(e.position());
    m_to = e.position();
    return true;
}

bool PushTool::move(const QMouseEvent& e) {
    if (!m_pushing)
        return false;
    m_to = e.position();
    emit changed();
    return true;
}

void PushTool::release(const QMouseEvent& e) {
    if (!m_pushing || e.button() != Qt::LeftButton)
        return;
    m_pushing = false;
    // the drag's component along the heading's left normal [m]
    const QPointF d = m_view.toWorld(e.position()) - m_from;
    const double left = -d.x() * std::sin(m_grabbed.phi) + d.y() * std::cos(m_grabbed.phi);
    if (QLineF(m_view.toPixel(m_from), e.position()).length() >= 3)
        emit pushDragged(m_grabbed.t, left);
    emit changed();
}

void PushTool::paint(QPainter& p) const {
    if (!m_pushing)
        return;
    // the push being dragged: a line from where the body was grabbed
    p.setPen(m_style.pen(m_style.closedLoop().darker(140), 2, Qt::DashLine));
    p.drawLine(m_view.toPixel(m_from), m_to);
}

} // namespace chaplygin::ui
