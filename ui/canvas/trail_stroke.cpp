#include "canvas/trail_stroke.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace chaplygin::ui {

namespace {

// how far beyond the area's bounds a segment's end may lie for it to be stroked whole [px]
constexpr double kNearPx = 2048;

// the rectangles of area, each grown by pad
std::vector<QRectF> grown(const QRegion& area, double pad) {
    std::vector<QRectF> out;
    for (const QRect& r : area)
        out.push_back(QRectF(r).adjusted(-pad, -pad, pad, pad));
    return out;
}

bool reaches(const std::vector<QRectF>& rects, const QRectF& bounds, QPointF a, QPointF b) {
    const QRectF box(QPointF(std::min(a.x(), b.x()), std::min(a.y(), b.y())),
                     QPointF(std::max(a.x(), b.x()), std::max(a.y(), b.y())));
    // a zero-size box still intersects: compare edges, not QRectF::intersects
    auto meets = [&](const QRectF& r) {
        return box.left() <= r.right() && r.left() <= box.right() && box.top() <= r.bottom() &&
               r.top() <= box.bottom();
    };
    if (!meets(bounds))
        return false;
    return std::any_of(rects.begin(), rects.end(), meets);
}

bool finite(QPointF p) {
    return std::isfinite(p.x()) && std::isfinite(p.y());
}

// the part of the segment a -> b inside r, as fractions of the way from a (Liang-Barsky); {1, 1}
// when none of it is
std::pair<double, double> clippedSpan(const QRectF& r, QPointF a, QPointF b) {
    double lo = 0, hi = 1;
    const double d[2] = {b.x() - a.x(), b.y() - a.y()};
    const double p0[2] = {a.x(), a.y()};
    const double low[2] = {r.left(), r.top()}, high[2] = {r.right(), r.bottom()};
    for (int axis = 0; axis < 2; ++axis) {
        if (d[axis] == 0) {
            if (p0[axis] < low[axis] || p0[axis] > high[axis])
                return {1, 1};
            continue;
        }
        double t0 = (low[axis] - p0[axis]) / d[axis], t1 = (high[axis] - p0[axis]) / d[axis];
        if (t0 > t1)
            std::swap(t0, t1);
        lo = std::max(lo, t0);
        hi = std::min(hi, t1);
    }
    if (!(lo <= hi))
        return {1, 1};
    return {lo, hi};
}

// the part of a -> b to stroke: all of it when both ends are near, else the part in bounds
std::pair<double, double> withinSpan(const QRectF& near, QPointF a, QPointF b,
                                     const QRectF& bounds) {
    if (near.contains(a) && near.contains(b))
        return {0, 1};
    return clippedSpan(bounds, a, b);
}

} // namespace

