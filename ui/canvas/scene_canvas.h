#pragma once
#include "canvas/body_clip_shapes.h"
#include "canvas/body_painter.h"
#include "canvas/body_sprites.h"
#include "canvas/canvas_style.h"
#include "canvas/canvas_toolbox.h"
#include "canvas/canvas_view.h"
#include "canvas/curve_flattening.h"
#include "canvas/edge_markers.h"
#include "canvas/ink_rows.h"
#include "canvas/layer_cache.h"
#include "canvas/push_tool.h"
#include "canvas/vector_layer.h"
#include "paths/path_source.h"
#include "scene/solution.h"

#include <QPixmap>
#include <QRegion>

#include <QImage>
#include <QPainterPath>
#include <QPen>
#include <QPointF>
#include <QWidget>

#include <array>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace chaplygin::ui {

class SceneDocument;

/// The animation canvas: the prescribed path coloured by curvature, the controlled body to scale
/// at its pose with its trail, and a translucent ghost of the free motion with its own trail.
/// It composes its parts and paints: the view (CanvasView: the metres-to-pixels map, fits,
/// follow, zoom), the mouse's tools of each mode (CanvasTool: draw and edit points in draw mode,
/// push and pan otherwise) and the cached layers (LayerCache).
class SceneCanvas : public QWidget {
    Q_OBJECT
  public:
    explicit SceneCanvas(SceneDocument* document, QWidget* parent = nullptr);

    double time() const { return m_time; }
    bool followsBody() const { return m_view.follows(); }
    bool drawMode() const { return m_tools.drawMode; }
    /// Whether the Plan tool is the mouse's (docs/physics.md §10).
    bool planMode() const { return m_tools.planMode; }
    PlanTool* planTool() const { return m_tools.plan; }
    /// Whether the Measure tool is the mouse's: ruler, protractor and probe (docs/user-guide.md,
    /// Measuring); the scene is left unchanged.
    bool measureMode() const;
    MeasureTool* measureTool() const { return m_tools.measure; }
    /// Whether the pen is the mouse's: marks and arrows over the canvas (docs/user-guide.md,
    /// Drawing over the lesson); the scene is left unchanged.
    bool penMode() const;
    PenTool* penTool() const { return m_tools.pen; }
    /// Whether the genuine vakonomic body (a third body) is drawn.
    bool showsVakonomic() const { return m_look.vakonomic; }
    /// Whether the perturbed bodies are drawn when the scene has a perturbation
    /// (docs/physics.md §9): the open loop and the closed loop.
    bool showsOpenLoop() const { return m_look.openLoop; }
    bool showsClosedLoop() const { return m_look.closedLoop; }
    /// Whether a push is being dragged from the controlled body.
    bool pushing() const { return m_tools.push->active(); }
    /// Pixels per metre.
    double scale() const { return m_view.scale(); }
    /// World point (metres) <-> widget pixel.
    QPointF toPixel(QPointF world) const;
    QPointF toWorld(QPointF pixel) const;
    /// The metres-to-pixels map: pixel = transform.map(world), y up in the world.
    QTransform worldToPixel() const { return m_view.transform(); }
    /// Every curve drawn, flattened at the current scale (docs/architecture.md, ui/: the desktop
    /// application, Canvas).
    const CanvasCurves& curves() const;

    QSize sizeHint() const override { return {800, 500}; }
    /// The markers at the drawing area's edge of the bodies out of view, as last painted: a
    /// click on one frames its body.
    const std::vector<EdgeMarker>& edgeMarkers() const { return m_edgeMarkers.markers(); }
    /// The arrows of View > Vectors as last painted.
    const VectorLayer& vectorLayer() const { return m_vectors; }
    /// The layer itself: tests move its scale bars to a corner of their choice.
    VectorLayer& vectorLayer() { return m_vectors; }
    /// The box [px] of the side view of the wheels (CanvasStyle::wheelInset), in the corner of
    /// the drawing area the bodies cross least over the run, not the scale bars'; empty when it
    /// is not drawn (off, the sleigh, no solution).
    QRectF wheelInsetBounds() const;
    Qt::Corner wheelInsetCorner() const { return m_insetCorner; }
    QSize minimumSizeHint() const override { return {240, 180}; }

