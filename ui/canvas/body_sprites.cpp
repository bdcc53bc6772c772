#include "canvas/body_sprites.h"

#include <QPainter>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace chaplygin::ui {

namespace {

constexpr std::size_t kSprites = 6;       // controlled, free and vakonomic, with room to spare
constexpr double kLargestSpritePx = 1536; // larger bodies are drawn directly
// a body larger still is not drawn: Qt flattens an outline's whole length, seconds at 10^9 px
// (a body a metre or two long at the zoom range's end, 10^5 px/m, is some 10^5 px)
constexpr double kLargestBodyPx = 4e6;
constexpr double kBandDevicePx = 64; // rows of a turned image drawn at once
constexpr int kMostBands = 64;

// the radius [px] around P that holds the body and its pens (the widest is 4 px, scaled)
double radiusPx(double pixelsPerMetre, const SystemSpec& spec, const DerivedSystem& derived,
                const BodyLook& look) {
    double lineScale = std::clamp(look.lineScale, 0.5, 4.0);
    double pad = 3 + 3 * lineScale;
    if (look.display == BodyDisplay::Marker) // knife 1.3 r, centre of mass at 2 r + 0.45 r
        return 2.5 * kMarkerRadiusPx * lineScale + pad;
    return bodyExtent(spec, derived) * pixelsPerMetre + pad;
}

// The box [logical px of the image] paintBody may cover: the body's box with its pens (the
// whole image for a marker, whose size is in pixels)
QRectF inkInImage(double centre, double pixelsPerMetre, const SystemSpec& spec,
                  const DerivedSystem& derived, const BodyLook& look) {
    const QRectF whole(0, 0, 2 * centre, 2 * centre);
    if (look.display == BodyDisplay::Marker)
        return whole;
    const double pad = 4 + 3 * std::clamp(look.lineScale, 0.5, 4.0);
    const QRectF body = bodyBounds(spec, derived, {});
    // y up in the body's frame, down in the image
    return QRectF(centre + body.left() * pixelsPerMetre - pad,
                  centre - body.bottom() * pixelsPerMetre - pad,
                  body.width() * pixelsPerMetre + 2 * pad, body.height() * pixelsPerMetre + 2 * pad)
        .intersected(whole);
}

// The columns [px] the convex polygon q covers between the rows top and bottom (none when it
// does not reach them)
std::optional<std::pair<double, double>> columnsWithin(const QPolygonF& q, double top,
                                                       double bottom) {
    double left = std::numeric_limits<double>::infinity(), right = -left;
    auto take = [&](double x) {
        left = std::min(left, x);
        right = std::max(right, x);
    };
    for (qsizetype i = 0; i < q.size(); ++i) {
        const QPointF a = q[i], b = q[(i + 1) % q.size()];
        if (a.y() >= top && a.y() <= bottom)
            take(a.x());
        for (double row : {top, bottom})
            if ((a.y() - row) * (b.y() - row) < 0)
                take(a.x() + (b.x() - a.x()) * (row - a.y()) / (b.y() - a.y()));
    }
    if (!(left <= right))
        return std::nullopt;
    return std::pair{left, right};
}

} // namespace

QRectF BodySprites::pixelBounds(const QTransform& world, double pixelsPerMetre,
                                const SystemSpec& spec, const DerivedSystem& derived,
                                const BodyPose& pose, const BodyLook& look) {
    double r = radiusPx(pixelsPerMetre, spec, derived, look) + 1;
    QPointF c = world.map(QPointF(pose.x, pose.y));
    return {c.x() - r, c.y() - r, 2 * r, 2 * r};
}

const BodySprites::Sprite* BodySprites::find(const Key& key, const SystemSpec& spec,
                                             const DerivedSystem& derived, const QColor& color,
                                             const BodyLook& look) {
    for (const Sprite& s : m_sprites)
        if (s.key == key)
            return &s;
    double centre = std::ceil(radiusPx(key.pixelsPerMetre, spec, derived, look));
    if (!(2 * centre * key.dpr <= kLargestSpritePx))
        return nullptr;
    Sprite s;
    s.key = key;
    s.centre = centre;
    s.ink = inkInImage(centre, key.pixelsPerMetre, spec, derived, look);
    int side = int(std::ceil(2 * centre * key.dpr));
    s.image = QImage(side, side, QImage::Format_ARGB32_Premultiplied);
    s.image.setDevicePixelRatio(key.dpr);
    s.image.fill(Qt::transparent);
    {
        QPainter p(&s.image);
        p.setRenderHint(QPainter::Antialiasing, true);
        p.translate(centre, centre);
        p.scale(key.pixelsPerMetre, -key.pixelsPerMetre);
        paintBody(p, spec, derived, {}, color, key.ghost, look);
    }
    if (m_sprites.size() < kSprites) {
        m_sprites.push_back(std::move(s));
        return &m_sprites.back();
    }
    Sprite& slot = m_sprites[m_next];
    m_next = (m_next + 1) % kSprites;
    slot = std::move(s);
    return &slot;
}

