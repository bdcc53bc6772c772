#include "canvas/masked_layer.h"

#include <QImage>
#include <QPainter>
#include <QPainterPath>

namespace chaplygin::ui {

void drawMaskedLayer(QPainter& p, const QImage& layer, QPoint origin, const QRect& box,
                     std::initializer_list<const QPainterPath*> areas,
                     const std::function<void(QPainter&)>& over) {
    if (box.isEmpty())
        return;
    const qreal dpr = layer.devicePixelRatio();
    QImage piece(box.size() * dpr, QImage::Format_ARGB32_Premultiplied);
    piece.setDevicePixelRatio(dpr);
    QImage mask = piece;
    mask.fill(Qt::transparent);
    {
        QPainter m(&mask);
        m.setRenderHint(QPainter::Antialiasing, true);
        m.translate(-box.topLeft());
        for (const QPainterPath* area : areas)
            m.fillPath(*area, Qt::black);
    }
    {
        QPainter c(&piece);
        c.setCompositionMode(QPainter::CompositionMode_Source);
        c.drawImage(QPointF(0, 0), layer,
                    QRectF(QPointF(box.topLeft() + origin) * dpr, QSizeF(box.size()) * dpr));
        c.setCompositionMode(QPainter::CompositionMode_SourceOver);
        c.setRenderHint(QPainter::Antialiasing, true);
        c.translate(-box.topLeft());
        over(c);
        c.resetTransform();
        c.setCompositionMode(QPainter::CompositionMode_DestinationIn);
        c.drawImage(QPointF(0, 0), mask);
    }
    p.drawImage(box.topLeft(), piece);
}

} // namespace chaplygin::ui
