#include "canvas/measure_tool.h"

#include "canvas/canvas_style.h"
#include "canvas/canvas_view.h"
#include "canvas/curve_flattening.h"
#include "document/scene_document.h"

#include <QFontMetricsF>
#include <QLineF>
#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace chaplygin::ui {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDegrees = 180 / std::numbers::pi;

// a path or trail as drawn, up to the parameter `limit` (arc length along the path, time along a
// trail)
struct Drawn {
    MeasureTool::Body body;
    const FlatCurve* curve;
    double limit;
};

// the point of a polyline nearest a pixel: its segment i, the fraction u along it, the distance
// [px]
struct Nearest {
    int index = -1; // of the curve
    int i = 0;
    double u = 0, distance = std::numeric_limits<double>::infinity();
};

std::vector<Drawn> drawnCurves(const MeasureTool::Shown& shown) {
    if (!shown.curves)
        return {};
    constexpr double kAll = std::numeric_limits<double>::infinity();
    using B = MeasureTool::Body;
    const CanvasCurves& c = *shown.curves;
    // the path whole; the trails as far as they are drawn now
    std::vector<Drawn> out{{B::Controlled, &c.path(), kAll}, {B::Free, &c.free(), shown.time}};
    if (shown.vakonomic)
        out.push_back({B::Vakonomic, &c.vakonomic(), shown.time});
    if (shown.openLoop)
        out.push_back({B::OpenLoop, &c.openLoop(), shown.time});
    if (shown.closedLoop)
        out.push_back({B::ClosedLoop, &c.closedLoop(), shown.time});
    return out;
}

// the nearest point of polylines given by their parameters and points, each up to its limit
template <class Param, class Point>
Nearest nearestOn(int count, const Param& param, const Point& point, const QTransform& map,
                  QPointF pixel) {
    Nearest best;
    for (int k = 0; k < count; ++k) {
        const auto [n, limit] = param(k, -1);
        for (int i = 0; i + 1 < n && param(k, i).second <= limit; ++i) {
            const double p0 = param(k, i).second, p1 = param(k, i + 1).second;
            const QPointF a = map.map(point(k, i)), b = map.map(point(k, i + 1));
            const double uMax = p1 > p0 ? std::clamp((limit - p0) / (p1 - p0), 0.0, 1.0) : 1.0;
            const QPointF ab = b - a;
            const double len2 = QPointF::dotProduct(ab, ab);
            const double u =
                len2 > 0 ? std::clamp(QPointF::dotProduct(pixel - a, ab) / len2, 0.0, uMax) : 0.0;
            const double d = QLineF(a + u * ab, pixel).length();
            if (std::isfinite(d) && d < best.distance)
                best = {k, i, u, d};
        }
    }
    return best;
}

Nearest nearestDrawn(const std::vector<Drawn>& drawn, const QTransform& map, QPointF pixel) {
    return nearestOn(
        int(drawn.size()),
        [&](int k, int i) -> std::pair<int, double> {
            const FlatCurve& c = *drawn[k].curve;
            if (i < 0)
                return {int(std::min(c.param.size(), c.points.size())), drawn[k].limit};
            return {0, c.param[i]};
        },
        [&](int k, int i) { return drawn[k].curve->points[i]; }, map, pixel);
}

// the controlled body's samples (t, x, y) nearest a pixel: a bracket of its time
Nearest nearestSample(const PlotSeries& s, const QTransform& map, QPointF pixel) {
    const int n = int(std::min({s.t.size(), s.x.size(), s.y.size()}));
    return nearestOn(
        1,
        [&](int, int i) -> std::pair<int, double> {
            return i < 0 ? std::pair{n, std::numeric_limits<double>::infinity()}
                         : std::pair{0, s.t[i]};
        },
        [&](int, int i) { return QPointF(s.x[i], s.y[i]); }, map, pixel);
}