    const CanvasStyle& canvasStyle() const { return m_look.style; }
    void setCanvasStyle(const CanvasStyle& style);
    /// The style and the bodies and keys shown, to draw another canvas the same way.
    CanvasLook look() const;
    void setLook(const CanvasLook& look);
    bool legendVisible() const { return m_look.legend; }
    /// The part of the widget the scene is drawn in: between the time line and the legend.
    QRectF drawingArea() const;
    /// Following: the body's size (the diameter of the circle that holds it) is this part of
    /// the drawing area's smaller side at the follow zoom 1.
    static constexpr double kFollowBodyPart = 1.0 / 6;
    /// The scale [px/m] at which the controlled body's size is kFollowBodyPart of the drawing
    /// area's smaller side; 0 without a solution.
    double readableBodyScale() const;
    /// The user's zoom of readableBodyScale while following (kept for the next follow).
    double followZoom() const { return m_view.followZoom(); }
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
    bool fitsEverything() const { return m_view.fitsEverything(); }
    /// The bodies' display drawn now: the chosen one, or what Automatic picks for this scene.
    BodyDisplay shownBodyDisplay() const;
    /// Forgets the cached layers (static layer, trails): the next paint draws everything anew.
    void dropLayers();
    /// Whether the last paint drew the path over the bodies from the path's layer (a view
    /// painted before) rather than within each body's box (a view's first paint).
    bool pathOverBodiesFromLayer() const { return m_pathOverBodies.fromLayer; }
    /// Tests: the path over a body laid over its whole box, not only where ink can be (the
    /// reference the parts must match).
    void setPathOverBodiesWhole(bool whole) {
        m_pathOverBodies.whole = whole;
        update();
    }

  public slots:
    void setTime(double t);
    /// Frames the lesson (F, the default): the path and the controlled body with a margin of
    /// 5 % on each side, the path filling at least 80 % of the drawing area in the direction
    /// that limits it, unless a body shown at the current time would then be cut: then the
    /// path and those bodies, at that scale where they fit in it (the view pans), else smaller.
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
    void keepViewForNextPath() { m_view.setKeepViewForNextPath(true); }
    /// Following the body: centred on it, at the scale where it is kFollowBodyPart of the
    /// drawing area's smaller side (or the scale before, where the body was larger), times the
    /// user's follow zoom; stopping here keeps the view.
    void setFollowBody(bool follow);
    /// The user's follow (B, View > Follow body): as setFollowBody, but stopping returns to the
    /// view before following (the fit, refitted to the canvas's size, or the user's view).
    void setFollowing(bool on);
    void setDrawMode(bool on);
    /// The Plan tool and panning take the mouse; ends draw mode.
    void setPlanMode(bool on);
    /// The Measure tool and panning take the mouse (M on the canvas); ends plan mode.
    void setMeasureMode(bool on);
    /// The pen and panning take the mouse (P on the canvas); ends the Plan and Measure tools.
    void setPenMode(bool on);
    /// Zooms about the centre; following, the follow zoom (the body stays centred).
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
    void planModeChanged(bool on);
    void measureModeChanged(bool on);
    void penModeChanged(bool on);
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
    /// A body drawn at a time: its pose, its colour and whether it is a translucent ghost.
    struct DrawnBody {
        BodyPose pose;
        QColor colour;
        bool ghost;
    };
    /// The bodies shown at `now`: the controlled body first, then the free ghost, and the
    /// vakonomic and pushed bodies where they are drawn.
    std::vector<DrawnBody> drawnBodies(const MotionSample& now) const;
    /// The box [m] of the bodies shown at the current time, as drawn (a marker: their points P).
    std::optional<QRectF> bodiesBounds() const;
    /// The part of the widget the moving scene (bodies, trails, ghosts, pins) is drawn in: the
    /// drawing area and the time line's band above it, under the read-out; not the legend.
    QRectF sceneArea() const;
    /// The edge markers of the bodies out of view at `now` (paintEvent draws them).
    std::vector<EdgeMarker> edgeMarkersAt(const MotionSample& now) const;
    QFont edgeMarkerFont() const;
    /// Brings the world box [m] of a body out of view into the view with what the view shows.
    void frameBody(const QRectF& box);
    /// Frames box [m] in the drawing area with a margin of `margin` [px] on each side, at no
    /// less than minScale and no more than maxScale; the view then refits to the path on a
    /// resize.
    void frame(const QRectF& box, double margin, double minScale,
               double maxScale = CanvasView::kMaxScale);
    BodyLook bodyLook() const;
    /// After a gesture began or ended: the cursor of the gesture under way, else the mode's.
    void updateCursor();
    /// The path's band, the controlled trail and the knife point P again over the bodies drawn
    /// to scale, inside their shapes: no body hides the path (docs/user-guide.md, Animation).
    void paintPathOverBodies(QPainter& p, const MotionSample& now);
    /// The path's band and marks as the static layer has them, from the layer cache; origin:
    /// the window's pixel p is the layer's p + origin. Null at a view's first paint (a zoom
    /// step): the band within each body's box costs less than the whole band, which a view
    /// seen once would not repay.
    const QImage& pathLayer(QPoint& origin);
    /// Following: the world layer's pixel under the window's (0, 0).
    QPoint worldLayerOrigin() const;
    /// Following: the map from metres to the world layer's pixels.
    QTransform worldLayerTransform() const;
    QTransform worldTransform() const { return m_view.transform(); }
    void paintGrid(QPainter& p, const QTransform& world, const QRectF& area) const;
    void paintScaleBar(QPainter& p) const;
    /// The scale bar's label ("5 m"), its font, and the left end [px] of the bar and label.
    QString scaleBarLabel() const;
    QFont scaleBarFont() const;
    double scaleBarLeft() const;
    /// The path's band; with `within` [px] only the segments that reach it, and with `inked`
    /// (within `within`) only their strokes' pixels there: the runs of one colour, which
    /// overlap where the colour changes, are those of `within`, so those pixels are the same.
    void paintPath(QPainter& p, const QTransform& world, const QRectF& within = {},
                   const QRectF& inked = {}) const;
    /// Whether a segment of the path's band reaches `within` [px].
    bool bandReaches(const QTransform& world, const QRectF& within) const;
    /// What paintPath draws, as ink [px]: the band's points and how far its ink reaches from
    /// them, and the marks (start, end, pivots) with theirs.
    QPolygonF bandPoints(const QTransform& world) const;
    double bandInkReach() const;
    std::vector<InkMark> pathMarks(const QTransform& world) const;
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
    /// bodiesDrawn false: a body was too large to draw at this zoom, which the read-out says.
    void paintTimeReadout(QPainter& p, double t, double tEnd, bool bodiesDrawn = true) const;
    /// Plan mode: the chosen motion and how to use the tool, under the time line.
    void paintPlanReadout(QPainter& p) const;
    /// The readout's height [px] (0 outside plan mode): a fit keeps the scene below it.
    double planReadoutHeight() const;
    /// The static layer (grid, path, legend) from the layer cache.
    const QPixmap& background();
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
    /// The boxes [px] of everything that moves drawn at time t, each body, arrow and trail's
    /// end its own (a frame repaints them, not the box around them all), with the trails'
    /// vertices after time `from`.
    QRegion movingBounds(const Solution& solution, const MotionSample& now, double from) const;
    /// The vectors' scale bars in the corner of the drawing area the shown bodies cross least
    /// over the run (the bottom right when none is crossed less): chosen again when the motion,
    /// the zoom, the area or the view's place changes.
    /// How many of the bodies drawn at 49 times of the run cross each box [px].
    std::vector<int> bodiesCrossing(const Solution& solution,
                                    const std::vector<QRectF>& boxes) const;
    void placeScaleBars(const Solution& solution);
    /// The side view of the wheels in its corner, chosen as the scale bars' is, among the
    /// corners they leave.
    void placeWheelInset(const Solution& solution);
    QRectF wheelInsetBounds(Qt::Corner corner) const;
    QFont wheelInsetFont() const;
    void centreOnBody();
    /// The vertices of the current drawn path (empty unless it is a polyline).
    std::vector<std::pair<double, double>> drawnPoints() const;
    /// Whether the scene's perturbed bodies are there and drawn.
    bool drawsOpenLoop() const;
    bool drawsClosedLoop() const;
    /// The controlled body under a pixel at the current time, for a push.
    PushTool::Grab grabAt(QPointF pixel) const;
    LayerKey layerKey() const;
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