bool BodySprites::paint(QPainter& painter, const QTransform& world, double pixelsPerMetre,
                        const SystemSpec& spec, const DerivedSystem& derived, const BodyPose& pose,
                        const QColor& color, bool ghost, const BodyLook& look) {
    Key key{spec,           derived.a,
            derived.b,      color.rgba(),
            ghost,          look.display,
            look.opacity,   look.lineScale,
            pixelsPerMetre, painter.device()->devicePixelRatioF()};
    const Sprite* sprite = std::isfinite(pose.x) && std::isfinite(pose.y) &&
                                   std::isfinite(pose.phi) && pixelsPerMetre > 0
                               ? find(key, spec, derived, color, look)
                               : nullptr;
    if (!sprite) {
        const QRectF bounds = pixelBounds(world, pixelsPerMetre, spec, derived, pose, look);
        if (!(std::max(bounds.width(), bounds.height()) <= kLargestBodyPx))
            return false;
        painter.save();
        painter.setTransform(world);
        paintBody(painter, spec, derived, pose, color, ghost, look);
        painter.restore();
        return true;
    }
    painter.save();
    // the turned image's rows are cut at the body's box whatever the repainted region, so
    // that a partial repaint resamples them as a full one does; only what the painter may
    // change (a body far off the view is not drawn: its box in int pixels could overflow)
    const QRectF reach =
        painter.hasClipping() ? painter.clipBoundingRect() : QRectF(painter.window());
    const QRect box = pixelBounds(world, pixelsPerMetre, spec, derived, pose, look)
                          .intersected(reach)
                          .toAlignedRect();
    if (box.isEmpty()) {
        painter.restore();
        return true;
    }
    const QTransform base = painter.transform();
    // image pixels -> the body's frame [m] -> the world -> the widget
    const double s = pixelsPerMetre, c = sprite->centre;
    QTransform toBody(1 / s, 0, 0, -1 / s, -c / s, c / s);
    QTransform pose2d;
    pose2d.translate(pose.x, pose.y);
    pose2d.rotate(pose.phi * 180.0 / M_PI);
    // the image's margin is transparent: its own edges need no antialiasing
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setRenderHint(QPainter::SmoothPixmapTransform, true);
    // in bands of whole rows: Qt resamples a row the same whichever band it is in, and a band's
    // rows stay fewer than the batch of spans that Qt would hand to its thread pool (waking
    // threads and waiting for them costs more than the band's resampling)
    int band = std::max(1, int(kBandDevicePx / painter.device()->devicePixelRatioF()));
    if (box.height() > kMostBands * band) // zoomed far in: one call, whatever Qt then does
        band = box.height();
    const bool clipped = painter.hasClipping();
    const QRegion clip = clipped ? painter.clipRegion() : QRegion();
    const QTransform place = toBody * pose2d * world;
    // the turned box of the body's ink: a band resamples only the columns it crosses (and two
    // on each side, where the smooth turn reaches), not the transparent rest of the image
    const QPolygonF ink = place.map(QPolygonF(sprite->ink));
    for (int top = box.top(); top <= box.bottom(); top += band) {
        const int rows = std::min(band, box.bottom() + 1 - top);
        const auto columns = columnsWithin(ink, top - 2, top + rows + 2);
        if (!columns)
            continue;
        const int left = std::max(box.left(), int(std::floor(columns->first)) - 2);
        const int right = std::min(box.right(), int(std::ceil(columns->second)) + 2);
        if (right < left)
            continue;
        painter.setTransform(base);
        painter.setClipRect(QRect(left, top, right + 1 - left, rows));
        if (clipped)
            painter.setClipRegion(clip, Qt::IntersectClip);
        painter.setTransform(place);
        painter.drawImage(QPointF(0, 0), sprite->image);
    }
    painter.restore();
    return true;
}

} // namespace chaplygin::ui