void strokePolylineWithin(QPainter& p, const QPolygonF& line, const QPen& pen,
                          const QRegion& area) {
    const QTransform device = p.deviceTransform();
    const double s = device.m11();
    const double width = pen.widthF() > 0 ? pen.widthF() : 1;
    const bool cosmetic = pen.isCosmetic() || pen.widthF() == 0;
    const double deviceWidth = cosmetic ? width : width * s;
    // Qt strokes thin pens with its cosmetic line stroker, and other transforms are rare: there
    // the whole line is Qt's
    if (line.size() < 2 || device.type() > QTransform::TxScale || device.m22() != s || !(s > 0) ||
        deviceWidth <= 1 || pen.style() == Qt::NoPen) {
        p.setPen(pen);
        p.drawPolyline(line);
        return;
    }
    const double unit = cosmetic ? 1 / s : 1; // a pen width unit in user coordinates
    const double w = width * unit;
    const bool miter = pen.joinStyle() == Qt::MiterJoin || pen.joinStyle() == Qt::SvgMiterJoin;
    // how far a segment's ink reaches: half its width, a miter join's spike, antialiasing
    const double pad = w * std::max(2.0, miter ? pen.miterLimit() : 1.0) + 3 * unit;
    const std::vector<QRectF> rects = grown(area, pad);
    const QRectF bounds = QRectF(area.boundingRect()).adjusted(-pad, -pad, pad, pad);
    if (rects.empty())
        return;
    // segments with both ends in here are drawn whole, as drawPolyline draws them; longer ones
    // only within bounds
    const QRectF near = bounds.adjusted(-kNearPx, -kNearPx, kNearPx, kNearPx);

    QPainterPath path;
    if (pen.style() == Qt::SolidLine) {
        bool open = false;
        for (qsizetype i = 1; i < line.size(); ++i) {
            const QPointF a = line[i - 1], b = line[i];
            if (!finite(a) || !finite(b) || !reaches(rects, bounds, a, b)) {
                open = false;
                continue;
            }
            // only the part within reach: a segment 1e289 px long is not handed to the stroker
            const auto [lo, hi] = withinSpan(near, a, b, bounds);
            if (!(lo < hi)) {
                open = false;
                continue;
            }
            if (!open || lo > 0)
                path.moveTo(a + (b - a) * lo);
            path.lineTo(a + (b - a) * hi);
            open = hi >= 1;
        }
    } else {
        // the dash pattern in user units: dashes and gaps alternate, an even count
        const QList<qreal> pattern = pen.dashPattern();
        std::vector<double> dashes;
        double period = 0;
        for (qsizetype i = 0; i + 1 < pattern.size(); i += 2)
            for (qsizetype j = i; j < i + 2; ++j) {
                dashes.push_back(std::max(pattern[j], qreal(0)) * w);
                period += dashes.back();
            }
        if (!(period > 0))
            return;
        // the pen's offset moves the pattern's start into it
        double offset = pen.dashOffset() * w;
        offset -= std::floor(offset / period) * period;
        std::size_t k = 0;
        while (offset >= dashes[k]) {
            offset -= dashes[k];
            k = (k + 1) % dashes.size();
        }
        double left = dashes[k] - offset; // what remains of dash or gap k
        // moves the pattern on by d: whole periods at once, so that a long stretch far from area
        // costs no more than a short one
        auto skip = [&](double d) {
            if (d < left) {
                left -= d;
                return;
            }
            d -= left;
            k = (k + 1) % dashes.size();
            d = std::fmod(d, period);
            while (d >= dashes[k]) {
                d -= dashes[k];
                k = (k + 1) % dashes.size();
            }
            left = dashes[k] - d;
        };
        bool open = false; // a dash of the path is being drawn
        for (qsizetype i = 1; i < line.size(); ++i) {
            const QPointF a = line[i - 1], b = line[i];
            const double length = std::hypot(b.x() - a.x(), b.y() - a.y());
            if (!finite(a) || !finite(b) || !std::isfinite(length)) {
                open = false; // a point that cannot be drawn
                continue;
            }
            if (!(length > 0))
                continue;
            // the dashes are laid out only along the part of the segment within reach of area,
            // from its own ends: their number is bounded by the area's size, however long the
            // segment (a trail point at 1e308 m is 1e289 px from the next one)
            const auto [lo, hi] = reaches(rects, bounds, a, b) ? withinSpan(near, a, b, bounds)
                                                               : std::pair<double, double>{1, 1};
            if (lo > 0) {
                skip(lo * length);
                open = false;
            }
            const QPointF from = a + (b - a) * lo, to = a + (b - a) * hi;
            const double span = hi > lo ? std::hypot(to.x() - from.x(), to.y() - from.y()) : 0;
            double at = 0; // along the part within reach
            while (at < span) {
                const bool inDash = k % 2 == 0;
                const double end = std::min(at + left, span);
                if (inDash) {
                    if (!open)
                        path.moveTo(from + (to - from) * (at / span));
                    path.lineTo(from + (to - from) * (end / span));
                    open = true;
                }
                if (at + left > span) {
                    left -= span - at;
                    break;
                }
                // dash or gap k ends here
                open = false;
                at += left;
                k = (k + 1) % dashes.size();
                left = dashes[k];
            }
            if (hi < 1) {
                skip((1 - hi) * length);
                open = false;
            }
        }
    }
    if (path.isEmpty()) // nothing reaches area
        return;
    QPen solid = pen;
    solid.setStyle(Qt::SolidLine);
    p.setPen(solid);
    p.setBrush(Qt::NoBrush);
    p.drawPath(path);
}

QRegion paintableArea(const QPainter& p) {
    QRectF area = p.worldTransform().inverted().mapRect(QRectF(p.window()));
    if (p.hasClipping())
        area = area.intersected(p.clipBoundingRect());
    return QRegion(area.toAlignedRect());
}

} // namespace chaplygin::ui