    SceneDocument* m_document;
    double m_time = 0;
    CanvasView m_view;
    CanvasLook m_look;     // the style, the bodies shown and the legend
    CanvasToolbox m_tools; // one tool per gesture, and the mode
    struct PathBounds {
        const Solution* of = nullptr; // the solution box belongs to
        QRectF box;                   // [m]
    };
    mutable PathBounds m_pathBounds;
    std::optional<QRegion> m_movingPainted; // the boxes of what moves, as last painted
    LayerCache m_layers;
    // the path over the bodies: whether the last paint took it from the layer, and whether it
    // is laid over each body's whole box (tests)
    struct {
        bool fromLayer = false, whole = false;
    } m_pathOverBodies;
    VectorLayer m_vectors;
    BodySprites m_bodies;
    mutable CanvasCurves m_curves;
    BodyClipShapes m_bodyClips;
    PaintedEdgeMarkers m_edgeMarkers;
    struct WheelInsetPlacement {
        const Solution* solution = nullptr;
        double scale = 0;
        QRectF area;
        QPointF cell;
        QSizeF size;
        Qt::Corner bars = Qt::BottomRightCorner;
        bool barsShown = false;
        bool operator==(const WheelInsetPlacement&) const = default;
    };
    WheelInsetPlacement m_insetPlacedFor;
    Qt::Corner m_insetCorner = Qt::BottomLeftCorner;
};

} // namespace chaplygin::ui
