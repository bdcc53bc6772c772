#pragma once
#include <QPoint>
#include <QRegion>

class QImage;
class QPainter;
class QPixmap;

namespace chaplygin::ui {

/// Copies the layer's pixels onto the painter's device within region (the painter's logical
/// pixels), the layer's pixel at `origin` + p landing on p. Rectangle by rectangle: under a
/// rectangular clip Qt's raster engine copies the rows itself, while under a region of several
/// rectangles it fills spans, and hands batches of more than about a hundred spans to its
/// thread pool, waking threads and waiting for them. The layer's device pixel ratio is the
/// painter's; a fractional one copies the whole layer under the region.
void blitRegion(QPainter& painter, const QRegion& region, const QPixmap& layer, QPoint origin = {});
void blitRegion(QPainter& painter, const QRegion& region, const QImage& layer, QPoint origin = {});

} // namespace chaplygin::ui
