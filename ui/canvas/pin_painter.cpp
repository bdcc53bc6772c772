#include "canvas/pin_painter.h"

#include "canvas/trail_stroke.h"

#include "canvas/body_painter.h"
#include "canvas/curve_flattening.h"
#include "document/pin_set.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <vector>

namespace chaplygin::ui {

namespace {

constexpr double kKeyRowPx = 16, kKeyTextPx = 28; // the key's rows, and its text after the line

QFont keyFont(QFont f) {
    f.setPointSizeF(9);
    return f;
}

QString keyText(PinSet& pins, int i) {
    return QObject::tr("pin %1: %2").arg(i + 1).arg(pins.label(i));
}

} // namespace

void paintPinnedRuns(QPainter& p, PinSet& pins, CanvasCurves& curves, const QTransform& world,
                     double t, QPointF topLeft) {
    const int n = pins.count();
    if (n == 0)
        return;
    p.save();
    // where each run is at t (clamped to its own end), computed once per paint
    std::vector<MotionSample> now(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        if (const PinSet::Run& run = pins.run(i); run.solution)
            now[std::size_t(i)] = run.solution->at(std::clamp(t, 0.0, run.solution->tEnd()));
    // trails and faint bodies first, then every dot on top, so that no pin hides another's dot
    for (int i = 0; i < n; ++i) {
        const PinSet::Run& run = pins.run(i);
        if (!run.solution)
            continue;
        const MotionSample& m = now[std::size_t(i)];
        QColor c = PinSet::color(i);
        c.setAlpha(150);
        QPen pen(c, 2.5);
        pen.setCosmetic(true);
        pen.setCapStyle(Qt::RoundCap);
        pen.setJoinStyle(Qt::RoundJoin);
        // the trail up to t, like the live body's: the lengths show which run is ahead; along
        // its path flattened at this scale, up to its arc length now
        const FlatCurve& path = curves.pinnedPath(run.solution);
        QPolygonF line;
        const std::size_t count = path.countUpTo(m.s);
        for (std::size_t k = 0; k < count; ++k)
            line << world.map(path.points[k]);
        if (path.reaches(m.s))
            line << world.map(QPointF(m.x, m.y));
        strokePolylineWithin(p, line, pen, paintableArea(p)); // clipped at any zoom
        p.save();
        p.setTransform(world, true);
        paintBody(p, run.solution->scene().system, run.solution->system(), {m.x, m.y, m.phi},
                  PinSet::color(i), true);
        p.restore();
    }
    for (int i = 0; i < n; ++i) {
        if (!pins.run(i).solution)
            continue;
        const MotionSample& m = now[std::size_t(i)];
        QColor c = PinSet::color(i);
        p.setPen(QPen(c.darker(130), 1));
        p.setBrush(c);
        p.drawEllipse(world.map(QPointF(m.x, m.y)), 4.5, 4.5);
    }
    p.setFont(keyFont(p.font()));
    for (int i = 0; i < n; ++i) {
        QPointF row = topLeft + QPointF(0, kKeyRowPx * i);
        QColor c = PinSet::color(i);
        p.setPen(QPen(c, 3));
        p.drawLine(row + QPointF(0, -4), row + QPointF(22, -4));
        p.setPen(Qt::black);
        p.drawText(row + QPointF(kKeyTextPx, 0), keyText(pins, i));
    }
    p.restore();
}

QRectF pinKeyBounds(PinSet& pins, QPointF topLeft, const QFont& font) {
    const int n = pins.count();
    if (n == 0)
        return {};
    const QFontMetricsF fm(keyFont(font));
    double width = 0;
    for (int i = 0; i < n; ++i)
        width = std::max(width, fm.horizontalAdvance(keyText(pins, i)));
    return QRectF(topLeft.x(), topLeft.y() - fm.ascent(), kKeyTextPx + width,
                  fm.ascent() + kKeyRowPx * (n - 1) + fm.descent());
}

} // namespace chaplygin::ui
