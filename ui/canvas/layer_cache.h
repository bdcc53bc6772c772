#pragma once
#include "canvas/canvas_style.h"

#include <QImage>
#include <QPixmap>
#include <QPointF>
#include <QSize>

#include <functional>

class QPainter;

namespace chaplygin {
class Solution;
}

namespace chaplygin::ui {

/// What a cached layer of the canvas depends on: a layer is drawn again only when its key
/// changes.
struct LayerKey {
    const Solution* solution = nullptr;
    QSize size;
    double scale = 0;
    QPointF centre;
    bool drawMode = false;
    qreal dpr = 0;
    bool vakonomic = true;
    CanvasStyle style;
    bool legend = true;
    bool openLoop = true, closedLoop = true;
    bool operator==(const LayerKey&) const = default;
};

/// The canvas's cached images and their keys: the static layer (grid, path and legend), the
/// world layer that following the body shifts by whole pixels, the legend's layer, the path's
/// layer for the bodies drawn to scale, and the trail layer (the static layer with the trails
/// drawn on it). The cache decides when a layer is stale; the canvas draws it through a
/// callback. Five images at most, each of the widget's size (the world layer twice that).
class LayerCache {
  public:
    using Paint = std::function<void(QPainter&)>;

    /// The static layer of key's size and device pixel ratio, drawn on white by `paint` (with
    /// antialiasing) when the key changed; the last view's pixels are painted over, since a
    /// new 8 MB image at 1920 x 1080 costs its pages' first touch at every zoom step.
    const QPixmap& background(const LayerKey& key, const Paint& paint);
    /// Whether the static layer is there for key.
    bool hasBackground(const LayerKey& key) const;

    /// The legend's layer, `size` [px] at key's device pixel ratio, drawn on transparent
    /// pixels when key changed.
    const QPixmap& legend(const LayerKey& key, QSize size, const Paint& paint);

    /// Following the body: grid and path drawn once over `margin` [px] around the view at
    /// `centre` [m], then shifted by whole pixels. Made anew when key (its centre aside)
    /// changed or the view moved more than the margin from the layer's centre; `paint` draws
    /// it given its size [px].
    const QPixmap& worldLayer(const LayerKey& key, QPointF centre, double scale, int margin,
                              const std::function<void(QPainter&, QSize)>& paint);
    /// Whether the world layer is there for key (its centre aside).
    bool hasWorldLayer(const LayerKey& key) const;
    QPointF worldCentre() const { return m_worldCentre; }
    int worldMargin() const { return m_worldMargin; }

    /// The path's band and marks on a transparent layer of `size` [px], made when the same
    /// view (key, following or not) is painted a second time; a null image at a view's first
    /// paint (a zoom step), which the band within each body's box serves more cheaply.
    const QImage& pathLayer(const LayerKey& key, bool following, QSize size, const Paint& paint);

    /// Brings the trail layer to time t over `base`: when the layer is missing, was made from
    /// another base or from a later time, it becomes a copy of base's pixels and `anew` is
    /// true; else `since` is the time the layer shows, whose trails' ends are to be drawn
    /// again up to t.
    struct TrailUpdate {
        bool anew = false;
        double since = 0;
    };
    TrailUpdate bringTrailLayerTo(const QPixmap& base, double t);
    QImage& trailLayer() { return m_trailLayer; }

    /// Forgets every layer and the views seen: the next paint draws everything anew, as a
    /// view's first paint does.
    void drop();

  private:
    LayerKey m_backgroundKey;
    QPixmap m_background;
    LayerKey m_worldKey;
    QPixmap m_worldLayer;
    QPointF m_worldCentre;
    int m_worldMargin = 0;
    LayerKey m_legendKey;
    QPixmap m_legendLayer;
    LayerKey m_pathKey;
    bool m_pathFollowing = false;
    QImage m_pathLayer;
    LayerKey m_pathSeenKey; // the view of the last paint without the path's layer
    bool m_pathSeenFollowing = false;
    QImage m_trailLayer;
    qint64 m_trailBase = 0; // the cache key of the static layer it was made from
    double m_trailsTime = 0;
};

} // namespace chaplygin::ui
