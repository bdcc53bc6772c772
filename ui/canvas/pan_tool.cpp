#include "canvas/pan_tool.h"

#include "canvas/canvas_view.h"

#include <QMouseEvent>

namespace chaplygin::ui {

PanTool::PanTool(CanvasView& view, QObject* parent) : CanvasTool(parent), m_view(view) {}

bool PanTool::press(const QMouseEvent& e) {
    m_panning = true;
    m_last = e.position();
    return true;
}

bool PanTool::move(const QMouseEvent& e) {
    if (!m_panning)
        return false;
    m_view.panBy(e.position() - m_last);
    m_last = e.position();
    emit panned();
    return true;
}

void PanTool::release(const QMouseEvent&) {
    m_panning = false;
}

} // namespace chaplygin::ui
