#pragma once
#include <QRectF>
#include <QString>

class QPainter;

namespace chaplygin::ui {

/// Black text in a white halo (eight copies `width` px around it): legible over the bodies and
/// trails that pass under it. The picture of QPainter::drawText(box, flags, text) for one line
/// aligned left, at the top or centred vertically, drawn nine times, but laid out once.
void drawHaloText(QPainter& painter, const QRectF& box, int flags, const QString& text,
                  double width);

} // namespace chaplygin::ui