// the parts of Solution::at a body needs
MotionParts partsOf(MeasureTool::Body body) {
    using B = MeasureTool::Body;
    return {.controlled = body == B::Controlled,
            .free = body == B::Free,
            .vakonomic = body == B::Vakonomic,
            .perturbed = body == B::OpenLoop || body == B::ClosedLoop};
}

// the body's knife point P, heading, speed, turning rate and control angle in a sample
struct Pose {
    double x, y, phi, sdot, phidot, psi;
};

Pose poseOf(MeasureTool::Body body, const MotionSample& m) {
    using B = MeasureTool::Body;
    switch (body) {
    case B::Controlled:
        return {m.x, m.y, m.phi, m.control.sdot, m.control.phidot, m.control.psi};
    case B::Free:
        return {m.free.x, m.free.y, m.free.phi, m.free.sdot, m.free.phidot, m.free.psi};
    case B::Vakonomic:
        return {m.vak.x, m.vak.y, m.vak.phi, m.vak.sdot, m.vak.phidot, m.vak.psi};
    case B::OpenLoop:
        return {m.pert.x, m.pert.y, m.pert.phi, m.pert.sdot, m.pert.phidot, m.pert.psi};
    case B::ClosedLoop:
        return {m.fb.x, m.fb.y, m.fb.phi, m.fb.sdot, m.fb.phidot, m.fb.psi};
    }
    return {};
}

QString number(double v) {
    return std::isfinite(v) ? QString::number(v, 'g', 5) : QStringLiteral("\u221e");
}

QString degrees(double radians) {
    return QString::number(radians * kDegrees, 'f', 1);
}

} // namespace

double MeasureTool::Arm::length() const {
    return QLineF(from, to).length();
}

double MeasureTool::Arm::direction() const {
    return std::atan2(to.y() - from.y(), to.x() - from.x());
}

MeasureTool::MeasureTool(const CanvasView& view, const CanvasStyle& style,
                         const SceneDocument* document, std::function<Shown()> shown,
                         QObject* parent)
    : CanvasTool(parent), m_view(view), m_style(style), m_document(document),
      m_shown(std::move(shown)) {}

void MeasureTool::setEnabled(bool on) {
    m_enabled = on;
    m_dragging = false;
    clear();
}

void MeasureTool::clear() {
    m_first.reset();
    m_ruler.reset();
    m_probe.reset();
    emit changed();
}

void MeasureTool::cancel() {
    if (m_dragging)
        m_ruler.reset();
    m_dragging = false;
    emit changed();
}

double MeasureTool::snapPx() const {
    return 8 * m_style.lineScale;
}

MeasureTool::Snap MeasureTool::snap(QPointF pixel) const {
    const double radius = snapPx();
    auto near = [&](QPointF world) { return QLineF(m_view.toPixel(world), pixel).length(); };
    // the ruler's ends, for the protractor's second arm
    if (m_ruler)
        for (QPointF end : {m_ruler->to, m_ruler->from})
            if (near(end) <= radius)
                return {end, {}};
    const auto& solution = m_document->solution();
    if (!solution)
        return {m_view.toWorld(pixel), {}};
    // the bodies' knife points P now, with their headings
    const Shown shown = m_shown();
    const MotionSample m = solution->at(std::clamp(shown.time, 0.0, solution->tEnd()));
    std::vector<Body> bodies{Body::Controlled, Body::Free};
    if (shown.vakonomic)
        bodies.push_back(Body::Vakonomic);
    if (m.perturbed && shown.openLoop)
        bodies.push_back(Body::OpenLoop);
    if (m.perturbed && shown.closedLoop)
        bodies.push_back(Body::ClosedLoop);
    for (Body body : bodies) {
        const Pose pose = poseOf(body, m);
        if (std::isfinite(pose.x) && std::isfinite(pose.y) && near({pose.x, pose.y}) <= radius)
            return {{pose.x, pose.y}, pose.phi};
    }
    // the path's ends
    const Path& path = *solution->path();
    for (const PathNode& end : {path.start(), path.end()})
        if (near({end.x, end.y}) <= radius)
            return {{end.x, end.y}, {}};
    // the path and the trails as drawn
    const std::vector<Drawn> drawn = drawnCurves(shown);
    const Nearest n = nearestDrawn(drawn, m_view.transform(), pixel);
    if (n.index >= 0 && n.distance <= radius) {
        const FlatCurve& c = *drawn[std::size_t(n.index)].curve;
        const QPointF a = c.points[std::size_t(n.i)], b = c.points[std::size_t(n.i) + 1];
        return {a + n.u * (b - a), {}};
    }
    return {m_view.toWorld(pixel), {}};
}

