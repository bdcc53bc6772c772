#include "canvas/layer_blit.h"

#include <QImage>
#include <QPainter>
#include <QPixmap>

#include <cmath>
#include <type_traits>

namespace chaplygin::ui {

namespace {

template <class Layer>
void blit(QPainter& painter, const QRegion& region, const Layer& layer, QPoint origin) {
    if (region.isEmpty() || layer.isNull())
        return;
    const qreal dpr = layer.devicePixelRatio();
    if (dpr != std::round(dpr)) {
        // a rectangle's edges would fall between device pixels: the whole layer, clipped
        painter.save();
        painter.setClipRegion(region, Qt::IntersectClip);
        const QRectF target(QPointF(-origin), QSizeF(layer.size()) / dpr);
        if constexpr (std::is_same_v<Layer, QPixmap>)
            painter.drawPixmap(target, layer, QRectF(layer.rect()));
        else
            painter.drawImage(target, layer, QRectF(layer.rect()));
        painter.restore();
        return;
    }
    const bool clipped = painter.hasClipping();
    const QRegion clip = painter.clipRegion();
    for (const QRect& r : region) {
        painter.setClipRect(r);
        if (clipped)
            painter.setClipRegion(clip, Qt::IntersectClip);
        const QRectF source(QPointF(r.topLeft() + origin) * dpr, QSizeF(r.size()) * dpr);
        if constexpr (std::is_same_v<Layer, QPixmap>)
            painter.drawPixmap(QRectF(r), layer, source);
        else
            painter.drawImage(QRectF(r), layer, source);
    }
    if (clipped)
        painter.setClipRegion(clip);
    else
        painter.setClipping(false);
}

} // namespace

void blitRegion(QPainter& painter, const QRegion& region, const QPixmap& layer, QPoint origin) {
    blit(painter, region, layer, origin);
}

void blitRegion(QPainter& painter, const QRegion& region, const QImage& layer, QPoint origin) {
    blit(painter, region, layer, origin);
}

} // namespace chaplygin::ui
