#pragma once
#include <QPointF>
#include <QPolygonF>
#include <QRect>

#include <vector>

namespace chaplygin::ui {

/// A polyline and how far its ink reaches from its segments [px]: half its pen's width and the
/// antialiasing, or more.
struct InkLine {
    const QPolygonF* points = nullptr;
    double reach = 0;
};

/// A mark drawn around a point, reaching `reach` [px] from it.
struct InkMark {
    QPointF at;
    double reach = 0;
};

/// The parts of box that the lines' and marks' ink can reach: box cut into bands of `rows` rows
/// from its top, each narrowed to the columns the ink within reach of those rows spans (a band
/// with none is left out). Every pixel of box within reach of a segment or a mark lies in one
/// of them; they do not overlap. Non-finite points are skipped, as a stroke skips them.
std::vector<QRect> inkRows(const QRect& box, int rows, const std::vector<InkLine>& lines,
                           const std::vector<InkMark>& marks);

} // namespace chaplygin::ui