std::optional<MeasureTool::Probe> MeasureTool::probeAt(QPointF pixel) const {
    const auto& solution = m_document->solution();
    if (!solution)
        return {};
    const Shown shown = m_shown();
    const std::vector<Drawn> drawn = drawnCurves(shown);
    const Nearest n = nearestDrawn(drawn, m_view.transform(), pixel);
    if (n.index < 0 || n.distance > 1.5 * snapPx())
        return {};
    // the nearest time by a golden-section search between the neighbouring samples (the
    // controlled body's: the path is drawn by arc length), on the distance to the exact motion
    const Drawn& c = drawn[std::size_t(n.index)];
    const double tEnd = std::min(c.limit, solution->tEnd());
    double lo = 0, hi = 0;
    if (c.body == Body::Controlled) {
        const PlotSeries& series = m_document->series();
        const Nearest sample = nearestSample(series, m_view.transform(), pixel);
        if (sample.index < 0)
            return {};
        const int last = int(series.t.size()) - 1;
        lo = series.t[std::max(sample.i - 1, 0)];
        hi = series.t[std::min(sample.i + 2, last)];
    } else {
        const int last = int(c.curve->param.size()) - 1;
        lo = c.curve->param[std::size_t(std::max(n.i - 1, 0))];
        hi = c.curve->param[std::size_t(std::min(n.i + 2, last))];
    }
    lo = std::clamp(lo, 0.0, tEnd);
    hi = std::clamp(hi, lo, tEnd);
    const QPointF target = m_view.toWorld(pixel);
    const MotionParts parts = partsOf(c.body);
    auto distance = [&](double t) {
        const Pose pose = poseOf(c.body, solution->at(t, parts));
        return std::hypot(pose.x - target.x(), pose.y - target.y());
    };
    const double g = (std::sqrt(5.0) - 1) / 2;
    double t1 = hi - g * (hi - lo), t2 = lo + g * (hi - lo);
    double d1 = distance(t1), d2 = distance(t2);
    for (int k = 0; k < 60 && hi - lo > 1e-12 * std::max(1.0, hi); ++k) {
        if (d1 <= d2) {
            hi = t2;
            t2 = t1;
            d2 = d1;
            t1 = hi - g * (hi - lo);
            d1 = distance(t1);
        } else {
            lo = t1;
            t1 = t2;
            d1 = d2;
            t2 = lo + g * (hi - lo);
            d2 = distance(t2);
        }
    }
    const double t = (lo + hi) / 2;
    const MotionSample m = solution->at(t, parts);
    const Pose pose = poseOf(c.body, m);
    Probe probe;
    probe.body = c.body;
    probe.t = t;
    probe.s = c.body == Body::Controlled ? m.s : kNaN;
    probe.x = pose.x;
    probe.y = pose.y;
    probe.phi = pose.phi;
    // the knife point moves along the heading: its path's curvature is dphi/ds
    probe.kappa = c.body == Body::Controlled ? m.kappa : pose.phidot / pose.sdot;
    probe.psi = pose.psi;
    probe.pixel = m_view.toPixel({pose.x, pose.y});
    return probe;
}

