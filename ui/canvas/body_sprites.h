#pragma once
#include "canvas/body_painter.h"

#include <QImage>
#include <QTransform>

#include <vector>

namespace chaplygin::ui {

/// The canvas's bodies, each drawn once by paintBody into an image at the canvas's scale and
/// then only placed and turned each frame. Source-over compositing is associative, so the image
/// laid over the canvas gives what drawing its shapes onto the canvas gives, but for the
/// resampling of the turn (smooth, under a pixel). A body too large for an image at this zoom
/// is drawn directly.
class BodySprites {
  public:
    /// Draws the body at pose; world maps metres to widget pixels (scale pixelsPerMetre, y up).
    /// False when the body is too large at this zoom to be drawn (over 4·10^6 px): it is not.
    bool paint(QPainter& painter, const QTransform& world, double pixelsPerMetre,
               const SystemSpec& spec, const DerivedSystem& derived, const BodyPose& pose,
               const QColor& color, bool ghost, const BodyLook& look);

    /// The bounding box [px] of the body drawn at pose, with its pens' widths.
    static QRectF pixelBounds(const QTransform& world, double pixelsPerMetre,
                              const SystemSpec& spec, const DerivedSystem& derived,
                              const BodyPose& pose, const BodyLook& look);

  private:
    struct Key {
        SystemSpec spec;
        double a = 0, b = 0;
        QRgb color = 0;
        bool ghost = false;
        BodyDisplay display = BodyDisplay::ToScale;
        double opacity = 0, lineScale = 0;
        double pixelsPerMetre = 0;
        qreal dpr = 0;
        bool operator==(const Key&) const = default;
    };
    struct Sprite {
        Key key;
        QImage image;
        double centre = 0; ///< P in the image [logical px from its corner]
        QRectF ink;        ///< what paintBody may cover, pens included [logical px]
    };
    const Sprite* find(const Key& key, const SystemSpec& spec, const DerivedSystem& derived,
                       const QColor& color, const BodyLook& look);

    std::vector<Sprite> m_sprites; // the few bodies on screen, the oldest replaced first
    std::size_t m_next = 0;
};

} // namespace chaplygin::ui
