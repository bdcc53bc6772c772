#include "canvas/trail_stroke.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <vector>

namespace chaplygin::ui {

namespace {

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

    QPainterPath path;
    if (pen.style() == Qt::SolidLine) {
        bool open = false;
        for (qsizetype i = 1; i < line.size(); ++i) {
            if (!reaches(rects, bounds, line[i - 1], line[i])) {
                open = false;
                continue;
            }
            if (!open)
                path.moveTo(line[i - 1]);
            path.lineTo(line[i]);
            open = true;
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
        bool open = false;                // a dash of the path is being drawn
        QPointF start = line[0];          // where the current dash began
        for (qsizetype i = 1; i < line.size(); ++i) {
            const QPointF a = line[i - 1], b = line[i];
            const double length = std::hypot(b.x() - a.x(), b.y() - a.y());
            if (!(length > 0))
                continue;
            const bool near = reaches(rects, bounds, a, b);
            if (!near)
                open = false;
            double at = 0; // along this segment
            while (true) {
                const bool inDash = k % 2 == 0;
                const double end = at + left;
                const bool within = end <= length;
                const QPointF to = within ? a + (b - a) * (end / length) : b;
                if (inDash && near) {
                    if (!open)
                        path.moveTo(at > 0 ? start : a);
                    path.lineTo(to);
                    open = true;
                }
                if (!within) {
                    left -= length - at;
                    break;
                }
                // dash or gap k ends here
                if (inDash)
                    open = false;
                else
                    start = to;
                at = end;
                k = (k + 1) % dashes.size();
                left = dashes[k];
            }
        }
    }
    QPen solid = pen;
    solid.setStyle(Qt::SolidLine);
    p.setPen(solid);
    p.setBrush(Qt::NoBrush);
    p.drawPath(path);
}

} // namespace chaplygin::ui
