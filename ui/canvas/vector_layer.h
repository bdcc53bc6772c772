#pragma once
#include "canvas/vector_painter.h"
#include "scene/solution.h"

#include <QRectF>
#include <QRegion>
#include <QSize>

#include <memory>
#include <vector>

namespace chaplygin::ui {

/// What the scale bars' corner was chosen for: the run, the view (its scale, area and place, to a
/// quarter of the area), the bars' box and the bodies drawn.
struct ScaleBarsPlacement {
    const Solution* solution = nullptr;
    double scale = 0;
    QRectF area;
    QPointF cell;
    QSize box;
    bool vakonomic = false, openLoop = false, closedLoop = false;
    bool operator==(const ScaleBarsPlacement&) const = default;
};

/// The canvas's View > Vectors layer: the shown arrows on the controlled body and on the free
/// ghost, and their scale bars. A quantity without its own scale in the scene is scaled so
/// that its largest value over the run is about the body's size (velocities share one scale,
/// and so do the forces, so that they compare).
class VectorLayer {
  public:
    /// Draws, where they meet repainted, the scale bars in the corner of area. The canvas draws
    /// them before the bodies, so that a body crossing their corner is drawn over them.
    void paintScaleBars(QPainter& painter, const std::shared_ptr<const Solution>& solution,
                        const VectorOverlay& overlay, double pixelsPerMetre, const QRectF& area,
                        const QRegion& repainted);
    /// Draws the arrows and their names, over the bodies.
    void paint(QPainter& painter, const std::shared_ptr<const Solution>& solution,
               const VectorOverlay& overlay, const MotionSample& now, const QTransform& world);

    /// The boxes [px] of the arrows, arcs and labels paint draws for now, one each (none when
    /// none are drawn); the scale bars stay put.
    std::vector<QRectF> bounds(const std::shared_ptr<const Solution>& solution,
                               const VectorOverlay& overlay, const MotionSample& now,
                               const QTransform& world) const;

    /// The box [px] of the scale bars paint draws in the corner of area (empty when none).
    QRect scaleBarsBounds(const VectorOverlay& overlay, const QRectF& area) const;
    /// The box [px] they would take in another corner of area.
    QRect scaleBarsBounds(const VectorOverlay& overlay, const QRectF& area,
                          Qt::Corner corner) const;
    /// The corner of the drawing area the scale bars are drawn in (the bottom right at first;
    /// the canvas moves them off the bodies' way).
    void setBarsCorner(Qt::Corner corner) { m_barsCorner = corner; }
    Qt::Corner barsCorner() const { return m_barsCorner; }
    /// Whether the bars' corner must be chosen again for placement (then kept as chosen for it).
    bool placeBarsAnew(const ScaleBarsPlacement& placement) {
        if (placement == m_placedFor)
            return false;
        m_placedFor = placement;
        return true;
    }

    /// The effective scales (the scene's, else automatic) for a solution.
    VectorScales scales(const std::shared_ptr<const Solution>& solution,
                        const VectorOverlay& overlay) const;

    /// The shapes of the last paint (empty when nothing is shown).
    const VectorShapes& controlledShapes() const { return m_controlled; }
    const VectorShapes& freeShapes() const { return m_free; }
    /// The boxes [px] of the controlled body's labels as the last paint placed them.
    const std::vector<QRectF>& labelBoxes() const { return m_labels; }
    /// Multiplies the pens, arrowheads and type (the canvas style's lineScale: presentation
    /// mode's larger type reaches the arrows' names and the scale bars too).
    void setLineScale(double lineScale) { m_lineScale = lineScale; }
    double lineScale() const { return m_lineScale; }

  private:
    /// The shapes of the free and the controlled body; false when no arrow is shown.
    bool shapes(const std::shared_ptr<const Solution>& solution, const VectorOverlay& overlay,
                const MotionSample& now, const QTransform& world, VectorShapes& free,
                VectorShapes& controlled, VectorScales& k) const;

    mutable std::shared_ptr<const Solution> m_solution; // the one m_auto was computed for
    mutable VectorScales m_auto{};
    VectorShapes m_controlled, m_free;
    std::vector<QRectF> m_labels;
    int m_barsText = 104; // the scale bars' text column [px] (scaleBarsTextWidth)
    double m_lineScale = 1;
    Qt::Corner m_barsCorner = Qt::BottomRightCorner;
    ScaleBarsPlacement m_placedFor;
};

} // namespace chaplygin::ui
