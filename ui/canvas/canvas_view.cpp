#include "canvas/canvas_view.h"

#include <QWidget>

#include <algorithm>
#include <cmath>

namespace chaplygin::ui {

QTransform CanvasView::transformAt(QPointF centre) const {
    QTransform t;
    t.translate(m_widget->width() / 2.0, m_widget->height() / 2.0);
    t.scale(m_scale, -m_scale);
    t.translate(-centre.x(), -centre.y());
    return t;
}

void CanvasView::frame(const QRectF& box, const QRectF& area, double margin, double minScale,
                       double maxScale) {
    const double w = std::max(area.width(), 100.0), h = std::max(area.height(), 100.0);
    const double room = std::min(w, h) * 0.4; // a margin never takes more than this
    const double ww = w - 2 * std::min(margin, room), hh = h - 2 * std::min(margin, room);
    const double fit =
        std::min(ww / std::max(box.width(), 1e-9), hh / std::max(box.height(), 1e-9));
    // a view far from the origin (a path at 1e308 m) keeps scale times its centre finite
    const double far = std::max({std::abs(box.center().x()), std::abs(box.center().y()), 1.0});
    m_scale = std::clamp(std::min({std::max(fit, minScale), maxScale, 1e300 / far}), kMinScale,
                         kMaxScale);
    m_centre = box.center() + QPointF(0, (area.center().y() - m_widget->height() / 2.0) / m_scale);
    m_autoFit = true;
}

void CanvasView::zoomBy(double factor) {
    m_autoFit = false;
    m_scale = std::clamp(m_scale * factor, kMinScale, kMaxScale);
}

void CanvasView::zoomAbout(QPointF pixel, double factor) {
    const QPointF before = toWorld(pixel);
    zoomBy(factor);
    m_centre += before - toWorld(pixel);
}

void CanvasView::panBy(QPointF pixels) {
    m_centre -= QPointF(pixels.x() / m_scale, -pixels.y() / m_scale);
    m_autoFit = false;
}

void CanvasView::moveCentre(QPointF metres) {
    m_centre += metres;
    m_autoFit = false;
}

void CanvasView::centreOn(QPointF world) {
    m_centre = QPointF(std::round(world.x() * m_scale) / m_scale,
                       std::round(world.y() * m_scale) / m_scale);
}

double CanvasView::gridStep() const {
    double decade = std::pow(10.0, std::floor(std::log10(40.0 / m_scale)));
    double step = decade;
    for (double f : {1.0, 2.0, 5.0, 10.0})
        if (f * decade * m_scale >= 40) {
            step = f * decade;
            break;
        }
    return step;
}

bool CanvasView::setFollows(bool on) {
    if (on == m_follow)
        return false;
    m_follow = on;
    if (m_follow) {
        m_beforeFollow = {m_scale, m_centre, m_autoFit};
        m_autoFit = false;
    }
    return true;
}

void CanvasView::setFollowScale(double readable) {
    if (!m_follow || !std::isfinite(readable) || !(readable > 0))
        return;
    m_readable = std::max(readable, m_beforeFollow.scale);
    m_scale = std::clamp(m_readable * m_followZoom, kMinScale, kMaxScale);
}

void CanvasView::zoomFollow(double factor) {
    if (!std::isfinite(factor) || !(factor > 0))
        return;
    m_scale = std::clamp(m_scale * factor, kMinScale, kMaxScale);
    if (m_follow && m_readable > 0)
        m_followZoom = m_scale / m_readable;
}

bool CanvasView::returnFromFollow() {
    if (!m_follow)
        return false;
    m_follow = false;
    m_scale = m_beforeFollow.scale;
    m_centre = m_beforeFollow.centre;
    m_autoFit = m_beforeFollow.autoFit;
    return true;
}

} // namespace chaplygin::ui
