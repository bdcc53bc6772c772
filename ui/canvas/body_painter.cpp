#include "canvas/body_painter.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace chaplygin::ui {

namespace {

double param(const SystemSpec& spec, const char* name, double fallback) {
    auto it = spec.params.find(name);
    return it == spec.params.end() ? fallback : it->second;
}

// a uniform elliptical plate with semi-axes (A, A/2) has I/m = 5 A^2 / 16 about its centre
double boardSemiAxis(const DerivedSystem& d) {
    double k2 = std::max(d.b * d.b - d.a * d.a, 0.0);
    return std::max(4.0 * std::sqrt(k2) / std::sqrt(5.0), 0.1 * d.b);
}

// pen widths scale with the look (presentation mode); set by paintBody for one body
double t_lineScale = 1;

QPen cosmeticPen(const QColor& c, double width) {
    QPen pen(c, width * t_lineScale);
    pen.setCosmetic(true);
    pen.setJoinStyle(Qt::RoundJoin);
    pen.setCapStyle(Qt::RoundCap);
    return pen;
}

// centre of mass: a circle with two filled quadrants
void paintCentreOfMass(QPainter& p, QPointF c, double r, const QColor& ink) {
    p.setPen(cosmeticPen(ink, 1.2));
    p.setBrush(Qt::white);
    p.drawEllipse(c, r, r);
    p.setBrush(ink);
    QRectF box(c.x() - r, c.y() - r, 2 * r, 2 * r);
    p.drawPie(box, 0, 90 * 16);
    p.drawPie(box, 180 * 16, 90 * 16);
}

void paintSleigh(QPainter& p, const DerivedSystem& d, const QColor& fill, const QColor& ink) {
    double big = boardSemiAxis(d);
    p.setPen(cosmeticPen(ink, 1.5));
    p.setBrush(fill);
    p.drawEllipse(QPointF(d.a, 0), big, big / 2);
    if (std::abs(d.a) > big) // the knife lies outside the board: a strut reaches it
        p.drawLine(QPointF(0, 0), QPointF(d.a - std::copysign(big, d.a), 0));
    // knife edge along s-hat at P
    double knife = 0.22 * big;
    p.setPen(cosmeticPen(ink, 4));
    p.drawLine(QPointF(-knife, 0), QPointF(knife, 0));
    p.setPen(Qt::NoPen);
    p.setBrush(Qt::black);
    p.drawEllipse(QPointF(0, 0), 0.03 * big, 0.03 * big); // the contact point P
    paintCentreOfMass(p, QPointF(d.a, 0), 0.08 * big, ink);
}

void paintDisk(QPainter& p, const SystemSpec& spec, const QColor& fill, const QColor& ink) {
    // an upright disk seen from above: a thin slab of length 2R along s-hat
    double r = param(spec, "R", 0.5);
    double w = 0.12 * r;
    p.setPen(cosmeticPen(ink, 1.5));
    p.setBrush(fill);
    p.drawRoundedRect(QRectF(-r, -w, 2 * r, 2 * w), w, w);
    p.setPen(cosmeticPen(ink, 1));
    p.drawLine(QPointF(0, -2 * w), QPointF(0, 2 * w)); // the contact point P
    // heading arrow
    p.drawLine(QPointF(r, 0), QPointF(1.4 * r, 0));
    p.drawLine(QPointF(1.4 * r, 0), QPointF(1.25 * r, 0.1 * r));
    p.drawLine(QPointF(1.4 * r, 0), QPointF(1.25 * r, -0.1 * r));
    paintCentreOfMass(p, QPointF(0, 0), 0.9 * w, ink);
}

// the two wheels sit at +-a across the heading (a: half the axle, App. B)
double halfAxle(const SystemSpec& spec) {
    return std::max(param(spec, "a", 0.2), 0.0);
}

void paintCarriage(QPainter& p, const SystemSpec& spec, const QColor& fill, const QColor& ink) {
    // P is the axle's centre, which is also the centre of mass (the CM offset is 0)
    double r = param(spec, "R", 0.3);
    double half = halfAxle(spec);
    double tw = 0.22 * r; // half the wheel's width
    double side = std::max(half - 1.5 * tw, 0.35 * r);
    double front = 0.9 * r;
    QPainterPath body;
    body.moveTo(-0.5 * r, -side);
    body.lineTo(front, -0.6 * side);
    body.lineTo(front, 0.6 * side);
    body.lineTo(-0.5 * r, side);
    body.closeSubpath();
    p.setPen(cosmeticPen(ink, 1.5));
    p.setBrush(fill);
    p.drawPath(body);
    p.setPen(cosmeticPen(ink, 3));
    p.drawLine(QPointF(0, -half), QPointF(0, half)); // axle
    p.setPen(cosmeticPen(ink, 1.2));
    p.setBrush(ink);
    p.drawRect(QRectF(-r, half - tw, 2 * r, 2 * tw));
    p.drawRect(QRectF(-r, -half - tw, 2 * r, 2 * tw));
    paintCentreOfMass(p, QPointF(0, 0), 0.18 * r, ink);
}

// a fixed-size marker: the knife edge through P along s-hat and the centre of mass at its true
// offset a, drawn no further than two marker radii away
void paintMarker(QPainter& p, const DerivedSystem& d, const QColor& ink) {
    double pxPerM = std::sqrt(std::abs(p.transform().determinant()));
    if (!(pxPerM > 0) || !std::isfinite(pxPerM))
        return;
    double r = kMarkerRadiusPx * t_lineScale / pxPerM; // metres
    p.setPen(cosmeticPen(ink, 1.5));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(QPointF(0, 0), r, r);
    p.setPen(cosmeticPen(ink, 4));
    p.drawLine(QPointF(-1.3 * r, 0), QPointF(1.3 * r, 0));
    double a = std::clamp(d.a, -2 * r, 2 * r);
    if (std::abs(a) > 0.2 * r) {
        p.setPen(cosmeticPen(ink, 1.5));
        p.drawLine(QPointF(0, 0), QPointF(a, 0));
    }
    paintCentreOfMass(p, QPointF(a, 0), 0.45 * r, ink);
}

} // namespace