bool MeasureTool::press(const QMouseEvent& e) {
    if (!m_enabled || e.button() != Qt::LeftButton)
        return false;
    const QPointF pixel = e.position();
    // from an end of the ruler: the protractor's second arm, the first from the same vertex
    std::optional<Arm> first;
    if (m_ruler) {
        const Arm r = *m_ruler;
        if (QLineF(m_view.toPixel(r.to), pixel).length() <= snapPx())
            first = Arm{r.to, r.from, {}};
        else if (QLineF(m_view.toPixel(r.from), pixel).length() <= snapPx())
            first = Arm{r.from, r.to, {}};
    }
    const Snap start = snap(pixel);
    m_first = first;
    m_ruler = Arm{start.world, start.world, first ? std::nullopt : start.heading};
    m_probe.reset();
    m_dragging = true;
    emit changed();
    return true;
}

bool MeasureTool::move(const QMouseEvent& e) {
    if (!m_dragging)
        return false;
    m_ruler->to = snap(e.position()).world;
    emit changed();
    return true;
}

void MeasureTool::release(const QMouseEvent& e) {
    if (!m_dragging || e.button() != Qt::LeftButton)
        return;
    m_dragging = false;
    m_ruler->to = snap(e.position()).world;
    // a click clears what was measured
    if (QLineF(m_view.toPixel(m_ruler->from), m_view.toPixel(m_ruler->to)).length() < 3) {
        m_first.reset();
        m_ruler.reset();
    }
    emit changed();
}

bool MeasureTool::hover(const QMouseEvent& e) {
    if (!m_enabled || m_dragging)
        return false;
    const std::optional<Probe> before = m_probe;
    m_probe = probeAt(e.position());
    if (before.has_value() || m_probe.has_value())
        emit changed();
    return true;
}

std::optional<double> MeasureTool::protractorAngle() const {
    if (!m_first || !m_ruler)
        return {};
    return std::abs(
        std::remainder(m_ruler->direction() - m_first->direction(), 2 * std::numbers::pi));
}

std::optional<double> MeasureTool::headingAngle() const {
    if (!m_ruler || !m_ruler->heading)
        return {};
    return std::remainder(m_ruler->direction() - *m_ruler->heading, 2 * std::numbers::pi);
}

QStringList MeasureTool::rulerText() const {
    if (!m_ruler)
        return {};
    QStringList lines;
    // the protractor's first arm, then the ruler (its second arm)
    for (const auto& arm : {m_first, m_ruler})
        if (arm)
            lines << tr("%1 m at %2°").arg(number(arm->length()), degrees(arm->direction()));
    if (const auto angle = protractorAngle())
        lines << tr("angle %1°").arg(degrees(*angle));
    if (const auto angle = headingAngle())
        lines << tr("%1° from the heading").arg(degrees(*angle));
    return lines;
}

QStringList MeasureTool::probeText() const {
    if (!m_probe)
        return {};
    const Probe& p = *m_probe;
    QString title;
    switch (p.body) {
    case Body::Controlled:
        title = tr("Path (controlled body)");
        break;
    case Body::Free:
        title = tr("Free body's trail");
        break;
    case Body::Vakonomic:
        title = tr("Vakonomic body's trail");
        break;
    case Body::OpenLoop:
        title = tr("Open-loop body's trail");
        break;
    case Body::ClosedLoop:
        title = tr("Feedback body's trail");
        break;
    }
    QStringList lines{title, tr("t = %1 s").arg(number(p.t))};
    if (std::isfinite(p.s))
        lines << tr("s = %1 m").arg(number(p.s));
    lines << tr("x = %1 m, y = %2 m").arg(number(p.x), number(p.y))
          << tr("φ = %1 rad (%2°)").arg(number(p.phi), degrees(p.phi))
          << tr("κ = %1 1/m, ρ = %2 m").arg(number(p.kappa), number(1 / p.kappa))
          << tr("Ψ = %1 rad (%2°)").arg(number(p.psi), degrees(p.psi));
    return lines;
}

