#pragma once
#include <QColor>
#include <QFont>
#include <QPointF>
#include <QRectF>
#include <QRegion>
#include <QString>
#include <QTransform>

#include <vector>

class QPainter;

namespace chaplygin::ui {

/// A body drawn on the canvas, as the edge markers see it.
struct ShownBody {
    QColor colour;
    QPointF at;      ///< its point P [m]
    QRectF bounds;   ///< the box [px] the body is drawn in
    QRectF worldBox; ///< the box [m] a click on its marker frames
};

/// A body out of view, pointed at from the drawing area's edge: an arrowhead in its colour at
/// the edge, on the line from the area's centre to the body, and its distance beyond the edge.
struct EdgeMarker {
    QColor colour;
    QPointF tip;         ///< [px] the arrowhead's point, just inside the drawing area's edge
    QPointF toward;      ///< unit vector [px] from the area's centre toward the body
    QRectF textBox;      ///< [px] the distance's box, behind the arrowhead
    QRectF box;          ///< [px] the arrowhead and its text: what a click hits
    double distance = 0; ///< [m] from the tip to the body's P
    QString text;        ///< the distance as shown, "12.3 m away"
    QRectF worldBox;     ///< [m] the body's box (ShownBody::worldBox)
};

/// The markers, at the edge of area [px], of the bodies whose box lies wholly outside visible
/// [px] (the area and what else of the widget shows the scene); world maps metres to pixels.
/// Markers that would overlap move along the edge, so that each stays readable and clickable.
/// lineScale multiplies their size and type (presentation mode's).
std::vector<EdgeMarker> layoutEdgeMarkers(const std::vector<ShownBody>& bodies, const QRectF& area,
                                          const QRectF& visible, const QTransform& world,
                                          const QFont& font, double lineScale);

/// Draws the markers; font as given to layoutEdgeMarkers.
void paintEdgeMarkers(QPainter& painter, const std::vector<EdgeMarker>& markers, const QFont& font,
                      double lineScale);

/// The markers a canvas last painted and the pixels they covered: a click finds its marker there,
/// and the next frame repaints where they were.
class PaintedEdgeMarkers {
  public:
    /// Draws markers (paintEdgeMarkers) and keeps them.
    void paint(QPainter& painter, std::vector<EdgeMarker> markers, const QFont& font,
               double lineScale);
    void clear();
    const std::vector<EdgeMarker>& markers() const { return m_markers; }
    /// The markers' boxes as last painted, with their pens' reach.
    const QRegion& painted() const { return m_painted; }

  private:
    std::vector<EdgeMarker> m_markers;
    QRegion m_painted;
};

} // namespace chaplygin::ui
