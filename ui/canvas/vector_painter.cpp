#include "canvas/vector_painter.h"

#include <QCoreApplication>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace chaplygin::ui {

namespace {

constexpr double kHeadPx = 9;       // arrowhead length
constexpr double kMinArrowPx = 1.5; // shorter arrows are not drawn
constexpr double kMaxSpanDeg = 340; // the couple's arc never closes
constexpr double kDeg = 180 / std::numbers::pi;

QPen pen(const QColor& c, double width, bool ghost) {
    QPen p(c, width, ghost ? Qt::DashLine : Qt::SolidLine);
    p.setCosmetic(true);
    p.setCapStyle(Qt::RoundCap);
    p.setJoinStyle(Qt::RoundJoin);
    return p;
}

QColor inkOf(VectorKind kind, bool ghost) {
    QColor c = vectorColor(kind);
    if (ghost)
        c.setAlpha(120);
    return c;
}

// the arrowhead's triangle at tip along direction; empty for no direction
QPolygonF headTriangle(QPointF tip, QPointF direction, double headPx) {
    double len = std::hypot(direction.x(), direction.y());
    if (!(len > 0))
        return {};
    QPointF u = direction / len, n(-u.y(), u.x());
    return QPolygonF{tip, tip - headPx * u + 0.45 * headPx * n,
                     tip - headPx * u - 0.45 * headPx * n};
}

void arrowHead(QPainter& p, QPointF tip, QPointF direction, const QColor& c, double headPx) {
    const QPolygonF head = headTriangle(tip, direction, headPx);
    if (head.isEmpty())
        return;
    p.setBrush(c);
    p.setPen(Qt::NoPen);
    p.drawPolygon(head);
}

} // namespace

VectorToggle VectorOverlay::*vectorToggle(VectorKind kind) {
    switch (kind) {
    case VectorKind::KnifeVelocity:
        return &VectorOverlay::knifeVelocity;
    case VectorKind::AxialForce:
        return &VectorOverlay::axialForce;
    case VectorKind::LateralReaction:
        return &VectorOverlay::lateralReaction;
    case VectorKind::ControlCouple:
        return &VectorOverlay::controlCouple;
    case VectorKind::CmVelocity:
        return &VectorOverlay::cmVelocity;
    }
    return &VectorOverlay::knifeVelocity;
}

QString vectorName(VectorKind kind) {
    switch (kind) {
    case VectorKind::KnifeVelocity:
        return QCoreApplication::translate("VectorPainter", "Knife point velocity v_P");
    case VectorKind::AxialForce:
        return QCoreApplication::translate("VectorPainter", "Control force along the axis f_s");
    case VectorKind::LateralReaction:
        return QCoreApplication::translate("VectorPainter", "Knife's lateral reaction N (at P)");
    case VectorKind::ControlCouple:
        return QCoreApplication::translate("VectorPainter", "Control couple \u03c4");
    case VectorKind::CmVelocity:
        return QCoreApplication::translate("VectorPainter", "Centre of mass velocity v_C");
    }
    return {};
}

QString vectorSymbol(VectorKind kind) {
    switch (kind) {
    case VectorKind::KnifeVelocity:
        return QStringLiteral("v_P");
    case VectorKind::AxialForce:
        return QStringLiteral("f_s");
    case VectorKind::LateralReaction:
        return QStringLiteral("N");
    case VectorKind::ControlCouple:
        return QStringLiteral("\u03c4");
    case VectorKind::CmVelocity:
        return QStringLiteral("v_C");
    }
    return {};
}

QString vectorUnit(VectorKind kind) {
    switch (kind) {
    case VectorKind::KnifeVelocity:
    case VectorKind::CmVelocity:
        return QStringLiteral("m/s");
    case VectorKind::AxialForce:
    case VectorKind::LateralReaction:
        return QStringLiteral("N");
    case VectorKind::ControlCouple:
        return QStringLiteral("N m");
    }
    return {};
}