double bodyExtent(const SystemSpec& spec, const DerivedSystem& derived) {
    switch (spec.kind) {
    case SystemKind::Sleigh:
        return std::abs(derived.a) + boardSemiAxis(derived);
    case SystemKind::Disk:
        return 1.4 * param(spec, "R", 0.5);
    case SystemKind::Carriage:
        return std::hypot(param(spec, "R", 0.3), halfAxle(spec) + 0.22 * param(spec, "R", 0.3));
    }
    return 1;
}

QPainterPath bodyShape(const SystemSpec& spec, const DerivedSystem& derived) {
    QPainterPath shape;
    switch (spec.kind) {
    case SystemKind::Sleigh: {
        const double big = boardSemiAxis(derived);
        shape.addEllipse(QPointF(derived.a, 0), big, big / 2);
        break;
    }
    case SystemKind::Disk: {
        const double r = param(spec, "R", 0.5), w = 0.12 * r;
        shape.addRoundedRect(QRectF(-r, -w, 2 * r, 2 * w), w, w);
        break;
    }
    case SystemKind::Carriage: {
        // the body's trapezium and the two wheels, as paintCarriage draws them
        const double r = param(spec, "R", 0.3), half = halfAxle(spec), tw = 0.22 * r;
        const double side = std::max(half - 1.5 * tw, 0.35 * r), front = 0.9 * r;
        shape.moveTo(-0.5 * r, -side);
        shape.lineTo(front, -0.6 * side);
        shape.lineTo(front, 0.6 * side);
        shape.lineTo(-0.5 * r, side);
        shape.closeSubpath();
        shape.addRect(QRectF(-r, half - tw, 2 * r, 2 * tw));
        shape.addRect(QRectF(-r, -half - tw, 2 * r, 2 * tw));
        shape.setFillRule(Qt::WindingFill);
        break;
    }
    }
    return shape;
}

QRectF bodyBounds(const SystemSpec& spec, const DerivedSystem& derived, const BodyPose& pose) {
    // what paintBody draws beyond bodyShape: P, the sleigh's knife and strut, the disk's contact
    // line and heading arrow
    QPolygonF marks{QPointF(0, 0)};
    if (spec.kind == SystemKind::Sleigh) {
        const double knife = 0.22 * boardSemiAxis(derived);
        marks << QPointF(-knife, 0) << QPointF(knife, 0);
    } else if (spec.kind == SystemKind::Disk) {
        const double r = param(spec, "R", 0.5), w = 0.12 * r;
        marks << QPointF(0, -2 * w) << QPointF(0, 2 * w) << QPointF(1.4 * r, 0.1 * r)
              << QPointF(1.4 * r, -0.1 * r);
    }
    QTransform place;
    place.translate(pose.x, pose.y);
    place.rotate(pose.phi * 180.0 / M_PI);
    return place.map(bodyShape(spec, derived))
        .boundingRect()
        .united(place.map(marks).boundingRect());
}

BodyDisplay shownBodyDisplay(BodyDisplay chosen, const SystemSpec& spec,
                             const DerivedSystem& derived, const QRectF& pathBounds) {
    if (chosen != BodyDisplay::Automatic)
        return chosen;
    const double path = std::max(pathBounds.width(), pathBounds.height());
    if (!(path > 0) || !std::isfinite(path))
        return BodyDisplay::ToScale;
    const double ratio = 2 * bodyExtent(spec, derived) / path;
    return ratio <= kAutoToScale   ? BodyDisplay::ToScale
           : ratio <= kAutoOutline ? BodyDisplay::Outline
                                   : BodyDisplay::Marker;
}

void paintBody(QPainter& painter, const SystemSpec& spec, const DerivedSystem& derived,
               const BodyPose& pose, const QColor& color, bool ghost, const BodyLook& look) {
    painter.save();
    painter.translate(pose.x, pose.y);
    painter.rotate(pose.phi * 180.0 / M_PI);
    t_lineScale = std::clamp(look.lineScale, 0.5, 4.0);
    double opacity = std::clamp(look.opacity, 0.05, 1.0);
    QColor fill = color.lighter(150);
    QColor ink = color.darker(140);
    if (ghost) {
        fill.setAlphaF(opacity / 3);
        ink.setAlpha(look.lineScale > 1 ? 220 : 130);
    } else {
        fill.setAlphaF(opacity);
    }
    if (look.display == BodyDisplay::Outline)
        fill = Qt::transparent;
    if (look.display == BodyDisplay::Marker) {
        paintMarker(painter, derived, ink);
        painter.restore();
        return;
    }
    switch (spec.kind) {
    case SystemKind::Sleigh:
        paintSleigh(painter, derived, fill, ink);
        break;
    case SystemKind::Disk:
        paintDisk(painter, spec, fill, ink);
        break;
    case SystemKind::Carriage:
        paintCarriage(painter, spec, fill, ink);
        break;
    }
    painter.restore();
}

} // namespace chaplygin::ui
