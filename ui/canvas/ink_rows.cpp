#include "canvas/ink_rows.h"

#include <QRectF>

#include <algorithm>
#include <cmath>
#include <limits>

namespace chaplygin::ui {

std::vector<QRect> inkRows(const QRect& box, int rows, const std::vector<InkLine>& lines,
                           const std::vector<InkMark>& marks) {
    if (box.isEmpty() || rows < 1)
        return {};
    const int bands = (box.height() + rows - 1) / rows;
    constexpr double kNone = std::numeric_limits<double>::infinity();
    std::vector<std::pair<double, double>> columns(std::size_t(bands), {kNone, -kNone});
    // box's pixels span [left, right + 1) x [top, bottom + 1)
    const QRectF area(box.left(), box.top(), box.width(), box.height());
    auto add = [&](QRectF ink) {
        if (!(ink.right() >= area.left() && ink.left() <= area.right() &&
              ink.bottom() >= area.top() && ink.top() <= area.bottom()))
            return;
        ink = ink.intersected(area.adjusted(-1, -1, 1, 1));
        const int first =
            std::clamp(int(std::floor((ink.top() - area.top()) / rows)), 0, bands - 1);
        const int last =
            std::clamp(int(std::floor((ink.bottom() - area.top()) / rows)), 0, bands - 1);
        for (int k = first; k <= last; ++k) {
            auto& [from, to] = columns[std::size_t(k)];
            from = std::min(from, ink.left());
            to = std::max(to, ink.right());
        }
    };
    auto finite = [](QPointF p) { return std::isfinite(p.x()) && std::isfinite(p.y()); };
    for (const InkLine& line : lines) {
        if (!line.points)
            continue;
        const QPolygonF& q = *line.points;
        const double r = line.reach;
        for (qsizetype i = 0; i < q.size(); ++i) {
            if (!finite(q[i]))
                continue;
            // a point alone (a stroke's round cap) and each segment from the one before
            QPointF a = q[i], b = q[i];
            if (i > 0 && finite(q[i - 1]))
                a = q[i - 1];
            add(QRectF(QPointF(std::min(a.x(), b.x()) - r, std::min(a.y(), b.y()) - r),
                       QPointF(std::max(a.x(), b.x()) + r, std::max(a.y(), b.y()) + r)));
        }
    }
    for (const InkMark& mark : marks)
        if (finite(mark.at))
            add(QRectF(mark.at - QPointF(mark.reach, mark.reach),
                       mark.at + QPointF(mark.reach, mark.reach)));
    std::vector<QRect> out;
    for (int k = 0; k < bands; ++k) {
        const auto [from, to] = columns[std::size_t(k)];
        if (from > to)
            continue;
        const int left = std::max(box.left(), int(std::floor(from)));
        const int right = std::min(box.right(), int(std::ceil(to)));
        if (right < left)
            continue;
        const int top = box.top() + k * rows;
        out.emplace_back(left, top, right + 1 - left, std::min(rows, box.bottom() + 1 - top));
    }
    return out;
}

} // namespace chaplygin::ui