QColor vectorColor(VectorKind kind) {
    switch (kind) {
    case VectorKind::KnifeVelocity:
        return {0, 120, 60};
    case VectorKind::AxialForce:
        return {215, 95, 0};
    case VectorKind::LateralReaction:
        return {185, 0, 135};
    case VectorKind::ControlCouple:
        return {140, 100, 0};
    case VectorKind::CmVelocity:
        return {0, 130, 160};
    }
    return Qt::black;
}

double roundValue(double target) {
    if (!(target > 0) || !std::isfinite(target))
        return 1;
    double decade = std::pow(10.0, std::floor(std::log10(target)));
    double best = decade;
    for (double f : {1.0, 2.0, 5.0, 10.0})
        if (std::fabs(std::log(f * decade / target)) < std::fabs(std::log(best / target)))
            best = f * decade;
    return best;
}

VectorShapes vectorShapes(const DerivedSystem& system, const BodyState& body,
                          const VectorOverlay& overlay, const VectorScales& scales,
                          const QTransform& world, double coupleRadius, bool ghost) {
    VectorShapes out;
    const BodyVectors v = bodyVectors(system, body);
    auto arrow = [&](VectorKind kind, const AttachedVector& a) {
        if (!(overlay.*vectorToggle(kind)).shown || body.pivot)
            return; // a pivoting body shows the couple alone
        double k = scales[std::size_t(kind)];
        QPointF tail = world.map(QPointF(a.x, a.y));
        QPointF head = world.map(QPointF(a.x + k * a.vx, a.y + k * a.vy));
        out.arrows.push_back({kind, tail, head, std::hypot(a.vx, a.vy), ghost});
    };
    arrow(VectorKind::KnifeVelocity, v.knifeVelocity);
    arrow(VectorKind::CmVelocity, v.cmVelocity);
    arrow(VectorKind::AxialForce, v.axialForce);
    arrow(VectorKind::LateralReaction, v.lateralReaction);
    if (overlay.controlCouple.shown) {
        CoupleShape c;
        c.centre = world.map(QPointF(v.cx, v.cy));
        QPointF rim = world.map(QPointF(v.cx + coupleRadius, v.cy));
        c.radius = std::hypot(rim.x() - c.centre.x(), rim.y() - c.centre.y());
        // the arc starts behind the body (opposite to s-hat) and turns with the sign of tau
        QPointF ahead = world.map(QPointF(v.cx + std::cos(body.phi), v.cy + std::sin(body.phi)));
        double heading = std::atan2(-(ahead.y() - c.centre.y()), ahead.x() - c.centre.x()) * kDeg;
        c.startDeg = heading + 180;
        double span = body.controlCouple * scales[std::size_t(VectorKind::ControlCouple)] * kDeg;
        c.spanDeg = std::clamp(span, -kMaxSpanDeg, kMaxSpanDeg);
        c.value = body.controlCouple;
        c.pivot = body.pivot;
        c.ghost = ghost;
        out.couples.push_back(c);
    }
    return out;
}

