#pragma once
#include <QPoint>
#include <QRect>

#include <functional>
#include <initializer_list>

class QImage;
class QPainter;
class QPainterPath;

namespace chaplygin::ui {

/// Draws, within box (the painter's logical pixels), the layer's pixels (the layer's pixel
/// origin + p lies under the painter's p; the layer at the painter's integral device pixel
/// ratio; a null layer is transparent), then what `over` paints on them (in the painter's
/// coordinates), keeping only what lies within the areas (paths in the painter's coordinates).
/// The picture of drawing both under a clip path per area, but the areas' antialiased coverage
/// masks a small image instead: Qt rasterises a clip path into spans for every clip set, which
/// cost more than the drawing.
void drawMaskedLayer(QPainter& painter, const QImage& layer, QPoint origin, const QRect& box,
                     std::initializer_list<const QPainterPath*> areas,
                     const std::function<void(QPainter&)>& over);

} // namespace chaplygin::ui
