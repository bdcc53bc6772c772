#include "canvas/canvas_style.h"

#include <QSettings>

#include <algorithm>
#include <cmath>

namespace chaplygin::ui {

std::optional<BodyDisplay> bodyDisplayNamed(std::string_view name) {
    if (name == "auto")
        return BodyDisplay::Automatic;
    if (name == "scale")
        return BodyDisplay::ToScale;
    if (name == "outline")
        return BodyDisplay::Outline;
    if (name == "marker")
        return BodyDisplay::Marker;
    return std::nullopt;
}

namespace {
// normal palette (the matplotlib defaults the exported plots use)
const QColor kControlled(0x1f, 0x77, 0xb4);
const QColor kFree(0xd6, 0x27, 0x28);
const QColor kVakonomic(0x94, 0x67, 0xbd);
const QColor kPath(0x7f, 0x7f, 0x7f);
const QColor kOpenLoop(0xff, 0x7f, 0x0e);
const QColor kClosedLoop(0x2c, 0xa0, 0x2c);
// high contrast: well separated grey levels (luminance 0.02, 0.12, 0.26, 0.46; the perturbed
// bodies 0.35 and 0.57)
const QColor kHcControlled(0x00, 0x1f, 0x7a);
const QColor kHcVakonomic(0xb0, 0x00, 0xb0);
const QColor kHcFree(0xff, 0xa0, 0x00);
const QColor kHcPath(0x8c, 0x8c, 0x8c);
const QColor kHcOpenLoop(0xff, 0x70, 0xa0);
const QColor kHcClosedLoop(0x40, 0xe4, 0x60);

QString key(const char* name) {
    return QStringLiteral("canvas/") + QLatin1String(name);
}
} // namespace

double luminance(const QColor& c) {
    auto lin = [](double v) {
        return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
    };
    return 0.2126 * lin(c.redF()) + 0.7152 * lin(c.greenF()) + 0.0722 * lin(c.blueF());
}

QColor CanvasStyle::controlled() const {
    return highContrast ? kHcControlled : kControlled;
}

QColor CanvasStyle::free() const {
    return highContrast ? kHcFree : kFree;
}

QColor CanvasStyle::vakonomic() const {
    return highContrast ? kHcVakonomic : kVakonomic;
}

QColor CanvasStyle::openLoop() const {
    return highContrast ? kHcOpenLoop : kOpenLoop;
}

QColor CanvasStyle::closedLoop() const {
    return highContrast ? kHcClosedLoop : kClosedLoop;
}

QPen CanvasStyle::pen(const QColor& color, double width, Qt::PenStyle style) const {
    QPen pen(color, width * lineScale, style);
    pen.setCosmetic(true);
    pen.setCapStyle(Qt::RoundCap);
    pen.setJoinStyle(Qt::RoundJoin);
    return pen;
}

QColor CanvasStyle::path() const {
    return highContrast ? kHcPath : kPath;
}

CanvasStyle CanvasStyle::sanitized() const {
    CanvasStyle s = *this;
    auto clamp = [](double v, double lo, double hi, double fallback) {
        return std::isfinite(v) ? std::clamp(v, lo, hi) : fallback;
    };
    s.lineScale = clamp(lineScale, 1, 4, 1);
    s.trailWidth = clamp(trailWidth, 0.5, 12, 2);
    s.bodyOpacity = clamp(bodyOpacity, 0.1, 1, 0.8);
    if (body != BodyDisplay::ToScale && body != BodyDisplay::Outline &&
        body != BodyDisplay::Marker && body != BodyDisplay::Automatic)
        s.body = BodyDisplay::Automatic;
    return s;
}

CanvasStyle CanvasStyle::load(const QSettings& settings) {
    CanvasStyle s;
    // "bodyDisplay", not the older "body": that key held the to-scale default saved at every
    // start, not a choice, and would keep the automatic display from its users
    s.body = static_cast<BodyDisplay>(settings.value(key("bodyDisplay"), int(s.body)).toInt());
    s.trailWidth = settings.value(key("trailWidth"), s.trailWidth).toDouble();
    s.bodyOpacity = settings.value(key("bodyOpacity"), s.bodyOpacity).toDouble();
    s.wheelInset = settings.value(key("wheelInset"), s.wheelInset).toBool();
    return s.sanitized();
}

void CanvasStyle::save(QSettings& settings) const {
    settings.setValue(key("bodyDisplay"), int(body));
    settings.setValue(key("trailWidth"), trailWidth);
    settings.setValue(key("bodyOpacity"), bodyOpacity);
    settings.setValue(key("wheelInset"), wheelInset);
}

CanvasStyle CanvasStyle::presentation(double factor) const {
    CanvasStyle s = *this;
    s.lineScale = factor;
    s.highContrast = true;
    s.largeTime = true;
    return s.sanitized();
}

} // namespace chaplygin::ui
