#include "canvas/layer_cache.h"

#include <QPainter>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace chaplygin::ui {

namespace {

// `to` becomes an RGB32 copy of `from`'s pixels, in its own memory when that has the size (a
// new image at every zoom step would cost its pages' first touch)
void copyPixels(const QImage& from, QImage& to) {
    const QImage source =
        from.format() == QImage::Format_RGB32 ? from : from.convertToFormat(QImage::Format_RGB32);
    if (to.size() != source.size() || to.format() != QImage::Format_RGB32)
        to = QImage(source.size(), QImage::Format_RGB32);
    const auto bytes = std::size_t(std::min(to.bytesPerLine(), source.bytesPerLine()));
    for (int y = 0; y < source.height(); ++y)
        std::memcpy(to.scanLine(y), source.constScanLine(y), bytes);
}

// `layer` filled with `fill` over `size` [px] at ratio dpr (its memory kept when it has that size:
// a new 8 MB image at 1920 x 1080 costs its pages' first touch), then painted with antialiasing
void paintLayer(QPixmap& layer, QSize size, qreal dpr, Qt::GlobalColor fill,
                const std::function<void(QPainter&)>& paint) {
    if (layer.size() != size * dpr) {
        layer = QPixmap(size * dpr);
        layer.setDevicePixelRatio(dpr);
    }
    layer.fill(fill);
    QPainter p(&layer);
    p.setRenderHint(QPainter::Antialiasing, true);
    paint(p);
}

} // namespace

const QPixmap& LayerCache::background(const LayerKey& key, const Paint& paint) {
    if (hasBackground(key))
        return m_background;
    m_backgroundKey = key;
    paintLayer(m_background, key.size, key.dpr, Qt::white, paint);
    return m_background;
}

bool LayerCache::hasBackground(const LayerKey& key) const {
    return key == m_backgroundKey && !m_background.isNull();
}

const QPixmap& LayerCache::legend(const LayerKey& key, QSize size, const Paint& paint) {
    if (key == m_legendKey && !m_legendLayer.isNull())
        return m_legendLayer;
    m_legendKey = key;
    paintLayer(m_legendLayer, size, key.dpr, Qt::transparent, paint);
    return m_legendLayer;
}

const QPixmap& LayerCache::worldLayer(const LayerKey& key, QPointF centre, double scale, int margin,
                                      const std::function<void(QPainter&, QSize)>& paint) {
    const QPointF shift = (centre - m_worldCentre) * scale; // [px], y up
    if (hasWorldLayer(key) && std::abs(shift.x()) <= m_worldMargin &&
        std::abs(shift.y()) <= m_worldMargin)
        return m_worldLayer;
    m_worldKey = key;
    m_worldCentre = centre;
    m_worldMargin = margin;
    const QSize big = key.size + QSize(2 * margin, 2 * margin);
    paintLayer(m_worldLayer, big, key.dpr, Qt::white, [&](QPainter& w) { paint(w, big); });
    return m_worldLayer;
}

bool LayerCache::hasWorldLayer(const LayerKey& key) const {
    return key == m_worldKey && !m_worldLayer.isNull();
}

const QImage& LayerCache::pathLayer(const LayerKey& key, bool following, QSize size,
                                    const Paint& paint) {
    // the key's size fixes the world layer's margin too
    if (key == m_pathKey && following == m_pathFollowing && !m_pathLayer.isNull())
        return m_pathLayer;
    if (!(key == m_pathSeenKey) || following != m_pathSeenFollowing) {
        m_pathSeenKey = key;
        m_pathSeenFollowing = following;
        static const QImage none;
        return none;
    }
    m_pathKey = key;
    m_pathFollowing = following;
    m_pathLayer = QImage(size * key.dpr, QImage::Format_ARGB32_Premultiplied);
    m_pathLayer.setDevicePixelRatio(key.dpr);
    m_pathLayer.fill(Qt::transparent);
    QPainter l(&m_pathLayer);
    l.setRenderHint(QPainter::Antialiasing, true);
    paint(l);
    return m_pathLayer;
}

LayerCache::TrailUpdate LayerCache::bringTrailLayerTo(const QPixmap& base, double t) {
    TrailUpdate update{.anew = false, .since = m_trailsTime};
    if (m_trailLayer.isNull() || m_trailBase != base.cacheKey() || t < m_trailsTime) {
        copyPixels(base.toImage(), m_trailLayer);
        m_trailLayer.setDevicePixelRatio(base.devicePixelRatio());
        m_trailBase = base.cacheKey();
        update.anew = true;
    }
    m_trailsTime = t;
    return update;
}

void LayerCache::drop() {
    m_background = {};
    m_worldLayer = {};
    m_legendLayer = {};
    m_pathLayer = {};
    m_pathSeenKey = {};
    m_trailLayer = {};
}

} // namespace chaplygin::ui
