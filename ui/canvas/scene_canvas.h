#pragma once
#include "canvas/body_painter.h"
#include "canvas/body_sprites.h"
#include "canvas/canvas_style.h"
#include "canvas/curve_flattening.h"
#include "canvas/vector_layer.h"
#include "paths/path_source.h"
#include "scene/solution.h"

#include <QPixmap>

#include <QImage>
#include <QPainterPath>
#include <QPen>
#include <QPointF>
#include <QWidget>

#include <memory>
#include <utility>
#include <vector>

namespace chaplygin::ui {

class SceneDocument;

/// The animation canvas: the prescribed path coloured by curvature, the controlled body to scale
/// at its pose with its trail, and a translucent ghost of the free motion with its own trail.
/// Wheel zooms about the cursor, dragging pans; in draw mode the left button draws a path.
class SceneCanvas : public QWidget {
    Q_OBJECT
  public:
    explicit SceneCanvas(SceneDocument* document, QWidget* parent = nullptr);

    double time() const { return m_time; }
    bool followsBody() const { return m_follow; }
    bool drawMode() const { return m_drawMode; }
    /// Whether the genuine vakonomic body (a third body) is drawn.
    bool showsVakonomic() const { return m_showVakonomic; }
    /// Whether the perturbed bodies are drawn when the scene has a perturbation
    /// (docs/physics.md §9): the open loop and the closed loop.
    bool showsOpenLoop() const { return m_showOpenLoop; }
    bool showsClosedLoop() const { return m_showClosedLoop; }
    /// Whether a push is being dragged from the controlled body.
    bool pushing() const { return m_pushing; }
    /// Pixels per metre.
    double scale() const { return m_scale; }
    /// World point (metres) <-> widget pixel.
    QPointF toPixel(QPointF world) const;
    QPointF toWorld(QPointF pixel) const;
    /// The metres-to-pixels map: pixel = transform.map(world), y up in the world.
    QTransform worldToPixel() const { return worldTransform(); }
    /// Every curve drawn, flattened at the current scale (docs/architecture.md, ui/: the desktop
    /// application, Canvas).
    const CanvasCurves& curves() const;

    QSize sizeHint() const override { return {800, 500}; }
    /// The arrows of View > Vectors as last painted.
    const VectorLayer& vectorLayer() const { return m_vectors; }
    QSize minimumSizeHint() const override { return {240, 180}; }

    const CanvasStyle& canvasStyle() const { return m_style; }
    void setCanvasStyle(const CanvasStyle& style);
    /// The style and the bodies and keys shown, to draw another canvas the same way.
    CanvasLook look() const;
    void setLook(const CanvasLook& look);
    bool legendVisible() const { return m_legendVisible; }
    /// The part of the widget the scene is drawn in: between the time line and the legend.
    QRectF drawingArea() const;
    /// The box of the draw-mode hint's text under the time line; empty outside draw mode.
    QRectF drawHintBounds() const;
    /// The box of the pinned runs' key of colours and labels; empty without pins.
    QRectF pinKeyBounds() const;
    /// The world rectangle of the path [m].
    QRectF pathBounds() const;
    /// The world rectangle "Fit everything that moves" frames: the path and every body drawn
    /// over the whole horizon.
    QRectF sceneBounds() const;
    /// Whether the view refits to everything that moves (fitEverything) rather than to the path
    /// and the controlled body (fitScene) on a resize or a new path.
    bool fitsEverything() const { return m_fitAll; }
    /// The bodies' display drawn now: the chosen one, or what Automatic picks for this scene.
    BodyDisplay shownBodyDisplay() const;
    /// Forgets the cached layers (static layer, trails): the next paint draws everything anew.
    void dropLayers();
    /// Whether the last paint drew the path over the bodies from the path's layer (a view
    /// painted before) rather than within each body's box (a view's first paint).
    bool pathOverBodiesFromLayer() const { return m_pathOverBodiesFromLayer; }

  public slots:
    void setTime(double t);
    /// Frames the lesson (F, the default): the path and the controlled body with a margin of
    /// 5 % on each side, the path filling at least 80 % of the drawing area in the direction
    /// that limits it.
    void fitScene();
    /// Frames everything that moves (Shift+F): the path and every body drawn, over the whole
    /// horizon.
    void fitEverything();
    /// After the canvas changed size or style: the same kind of fit again, or still centred on
    /// the followed body, or nothing when the user zoomed or panned.
    void refit();
    /// Keeps the view when the path lies in the drawing area (and no longer refits it on a
    /// resize), else fits it (fitScene): a drawn stroke or a moved point does not move the view.
    void keepPathInView();
    /// The next new path (a stroke, a moved point, other corners) keeps the view
    /// (keepPathInView) instead of being fitted.
    void keepViewForNextPath() { m_keepView = true; }
    void setFollowBody(bool follow);
    void setDrawMode(bool on);
    void zoomBy(double factor);
    void setShowVakonomic(bool show);
    void setShowOpenLoop(bool show);
    void setShowClosedLoop(bool show);
    /// Shows or collapses the legend strip under the drawing area (key L).
    void setLegendVisible(bool visible);

