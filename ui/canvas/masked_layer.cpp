#include "canvas/masked_layer.h"

#include <QImage>
#include <QPaintDevice>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>

namespace chaplygin::ui {

namespace {

// Qt's raster engine hands a blend of more than about 96 spans to its thread pool, waking
// threads and waiting for them (docs/numerics.md §7): translucent images go in bands of rows
constexpr int kBandRows = 64;

// image (at the painter's device pixel ratio) drawn at `at` in bands of rows
void drawInBands(QPainter& p, QPointF at, const QImage& image) {
    const qreal dpr = image.devicePixelRatio();
    for (int top = 0; top < image.height(); top += kBandRows) {
        const int rows = std::min(kBandRows, image.height() - top);
        p.drawImage(at + QPointF(0, top / dpr), image, QRect(0, top, image.width(), rows));
    }
}

} // namespace

void drawMaskedLayer(QPainter& p, const QImage& layer, QPoint origin, const QRect& box,
                     std::initializer_list<const QPainterPath*> areas,
                     const std::function<void(QPainter&)>& over) {
    if (box.isEmpty())
        return;
    const qreal dpr = p.device()->devicePixelRatio();
    QImage piece(box.size() * dpr, QImage::Format_ARGB32_Premultiplied);
    piece.setDevicePixelRatio(dpr);
    QImage mask(piece.size(), piece.format());
    mask.setDevicePixelRatio(dpr);
    mask.fill(Qt::transparent);
    {
        QPainter m(&mask);
        m.setRenderHint(QPainter::Antialiasing, true);
        m.translate(-box.topLeft());
        for (const QPainterPath* area : areas)
            m.fillPath(*area, Qt::black);
    }
    {
        if (layer.isNull())
            piece.fill(Qt::transparent);
        QPainter c(&piece);
        if (!layer.isNull()) {
            c.setCompositionMode(QPainter::CompositionMode_Source);
            c.drawImage(QPointF(0, 0), layer,
                        QRectF(QPointF(box.topLeft() + origin) * dpr, QSizeF(box.size()) * dpr));
            c.setCompositionMode(QPainter::CompositionMode_SourceOver);
        }
        c.setRenderHint(QPainter::Antialiasing, true);
        c.translate(-box.topLeft());
        over(c);
        c.resetTransform();
        c.setCompositionMode(QPainter::CompositionMode_DestinationIn);
        drawInBands(c, QPointF(0, 0), mask);
    }
    drawInBands(p, box.topLeft(), piece);
}

} // namespace chaplygin::ui
