#pragma once
#include "paths/path.h"

#include <QPointF>
#include <QRectF>
#include <QTransform>

#include <memory>

class QWidget;

namespace chaplygin::ui {

/// The canvas's view of the world: the map between metres and the widget's pixels (y up in
/// the world), zoom and pan, the framing of a box in the drawing area, and how the view follows
/// the scene (refit on a resize or a new path, follow the body, keep the view for a stroke).
class CanvasView {
  public:
    /// The zoom range [px/m].
    static constexpr double kMinScale = 1e-3, kMaxScale = 1e5;

    /// The view of `widget`, whose size it reads at every use.
    explicit CanvasView(const QWidget& widget) : m_widget(&widget) {}

    /// Pixels per metre.
    double scale() const { return m_scale; }
    /// The world point at the widget's centre [m].
    QPointF centre() const { return m_centre; }
    /// The metres-to-pixels map: pixel = transform().map(world).
    QTransform transform() const { return transformAt(m_centre); }
    /// The same map with its centre at `centre` [m].
    QTransform transformAt(QPointF centre) const;
    QPointF toPixel(QPointF world) const { return transform().map(world); }
    QPointF toWorld(QPointF pixel) const { return transform().inverted().map(pixel); }

    /// Frames box [m] in area [px] with a margin of `margin` [px] on each side (never more
    /// than 40 % of the area), at no less than minScale and no more than maxScale; the view then
    /// refits on a resize.
    void frame(const QRectF& box, const QRectF& area, double margin, double minScale,
               double maxScale = kMaxScale);
    /// Zooms by factor about the widget's centre, within the zoom range; the user's view from
    /// then on (no refit).
    void zoomBy(double factor);
    /// Zooms by factor keeping the world point under `pixel` where it is.
    void zoomAbout(QPointF pixel, double factor);
    /// Moves the world by `pixels` on the screen (a drag); the user's view from then on.
    void panBy(QPointF pixels);
    /// Moves the centre by `metres`; the user's view from then on.
    void moveCentre(QPointF metres);
    /// Centres the view on `world` [m] snapped to the pixel grid, so that following a body
    /// moves the view by whole pixels and the static layer is shifted rather than drawn again.
    void centreOn(QPointF world);
    /// Grid lines every 1, 2 or 5 x 10^k m, at least 40 px apart.
    double gridStep() const;

    /// Whether the view refits on a resize and a new path (until the user zooms or pans).
    bool autoFit() const { return m_autoFit; }
    void setAutoFit(bool on) { m_autoFit = on; }
    /// Whether the last fit framed everything that moves rather than the path and the body.
    bool fitsEverything() const { return m_fitAll; }
    void setFitsEverything(bool on) { m_fitAll = on; }
    /// Whether the next new path (a stroke, a moved point) keeps the view.
    bool keepsViewForNextPath() const { return m_keepView; }
    void setKeepViewForNextPath(bool on) { m_keepView = on; }
    bool follows() const { return m_follow; }
    /// Starts or stops following the body; returns whether that changed anything. Starting
    /// remembers the view, which returnFromFollow restores; stopping here keeps the view.
    bool setFollows(bool on);
    /// Following: the scale at which the body is readable [px/m], or the view's before following
    /// where that was larger, times the user's follow zoom (1 until the user zooms while
    /// following; kept for the next follow).
    void setFollowScale(double readable);
    /// Following: zooms by factor (within the zoom range) about the centre; the follow zoom from
    /// then on.
    void zoomFollow(double factor);
    /// The user's zoom of the follow scale.
    double followZoom() const { return m_followZoom; }
    /// Stops following and returns to the view before it (its scale, centre and whether it
    /// refits); returns whether it was following.
    bool returnFromFollow();
    /// The path the view was last fitted to (a new one is fitted again).
    const std::shared_ptr<const Path>& fittedPath() const { return m_fittedPath; }
    void setFittedPath(std::shared_ptr<const Path> path) { m_fittedPath = std::move(path); }

  private:
    const QWidget* m_widget;
    double m_scale = 50; // px per metre
    QPointF m_centre;    // world point at the widget centre
    bool m_autoFit = true;
    bool m_fitAll = false;
    bool m_keepView = false;
    bool m_follow = false;
    double m_readable = 0;   // px per metre at which the followed body is readable
    double m_followZoom = 1; // the user's zoom of it
    struct SavedView {
        double scale = 50;
        QPointF centre;
        bool autoFit = true;
    } m_beforeFollow;
    std::shared_ptr<const Path> m_fittedPath;
};

} // namespace chaplygin::ui
