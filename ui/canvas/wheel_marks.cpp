#include "canvas/wheel_marks.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace chaplygin::ui {

namespace {

constexpr double kPi = std::numbers::pi;

double param(const SystemSpec& spec, const char* name) {
    const auto it = spec.params.find(name);
    return it != spec.params.end() ? it->second : defaultSystemParams(spec.kind).at(name);
}

QString insetTitle() {
    return QCoreApplication::translate("WheelInset", "Side view, ahead \u2192");
}

QPen cosmeticPen(const QColor& c, double width) {
    QPen pen(c, width);
    pen.setCosmetic(true);
    pen.setCapStyle(Qt::FlatCap);
    return pen;
}

// the stripes across one wheel's tread, from y0 to y1 across the heading [m]
void paintStripes(QPainter& p, double theta, double radius, double y0, double y1,
                  const QColor& stripe, double lineScale) {
    for (const TreadStripe& s : treadStripes(theta, radius)) {
        p.setPen(s.marked ? cosmeticPen(rollMarkColour(), 3 * lineScale)
                          : cosmeticPen(stripe, 1.3 * lineScale));
        p.drawLine(QPointF(s.along, y0), QPointF(s.along, y1));
    }
}

} // namespace

std::vector<TreadStripe> treadStripes(double theta, double radius) {
    std::vector<TreadStripe> out;
    if (!std::isfinite(theta))
        return out;
    for (int k = 0; k < kTreadStripes; ++k) {
        const double alpha = theta + 2 * kPi * k / kTreadStripes;
        if (std::cos(alpha) < 0) // the upper half, seen from above
            out.push_back({-radius * std::sin(alpha), k == 0});
    }
    return out;
}

QColor rollMarkColour() {
    return {235, 110, 0};
}

void paintTreadStripes(QPainter& painter, const SystemSpec& spec, const WheelAngles& angles,
                       const QColor& ink, double lineScale) {
    if (angles.wheels == 0)
        return;
    const double r = param(spec, "R");
    const double pxPerM = std::sqrt(std::abs(painter.transform().determinant()));
    if (!(2 * r * pxPerM >= 8))
        return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    if (spec.kind == SystemKind::Disk) {
        // the slab paintBody draws, 0.12 R to each side; stripes in the ink on its light fill
        const double w = 0.12 * r;
        paintStripes(painter, angles.theta1, r, -w, w, ink, lineScale);
    } else {
        // the wheels paintBody fills with the ink: light stripes; wheel 1 at -a, wheel 2 at +a
        const double half = std::max(param(spec, "a"), 0.0), tw = 0.22 * r;
        const QColor light(255, 255, 255, 230);
        paintStripes(painter, angles.theta1, r, -half - tw, -half + tw, light, lineScale);
        paintStripes(painter, angles.theta2, r, half - tw, half + tw, light, lineScale);
    }
    painter.restore();
}

WheelInsetLayout wheelInsetLayout(int wheels, double lineScale, const QFont& font) {
    WheelInsetLayout out;
    if (wheels <= 0)
        return out;
    const QFontMetricsF metrics(font);
    const double pad = 8 * lineScale;
    out.radius = 26 * lineScale;
    // the widest label a wheel can have: its angle at six digits
    WheelAngles wide{wheels, -9999.99, -9999.99};
    double labelWidth = 0;
    for (int k = 0; k < wheels; ++k)
        labelWidth = std::max(labelWidth, metrics.horizontalAdvance(wheelLabel(wide, k)));
    const double cell = std::max(2 * out.radius + 2 * pad, labelWidth + pad);
    const double title = metrics.height();
    const double top = pad + title + pad;
    for (int k = 0; k < wheels; ++k) {
        const double cx = pad / 2 + cell * (k + 0.5);
        out.centres.push_back({cx, top + out.radius});
        out.labels.push_back(
            QRectF(pad / 2 + cell * k, top + 2 * out.radius + pad / 2 + 2, cell, metrics.height()));
    }
    // as wide as the title too, the cells centred
    const double titleWidth = metrics.horizontalAdvance(insetTitle()) + 2 * pad;
    const double shift = std::max(0.0, (titleWidth - (pad + cell * wheels)) / 2);
    for (std::size_t k = 0; k < out.centres.size(); ++k) {
        out.centres[k].rx() += shift;
        out.labels[k].translate(shift, 0);
    }
    out.size = QSizeF(std::max(pad + cell * wheels, titleWidth),
                      top + 2 * out.radius + pad / 2 + 2 + title + pad);
    return out;
}