  signals:
    /// The user finished drawing a stroke: sampled points in metres, in order.
    void pathDrawn(const std::vector<std::pair<double, double>>& points);
    /// The user moved (drag) or deleted (right click) a vertex of the drawn path in draw mode.
    void pointsEdited(const std::vector<std::pair<double, double>>& points);
    void followBodyChanged(bool follow);
    /// The user dragged the controlled body sideways at time t: a push of pushDy [m] to the
    /// left of its heading (docs/physics.md §9).
    void pushDragged(double t, double pushDy);

  protected:
    void paintEvent(QPaintEvent*) override;
    void wheelEvent(QWheelEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;
    void resizeEvent(QResizeEvent* e) override;

  private:
    void onSolutionChanged();
    /// The view that frames box [m] in the drawing area, with a margin of `margin` [px] on each
    /// side, at no less than minScale.
    void frame(const QRectF& box, double margin, double minScale);
    BodyLook bodyLook() const;
    /// The path's band, the controlled trail and the knife point P again over the bodies drawn
    /// to scale, inside their shapes: no body hides the path (docs/user-guide.md, Animation).
    void paintPathOverBodies(QPainter& p, const MotionSample& now);
    /// The path's band and marks as the static layer has them, on a transparent layer made once
    /// per view when the view is painted a second time; origin: the window's pixel p is the
    /// layer's p + origin. Null at a view's first paint (a zoom step): the band within each
    /// body's box costs less than the whole band, which a view seen once would not repay.
    const QImage& pathLayer(QPoint& origin);
    /// Following: the world layer's pixel under the window's (0, 0).
    QPoint worldLayerOrigin() const;
    /// Following: the map from metres to the world layer's pixels.
    QTransform worldLayerTransform() const;
    QTransform worldTransform() const;
    /// The view's map with its centre at `centre` [m].
    QTransform worldTransformAt(QPointF centre) const;
    /// Grid lines every 1, 2 or 5 x 10^k m, at least 40 px apart.
    double gridStep() const;
    void paintGrid(QPainter& p, const QTransform& world, const QRectF& area) const;
    void paintScaleBar(QPainter& p) const;
    /// The path's band; with `within` [px] only the segments that reach it.
    void paintPath(QPainter& p, const QTransform& world, const QRectF& within = {}) const;
    /// Whether a segment of the path's band reaches `within` [px].
    bool bandReaches(const QTransform& world, const QRectF& within) const;
    /// A trail to draw: its flattened curve up to the parameter `limit` (time, or arc length for
    /// the controlled body), then its end now.
    struct Trail {
        const FlatCurve* curve;
        double limit;
        QPointF end;
        bool byArcLength;
        QPen pen;
    };
    std::vector<Trail> trails(const MotionSample& now) const;
    /// The trails up to now, as far as they reach area [px].
    void paintTrails(QPainter& p, const MotionSample& now, const QRegion& area) const;
    void paintLegend(QPainter& p) const;
    /// The legend's strip, from a layer made once per size, style and shown bodies.
    void paintLegendLayer(QPainter& p);
    void paintTimeReadout(QPainter& p, double tEnd) const;
    void paintBackground();
    /// The static layer onto the widget within region: the cached background, or while following
    /// the body the world layer shifted by whole pixels under the legend and the scale bar; with
    /// the trails up to now in the drawing area, copied from the trail layer.
    void paintStaticLayer(QPainter& p, const QRegion& region, const MotionSample* now);
    /// Brings the trail layer (the static layer `base` with the trails drawn on it; its pixel at
    /// `origin` + p lies under the widget's p) to now: anew when the base or the trails' start
    /// changed, else only where the trails' ends moved since the layer's time, restored from the
    /// base and stroked again there.
    void updateTrailLayer(const MotionSample& now, const QPixmap& base, QPoint origin);
    /// The boxes [px] of the trails, each from its last vertex at or before time `from` to its
    /// end now.
    std::vector<QRectF> trailEndsBounds(const MotionSample& now, double from) const;
    /// Repaints what moved from time `from` (and the view centred on `centre`) to m_time: the
    /// bodies, their arrows and the new end of each trail where that suffices, else the whole
    /// canvas. Following the body, the drawing area's pixels are scrolled by the whole pixels
    /// the view moved, and what scrolling uncovers is repainted with the rest.
    void updateMoving(double from, QPointF centre);
    /// Whether the static layer is the world layer shifted with the followed body.
    bool followsWithWorldLayer() const;
    /// The box [px] of everything that moves drawn at time t, with the trails' vertices
    /// after time `from`.
    QRect movingBounds(const Solution& solution, const MotionSample& now, double from) const;
    void centreOnBody();
    /// The vertices of the current drawn path (empty unless it is a polyline).
    std::vector<std::pair<double, double>> drawnPoints() const;
    /// The vertex within a few pixels of pos, or -1.
    int vertexAt(QPointF pos) const;
    void paintVertices(QPainter& p) const;

    SceneDocument* m_document;
    double m_time = 0;
    double m_scale = 50; // px per metre
    QPointF m_centre;    // world point at the widget centre
    bool m_follow = false;
    std::shared_ptr<const Path> m_fittedPath; // the path the view was last fitted to
    bool m_autoFit = true;   // refit on resize and new solutions until the user zooms or pans
    bool m_fitAll = false;   // the last fit framed everything that moves, not only the path
    bool m_keepView = false; // the next new path is the user's stroke or edit: keep the view
    mutable const Solution* m_boundsOf = nullptr; // the solution m_pathBounds belongs to
    mutable QRectF m_pathBounds;
    bool m_drawMode = false;
    bool m_showVakonomic = true;
    bool m_showOpenLoop = true, m_showClosedLoop = true;
    bool m_panning = false;
    bool m_pushing = false; // dragging the controlled body: a push
    QPointF m_pushFrom;     // world point pressed
    QPointF m_pushTo;       // pixel under the mouse while pushing
    double m_pushTime = 0, m_pushPhi = 0;
    /// Whether the scene's perturbed bodies are there and drawn.
    bool drawsOpenLoop() const;
    bool drawsClosedLoop() const;
    /// Whether a pixel lies on the controlled body at the current time.
    bool onControlledBody(QPointF pixel) const;
    QPointF m_lastMouse;
    std::vector<QPointF> m_stroke; // world points of the stroke being drawn
    int m_dragVertex = -1;         // the vertex being dragged, or -1
    std::vector<std::pair<double, double>> m_editPoints;
    struct BackgroundKey {
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
        bool operator==(const BackgroundKey&) const = default;
    };
    BackgroundKey backgroundKey() const;
    BackgroundKey m_backgroundKey;
    QRect m_movingPainted; // the box of what moves, as last painted
    // following the body: grid and path drawn once over a margin around the view, then shifted
    // by whole pixels (the followed centre snaps to the pixel grid); the legend on its own
    BackgroundKey m_worldKey;
    QPixmap m_worldLayer;
    QPointF m_worldCentre;
    int m_worldMargin = 0;
    BackgroundKey m_legendKey;
    QPixmap m_legendLayer;
    BackgroundKey m_pathKey;
    bool m_pathFollowing = false;
    QImage m_pathLayer;
    BackgroundKey m_pathSeenKey; // the view of the last paint without the layer
    bool m_pathSeenFollowing = false;
    bool m_pathOverBodiesFromLayer = false;
    QPixmap m_background;   // grid, path and legend
    QImage m_trailLayer;    // the static layer with the trails up to m_trailsTime drawn on it
    qint64 m_trailBase = 0; // the cache key of the static layer it was made from
    double m_trailsTime = 0;
    VectorLayer m_vectors;
    BodySprites m_bodies;
    mutable CanvasCurves m_curves;
    /// The body's shape and the ring its outline's pen covers, in metres (body coordinates): the
    /// clips of paintPathOverBodies, made once per solution, zoom and line scale.
    const std::pair<QPainterPath, QPainterPath>& bodyClipShapes() const;
    mutable const Solution* m_bodyClipOf = nullptr;
    mutable double m_bodyClipScale = 0, m_bodyClipPen = 0;
    mutable std::pair<QPainterPath, QPainterPath> m_bodyClips;
    CanvasStyle m_style;
    bool m_legendVisible = true;
    int topBandPx() const;
    /// The draw-mode hint's font and text box (painted in paintLegend).
    QFont drawHintFont() const;
    QRectF drawHintBox() const;
    QString drawHintText() const;
    /// Where the pin key's first row sits: under the draw-mode hint when it is shown.
    QPointF pinKeyOrigin() const;
    int legendBandPx() const;
    /// The legend in two rows of two columns (presentation mode, no pushed bodies), not four
    /// rows: the drawing area keeps the height.
    bool compactLegend() const;
};

} // namespace chaplygin::ui
