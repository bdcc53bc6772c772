#include "canvas/halo_text.h"

#include <QPainter>
#include <QTextLayout>
#include <QTextOption>

#include <algorithm>

namespace chaplygin::ui {

void drawHaloText(QPainter& p, const QRectF& box, int flags, const QString& text, double width) {
    // laid out as drawText lays out one line that does not wrap: the painter's font for its
    // device, trailing spaces kept, the line at the box's left, at its top or its middle
    QTextLayout layout(text, p.font(), p.device());
    QTextOption option;
    option.setWrapMode(QTextOption::ManualWrap);
    option.setFlags(option.flags() | QTextOption::IncludeTrailingSpaces);
    option.setTextDirection(p.layoutDirection());
    layout.setTextOption(option);
    layout.setCacheEnabled(true);
    layout.beginLayout();
    QTextLine line = layout.createLine();
    line.setLineWidth(std::max(0.0, box.width()));
    line.setPosition(QPointF(0, 0));
    layout.endLayout();
    // the line's height unrounded, as drawText centres it (QTextLine::height rounds it up)
    const double height = line.ascent() + line.descent();
    const double yoff = (flags & Qt::AlignVCenter) ? (box.height() - height) / 2 : 0;
    const QPointF at(box.x(), box.y() + yoff);
    // text that does not fit is clipped to the box, each copy to its own
    const bool clipped = !box.contains(QRectF(at, QSizeF(line.naturalTextWidth(), height)));
    auto draw = [&](QPointF d) {
        if (clipped) {
            p.save();
            p.setClipRect(box.translated(d), Qt::IntersectClip);
        }
        line.draw(&p, at + d);
        if (clipped)
            p.restore();
    };
    p.setPen(QColor(255, 255, 255, 220));
    for (QPointF d : {QPointF(-1, 0), QPointF(1, 0), QPointF(0, -1), QPointF(0, 1), QPointF(-1, -1),
                      QPointF(1, 1), QPointF(-1, 1), QPointF(1, -1)})
        draw(d * width);
    p.setPen(Qt::black);
    draw({});
}

} // namespace chaplygin::ui