void MeasureTool::paintLabel(QPainter& p, QPointF at, double gap, const QStringList& lines,
                             bool awayFromMiddle) const {
    const QFontMetricsF metrics(p.font());
    double w = 0;
    for (const QString& line : lines)
        w = std::max(w, metrics.horizontalAdvance(line));
    const double pad = 4 * m_style.lineScale;
    QRectF box(at, QSizeF(w + 2 * pad, lines.size() * metrics.lineSpacing() + 2 * pad));
    const QRectF room = m_shown().area;
    // away from the middle, where the ruler's read-out usually is
    if (awayFromMiddle) {
        if (at.x() < room.center().x())
            box.moveRight(at.x() - 2 * gap);
        if (at.y() < room.center().y())
            box.moveBottom(at.y() - 2 * gap);
    }
    // kept inside the drawing area where it fits
    box.moveLeft(std::max(std::min(box.left(), room.right() - box.width()), room.left()));
    box.moveTop(std::max(std::min(box.top(), room.bottom() - box.height()), room.top()));
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(255, 255, 255, 225));
    p.drawRect(box);
    p.setPen(Qt::black);
    QPointF line = box.topLeft() + QPointF(pad, pad + metrics.ascent());
    for (const QString& text : lines) {
        p.drawText(line, text);
        line.ry() += metrics.lineSpacing();
    }
}

void MeasureTool::paint(QPainter& p) const {
    if (!m_enabled)
        return;
    p.save();
    p.setClipRect(m_shown().area);
    p.setRenderHint(QPainter::Antialiasing);
    // the read-outs in the canvas's font, scaled as its lines
    QFont font = p.font();
    font.setPointSizeF(font.pointSizeF() * m_style.lineScale);
    p.setFont(font);
    const QColor ink(20, 20, 20);
    const double ls = m_style.lineScale;
    auto drawArm = [&](const Arm& arm) {
        const QPointF a = m_view.toPixel(arm.from), b = m_view.toPixel(arm.to);
        p.setPen(m_style.pen(QColor(255, 255, 255, 200), 5));
        p.drawLine(a, b);
        p.setPen(m_style.pen(ink, 2));
        p.drawLine(a, b);
        p.setBrush(Qt::white);
        for (QPointF end : {a, b})
            p.drawEllipse(end, 3.5 * ls, 3.5 * ls);
    };
    // an arc at a vertex [px] from one direction to another [rad, world: counter-clockwise]
    auto drawArc = [&](QPointF vertex, double from, double sweep, double radius) {
        p.setBrush(Qt::NoBrush);
        p.setPen(m_style.pen(ink, 1.5));
        const QRectF box(vertex - QPointF(radius, radius), QSizeF(2 * radius, 2 * radius));
        // on the screen y points down, and QPainter's angles run counter-clockwise on it
        p.drawArc(box, int(std::lround(from * kDegrees * 16)),
                  int(std::lround(sweep * kDegrees * 16)));
    };
    if (m_first)
        drawArm(*m_first);
    if (m_ruler) {
        drawArm(*m_ruler);
        const QPointF vertex = m_view.toPixel(m_ruler->from);
        if (m_first)
            drawArc(
                vertex, m_first->direction(),
                std::remainder(m_ruler->direction() - m_first->direction(), 2 * std::numbers::pi),
                28 * ls);
        if (m_ruler->heading) {
            // the heading: a dashed ray from the body, as long as the ruler on the screen
            const double h = *m_ruler->heading;
            const double reach =
                std::max(QLineF(vertex, m_view.toPixel(m_ruler->to)).length(), 40 * ls);
            p.setPen(m_style.pen(ink, 1.5, Qt::DashLine));
            p.drawLine(vertex, vertex + reach * QPointF(std::cos(h), -std::sin(h)));
            drawArc(vertex, h, std::remainder(m_ruler->direction() - h, 2 * std::numbers::pi),
                    22 * ls);
        }
        paintLabel(p, m_view.toPixel(m_ruler->to) + QPointF(10, 6) * ls, 10 * ls, rulerText(),
                   false);
    }
    if (m_probe) {
        p.setPen(m_style.pen(ink, 2));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(m_probe->pixel, 6 * ls, 6 * ls);
        paintLabel(p, m_probe->pixel + QPointF(12, 12) * ls, 12 * ls, probeText(), true);
    }
    p.restore();
}

} // namespace chaplygin::ui