QPointF spokeTip(QPointF centre, double radius, double theta, int k) {
    // rolling forwards the wheel turns clockwise on the screen (y down): its bottom moves back
    const double alpha = theta + 2 * kPi * k / kSpokes;
    return centre + radius * QPointF(-std::sin(alpha), std::cos(alpha));
}

QString wheelLabel(const WheelAngles& angles, int wheel) {
    if (angles.wheels == 1)
        return QCoreApplication::translate("WheelInset", "\u03b8 = %1 rad")
            .arg(angles.theta1, 0, 'f', 2);
    if (wheel == 0)
        return QCoreApplication::translate("WheelInset", "1 right: \u03b8\u2081 = %1 rad")
            .arg(angles.theta1, 0, 'f', 2);
    return QCoreApplication::translate("WheelInset", "2 left: \u03b8\u2082 = %1 rad")
        .arg(angles.theta2, 0, 'f', 2);
}

void paintWheelInset(QPainter& painter, const QRectF& box, const WheelAngles& angles,
                     const QColor& ink, double lineScale, const QFont& font) {
    const WheelInsetLayout layout = wheelInsetLayout(angles.wheels, lineScale, font);
    if (layout.centres.empty())
        return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setFont(font);
    painter.setPen(cosmeticPen(QColor(120, 120, 120), 1));
    painter.setBrush(QColor(255, 255, 255, 240));
    painter.drawRoundedRect(box, 4 * lineScale, 4 * lineScale);
    const QFontMetricsF metrics(font);
    const double pad = 8 * lineScale;
    // the title, and the direction ahead: the wheels roll to the right
    painter.setPen(Qt::black);
    const QRectF title(box.left() + pad, box.top() + pad / 2, box.width() - 2 * pad,
                       metrics.height() + pad / 2);
    painter.drawText(title, Qt::AlignLeft | Qt::AlignVCenter, insetTitle());
    const double r = layout.radius;
    for (std::size_t k = 0; k < layout.centres.size(); ++k) {
        const QPointF c = box.topLeft() + layout.centres[k];
        const double theta = k == 0 ? angles.theta1 : angles.theta2;
        // the ground under the wheel
        painter.setPen(cosmeticPen(QColor(110, 110, 110), 1.5 * lineScale));
        painter.drawLine(c + QPointF(-1.3 * r, r), c + QPointF(1.3 * r, r));
        // the tyre and the spokes, spoke 0 marked
        painter.setPen(cosmeticPen(ink, 3 * lineScale));
        painter.setBrush(QColor(235, 238, 245));
        painter.drawEllipse(c, r, r);
        for (int s = kSpokes - 1; s >= 0; --s) {
            painter.setPen(s == 0 ? cosmeticPen(rollMarkColour(), 3.5 * lineScale)
                                  : cosmeticPen(ink, 1.5 * lineScale));
            if (std::isfinite(theta))
                painter.drawLine(c, spokeTip(c, 0.92 * r, theta, s));
        }
        painter.setPen(Qt::NoPen);
        painter.setBrush(ink);
        painter.drawEllipse(c, 0.12 * r, 0.12 * r);
        painter.setPen(Qt::black);
        painter.drawText(layout.labels[k].translated(box.topLeft()), Qt::AlignCenter,
                         wheelLabel(angles, int(k)));
    }
    painter.restore();
}

} // namespace chaplygin::ui