namespace {

// "v_P: 2 m/s", "τ: 0.1 N m = 103°": a scale bar's words
QString scaleBarText(VectorKind kind, double k, double pixelsPerMetre, double barPx) {
    if (kind == VectorKind::ControlCouple) {
        double value = roundValue((std::numbers::pi / 2) / k);
        double span = std::min(value * k * kDeg, kMaxSpanDeg);
        return vectorSymbol(kind) + QStringLiteral(": %1 %2 = %3\u00b0")
                                        .arg(value)
                                        .arg(vectorUnit(kind))
                                        .arg(span, 0, 'f', 0);
    }
    double value = roundValue(barPx / (k * pixelsPerMetre));
    return vectorSymbol(kind) + QStringLiteral(": %1 %2").arg(value).arg(vectorUnit(kind));
}

// text beyond the arrowhead's tip along its direction u, its box wholly ahead of the tip, unless
// an earlier label or an arrowhead holds that place: then the first free place of rings around
// it (a label's height apart), within the margin VectorLayer::bounds allows
void placeLabel(QPainter& p, QPointF tip, QPointF u, const QString& text,
                std::vector<QRectF>& placed, const std::vector<QPolygonF>& heads, double gap) {
    const QFontMetricsF metrics(p.font());
    const QRectF glyphs = metrics.boundingRect(text).adjusted(-1, -1, 1, 1); // from the baseline
    const double length = std::hypot(u.x(), u.y());
    u = length > 0 ? u / length : QPointF(1, 0);
    // the box's half extent along u: its nearest side is gap beyond the tip
    const double half =
        0.5 * (std::abs(u.x()) * glyphs.width() + std::abs(u.y()) * glyphs.height());
    const QPointF natural = tip + u * (gap + half) - glyphs.center();
    const QRectF box = glyphs.translated(natural);
    const double step = metrics.height();
    auto free = [&](const QRectF& at) {
        const QPolygonF corners(at);
        return std::none_of(placed.begin(), placed.end(),
                            [&](const QRectF& r) { return r.intersects(at); }) &&
               std::none_of(heads.begin(), heads.end(),
                            [&](const QPolygonF& h) { return corners.intersects(h); });
    };
    QPointF best;
    for (int ring = 0; ring <= 2; ++ring) {
        bool found = false;
        const int tries = ring == 0 ? 1 : 8;
        for (int k = 0; k < tries && !found; ++k) {
            const double angle = k * std::numbers::pi / 4;
            const QPointF shift = ring * step * QPointF(std::cos(angle), std::sin(angle));
            found = free(box.translated(shift));
            if (found)
                best = shift;
        }
        if (found)
            break;
    }
    placed.push_back(box.translated(best));
    p.drawText(natural + best, text);
}

} // namespace

int scaleBarsTextWidth(const QFont& font, const VectorOverlay& overlay, const VectorScales& scales,
                       double pixelsPerMetre, double barPx) {
    const QFontMetrics metrics(font);
    int widest = int(std::lround(104 * barPx / kBarPx));
    for (int i = 0; i < kVectorKinds; ++i) {
        auto kind = VectorKind(i);
        if ((overlay.*vectorToggle(kind)).shown)
            widest = std::max(widest, metrics.horizontalAdvance(scaleBarText(
                                          kind, scales[std::size_t(i)], pixelsPerMetre, barPx)) +
                                          4);
    }
    return widest;
}

void paintVectorShapes(QPainter& p, const VectorShapes& shapes, bool labels,
                       std::vector<QRectF>* placed, double lineScale) {
    std::vector<QRectF> own;
    std::vector<QRectF>& taken = placed ? *placed : own;
    const double s = lineScale, headPx = kHeadPx * s;
    // every arrowhead, which no label may cover
    std::vector<QPolygonF> heads;
    for (const CoupleShape& c : shapes.couples) {
        const double end = (c.startDeg + c.spanDeg) * std::numbers::pi / 180;
        const QPointF tip = c.centre + c.radius * QPointF(std::cos(end), -std::sin(end));
        const QPointF tangent = (c.spanDeg > 0 ? 1 : -1) * QPointF(-std::sin(end), -std::cos(end));
        heads.push_back(headTriangle(tip + 0.5 * headPx * tangent, tangent, headPx));
    }
    for (const ArrowShape& a : shapes.arrows)
        if (std::hypot(a.head.x() - a.tail.x(), a.head.y() - a.tail.y()) >= kMinArrowPx)
            heads.push_back(headTriangle(a.head, a.head - a.tail, headPx));
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    QFont f = p.font();
    f.setPointSizeF(9 * s);
    f.setBold(true);
    p.setFont(f);
    for (const CoupleShape& c : shapes.couples) {
        QColor ink = inkOf(VectorKind::ControlCouple, c.ghost);
        QRectF box(c.centre.x() - c.radius, c.centre.y() - c.radius, 2 * c.radius, 2 * c.radius);
        if (std::fabs(c.spanDeg) * std::numbers::pi / 180 * c.radius < kMinArrowPx) {
            if (c.pivot && labels) {
                // tau = 0 while the body turns in place; the control acts in impulses at the
                // start and the end of the turn (docs/physics.md §3)
                p.setPen(pen(ink, s, true));
                p.setBrush(Qt::NoBrush);
                p.drawEllipse(box);
                p.setPen(ink);
                p.drawText(
                    QRectF(c.centre.x() - 150 * s, c.centre.y() + c.radius + 2, 300 * s, 18 * s),
                    Qt::AlignHCenter | Qt::AlignTop,
                    QCoreApplication::translate("VectorPainter",
                                                "\u03c4 = 0 while turning in place"));
            }
            continue;
        }
        p.setPen(pen(ink, 2.5 * s, c.ghost));
        p.setBrush(Qt::NoBrush);
        p.drawArc(box, int(std::lround(c.startDeg * 16)), int(std::lround(c.spanDeg * 16)));
        double end = (c.startDeg + c.spanDeg) * std::numbers::pi / 180;
        QPointF tip = c.centre + c.radius * QPointF(std::cos(end), -std::sin(end));
        double sign = c.spanDeg > 0 ? 1 : -1;
        QPointF tangent = sign * QPointF(-std::sin(end), -std::cos(end));
        arrowHead(p, tip + 0.5 * headPx * tangent, tangent, ink, headPx);
        if (labels) {
            p.setPen(ink);
            placeLabel(p, tip + 0.5 * headPx * tangent, tangent,
                       vectorSymbol(VectorKind::ControlCouple), taken, heads, 4 * s);
        }
    }
    for (const ArrowShape& a : shapes.arrows) {
        QPointF d = a.head - a.tail;
        double len = std::hypot(d.x(), d.y());
        if (len < kMinArrowPx)
            continue;
        QColor ink = inkOf(a.kind, a.ghost);
        p.setPen(pen(ink, 2.5 * s, a.ghost));
        // the shaft stops where the head begins, so the tip stays sharp
        QPointF shaftEnd = len > headPx ? a.head - d * (headPx * 0.8 / len) : a.tail;
        p.drawLine(a.tail, shaftEnd);
        arrowHead(p, a.head, d, ink, headPx);
        if (labels) {
            p.setPen(ink);
            placeLabel(p, a.head, d, vectorSymbol(a.kind), taken, heads, 4 * s);
        }
    }
    p.restore();
}

