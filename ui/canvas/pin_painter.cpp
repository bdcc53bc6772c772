#include "canvas/pin_painter.h"

#include "canvas/body_painter.h"
#include "document/pin_set.h"

#include <QPainter>

#include <algorithm>

namespace chaplygin::ui {

void paintPinnedRuns(QPainter& p, PinSet& pins, const QTransform& world, double t,
                     QPointF topLeft) {
    const int n = pins.count();
    if (n == 0)
        return;
    p.save();
    // trails and faint bodies first, then every dot on top, so that no pin hides another's dot
    for (int i = 0; i < n; ++i) {
        const PinSet::Run& run = pins.run(i);
        if (!run.solution)
            continue;
        QColor c = PinSet::color(i);
        c.setAlpha(150);
        QPen pen(c, 2.5);
        pen.setCosmetic(true);
        pen.setCapStyle(Qt::RoundCap);
        pen.setJoinStyle(Qt::RoundJoin);
        p.setPen(pen);
        // the trail up to t, like the live body's: the lengths show which run is ahead
        MotionSample now = run.solution->at(std::clamp(t, 0.0, run.solution->tEnd()));
        QPolygonF line;
        for (int k = 0; k < run.series.x.size() && run.series.t[k] <= t; ++k)
            line << world.map(QPointF(run.series.x[k], run.series.y[k]));
        line << world.map(QPointF(now.x, now.y));
        p.drawPolyline(line);
        p.save();
        p.setTransform(world, true);
        paintBody(p, run.solution->scene().system, run.solution->system(), {now.x, now.y, now.phi},
                  PinSet::color(i), true);
        p.restore();
    }
    for (int i = 0; i < n; ++i) {
        const PinSet::Run& run = pins.run(i);
        if (!run.solution)
            continue;
        QColor c = PinSet::color(i);
        MotionSample now = run.solution->at(std::clamp(t, 0.0, run.solution->tEnd()));
        p.setPen(QPen(c.darker(130), 1));
        p.setBrush(c);
        p.drawEllipse(world.map(QPointF(now.x, now.y)), 4.5, 4.5);
    }
    QFont f = p.font();
    f.setPointSizeF(9);
    p.setFont(f);
    for (int i = 0; i < n; ++i) {
        QPointF row = topLeft + QPointF(0, 16.0 * i);
        QColor c = PinSet::color(i);
        p.setPen(QPen(c, 3));
        p.drawLine(row + QPointF(0, -4), row + QPointF(22, -4));
        p.setPen(Qt::black);
        p.drawText(row + QPointF(28, 0), QObject::tr("pin %1: %2").arg(i + 1).arg(pins.label(i)));
    }
    p.restore();
}

} // namespace chaplygin::ui
