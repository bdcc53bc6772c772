#include "canvas/edge_markers.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QPainter>
#include <QPolygonF>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace chaplygin::ui {

namespace {

constexpr double kArrowPx = 16; // the arrowhead's length, before the line scale
constexpr double kInsetPx = 3;  // the tip's distance from the area's edge
constexpr double kGapPx = 4;    // between the arrowhead and its text
constexpr int kMostShifts = 12; // steps along the edge to clear an earlier marker

bool finite(QPointF p) {
    return std::isfinite(p.x()) && std::isfinite(p.y());
}

// where the ray from c (inside r) along d leaves r
QPointF rayExit(const QRectF& r, QPointF c, QPointF d) {
    double t = std::numeric_limits<double>::infinity();
    if (d.x() > 0)
        t = std::min(t, (r.right() - c.x()) / d.x());
    if (d.x() < 0)
        t = std::min(t, (r.left() - c.x()) / d.x());
    if (d.y() > 0)
        t = std::min(t, (r.bottom() - c.y()) / d.y());
    if (d.y() < 0)
        t = std::min(t, (r.top() - c.y()) / d.y());
    return c + t * d;
}

// "12.3 m away": a tenth of a metre up to 100 m, whole metres beyond
QString distanceText(double metres) {
    return QCoreApplication::translate("EdgeMarkers", "%1 m away")
        .arg(metres, 0, 'f', metres < 100 ? 1 : 0);
}

QPolygonF arrowhead(const EdgeMarker& m, double lineScale) {
    const double length = kArrowPx * lineScale;
    const QPointF u = m.toward, n(-u.y(), u.x());
    return QPolygonF{m.tip, m.tip - length * u + 0.3 * length * n,
                     m.tip - length * u - 0.3 * length * n};
}

// whether the tip lies on the left or right edge of inner (else on the top or bottom one)
bool onSide(const EdgeMarker& m, const QRectF& inner) {
    return std::abs(m.tip.x() - inner.left()) < 0.5 || std::abs(m.tip.x() - inner.right()) < 0.5;
}

// the marker's text box and its whole box for its tip: the text beside the arrowhead along the
// edge, on the side of the edge's middle, and against the edge, so that the marker keeps to the
// edge's strip (the margin a fit leaves) and hides little of the scene
void placeText(EdgeMarker& m, const QRectF& inner, QPointF centre, const QFontMetricsF& metrics,
               double lineScale) {
    const QRectF text = metrics.boundingRect(m.text).adjusted(-3, -1, 3, 1);
    const QRectF head = arrowhead(m, lineScale).boundingRect();
    const double gap = kGapPx * lineScale;
    QRectF box(QPointF(), text.size());
    if (onSide(m, inner)) {
        box.moveLeft(m.tip.x() < centre.x() ? inner.left() : inner.right() - box.width());
        if (m.tip.y() > centre.y())
            box.moveBottom(head.top() - gap);
        else
            box.moveTop(head.bottom() + gap);
    } else {
        box.moveTop(m.tip.y() < centre.y() ? inner.top() : inner.bottom() - box.height());
        if (m.tip.x() > centre.x())
            box.moveRight(head.left() - gap);
        else
            box.moveLeft(head.right() + gap);
    }
    // within the area, where a corner would push it out
    box.moveLeft(
        std::clamp(box.left(), inner.left(), std::max(inner.left(), inner.right() - box.width())));
    box.moveTop(
        std::clamp(box.top(), inner.top(), std::max(inner.top(), inner.bottom() - box.height())));
    m.textBox = box;
    m.box = box.united(head).adjusted(-2, -2, 2, 2);
}

} // namespace

std::vector<EdgeMarker> layoutEdgeMarkers(const std::vector<ShownBody>& bodies, const QRectF& area,
                                          const QRectF& visible, const QTransform& world,
                                          const QFont& font, double lineScale) {
    std::vector<EdgeMarker> out;
    const double s = lineScale;
    const QRectF inner = area.adjusted(kInsetPx * s, kInsetPx * s, -kInsetPx * s, -kInsetPx * s);
    if (inner.width() < 4 * kArrowPx * s || inner.height() < 4 * kArrowPx * s)
        return out; // no room for a marker
    const QTransform toWorld = world.inverted();
    const QFontMetricsF metrics(font);
    const QPointF centre = area.center();
    for (const ShownBody& body : bodies) {
        const QPointF at = world.map(body.at);
        if (!finite(at) || !finite(body.at) || body.bounds.intersects(visible))
            continue;
        const QPointF d = at - centre;
        const double length = std::hypot(d.x(), d.y());
        if (!(length > 0) || !std::isfinite(length))
            continue;
        EdgeMarker m;
        m.colour = body.colour;
        m.toward = d / length;
        m.tip = rayExit(inner, centre, m.toward);
        m.worldBox = body.worldBox;
        // a marker on the left or right edge moves up or down to clear another, else sideways
        const bool upright =
            std::abs(m.tip.x() - inner.left()) < 0.5 || std::abs(m.tip.x() - inner.right()) < 0.5;
        const QPointF along = upright ? QPointF(0, m.tip.y() < centre.y() ? 1 : -1)
                                      : QPointF(m.tip.x() < centre.x() ? 1 : -1, 0);
        auto place = [&] {
            m.distance = std::hypot(body.at.x() - toWorld.map(m.tip).x(),
                                    body.at.y() - toWorld.map(m.tip).y());
            m.text = distanceText(m.distance);
            placeText(m, inner, centre, metrics, s);
        };
        place();
        for (int k = 0; k < kMostShifts; ++k) {
            auto taken = std::find_if(out.begin(), out.end(), [&](const EdgeMarker& other) {
                return other.box.intersects(m.box);
            });
            if (taken == out.end())
                break;
            const double step = upright ? taken->box.height() : taken->box.width();
            m.tip += along * (0.5 * step + 2);
            m.tip.setX(std::clamp(m.tip.x(), inner.left(), inner.right()));
            m.tip.setY(std::clamp(m.tip.y(), inner.top(), inner.bottom()));
            place();
        }
        out.push_back(m);
    }
    return out;
}

void paintEdgeMarkers(QPainter& p, const std::vector<EdgeMarker>& markers, const QFont& font,
                      double lineScale) {
    if (markers.empty())
        return;
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setFont(font);
    for (const EdgeMarker& m : markers) {
        const QColor ink = m.colour.darker(150);
        QPen pen(ink, 1.5 * lineScale);
        pen.setJoinStyle(Qt::RoundJoin);
        p.setPen(pen);
        p.setBrush(m.colour);
        p.drawPolygon(arrowhead(m, lineScale));
        p.setPen(QPen(ink, lineScale));
        p.setBrush(QColor(255, 255, 255, 230));
        p.drawRoundedRect(m.textBox, 3 * lineScale, 3 * lineScale);
        p.setPen(ink);
        p.drawText(m.textBox, Qt::AlignCenter, m.text);
    }
    p.restore();
}

void PaintedEdgeMarkers::paint(QPainter& painter, std::vector<EdgeMarker> markers,
                               const QFont& font, double lineScale) {
    m_markers = std::move(markers);
    paintEdgeMarkers(painter, m_markers, font, lineScale);
    m_painted = {};
    for (const EdgeMarker& marker : m_markers)
        m_painted += marker.box.toAlignedRect().adjusted(-2, -2, 2, 2);
}

void PaintedEdgeMarkers::clear() {
    m_markers.clear();
    m_painted = {};
}

} // namespace chaplygin::ui