void paintScaleBars(QPainter& p, const VectorOverlay& overlay, const VectorScales& scales,
                    double pixelsPerMetre, QPointF bottomRight, double lineScale, double barPx) {
    const double s = lineScale;
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    QFont f = p.font();
    f.setPointSizeF(8.5 * s);
    p.setFont(f);
    // the texts in one column as wide as the widest; the bars left of it
    const double textWidth = scaleBarsTextWidth(f, overlay, scales, pixelsPerMetre, barPx);
    QPointF row = bottomRight;
    for (int i = kVectorKinds - 1; i >= 0; --i) {
        auto kind = VectorKind(i);
        if (!(overlay.*vectorToggle(kind)).shown)
            continue;
        double k = scales[std::size_t(i)];
        QColor ink = vectorColor(kind);
        p.setPen(pen(ink, 2.5 * s, false));
        p.setBrush(Qt::NoBrush);
        if (kind == VectorKind::ControlCouple) {
            // an arc of radius 9 px: a round couple turning it by about a quarter
            double value = roundValue((std::numbers::pi / 2) / k);
            double span = std::min(value * k * kDeg, kMaxSpanDeg);
            QPointF c = row + QPointF(-textWidth - 46 * s, -5 * s);
            p.drawArc(QRectF(c.x() - 9 * s, c.y() - 9 * s, 18 * s, 18 * s), 180 * 16,
                      int(-span * 16));
        } else {
            double value = roundValue(barPx / (k * pixelsPerMetre));
            double len = value * k * pixelsPerMetre;
            QPointF right = row + QPointF(-textWidth - 6 * s, -5 * s),
                    left = right - QPointF(len, 0);
            p.drawLine(left, right);
            p.drawLine(left + s * QPointF(0, -3), left + s * QPointF(0, 3));
            p.drawLine(right + s * QPointF(0, -3), right + s * QPointF(0, 3));
        }
        p.setPen(Qt::black);
        p.drawText(QRectF(row.x() - textWidth, row.y() - 14 * s, textWidth, 16 * s),
                   Qt::AlignLeft | Qt::AlignVCenter, scaleBarText(kind, k, pixelsPerMetre, barPx));
        row -= QPointF(0, 18 * s);
    }
    p.restore();
}

} // namespace chaplygin::ui
