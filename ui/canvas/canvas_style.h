#pragma once
#include <QColor>
#include <QPen>

#include <optional>
#include <string_view>

class QSettings;

namespace chaplygin::ui {

/// How the bodies are drawn: to scale, as an outline only, or as a small marker with the knife
/// and the centre of mass (so that a large body never hides the path); Automatic (the default)
/// picks one of the three from the body's size against the path's (shownBodyDisplay in
/// canvas/body_painter.h).
enum class BodyDisplay { ToScale, Outline, Marker, Automatic };

/// The display a command-line name asks for: auto, scale, outline or marker; nothing for another
/// name.
std::optional<BodyDisplay> bodyDisplayNamed(std::string_view name);

/// The look of the canvas and the plots: line and font scale, palette, body display, trail width
/// and body opacity. Presentation mode uses a scaled, high-contrast copy.
struct CanvasStyle {
    double lineScale = 1;      ///< multiplies pen widths and font sizes (>= 1)
    bool highContrast = false; ///< a palette whose colours differ in greyscale too
    bool largeTime = false;    ///< a large time read-out on the canvas
    BodyDisplay body = BodyDisplay::Automatic;
    double trailWidth = 2;    ///< px, before lineScale
    double bodyOpacity = 0.8; ///< of the controlled body's fill, 0.1 ... 1
    bool wheelInset = false;  ///< a side view of the disk's or the carriage's wheels turning

    QColor controlled() const;
    QColor free() const;
    /// The third (vakonomic) body, for the canvas and the plots.
    QColor vakonomic() const;
    /// The perturbed bodies (docs/physics.md §9): open loop (the nominal lambda(t)) and closed
    /// loop (feedback).
    QColor openLoop() const;
    QColor closedLoop() const;
    /// The path where the palette does not colour it by curvature.
    QColor path() const;

    /// A cosmetic pen with round caps and joins, width [px] times lineScale.
    QPen pen(const QColor& color, double width, Qt::PenStyle style = Qt::SolidLine) const;

    /// Clamps the numbers into their ranges.
    CanvasStyle sanitized() const;
    /// The user's choices (body display, trail width, opacity, the wheels' side view) from and
    /// to QSettings.
    static CanvasStyle load(const QSettings& settings);
    void save(QSettings& settings) const;
    /// A presentation copy: scaled by factor, high contrast, large time read-out.
    CanvasStyle presentation(double factor) const;

    bool operator==(const CanvasStyle&) const = default;
};

/// What a canvas shows beside the scene itself: its style and which bodies and keys are drawn.
/// An exported animation is drawn with the look of the canvas on the screen.
struct CanvasLook {
    CanvasStyle style;
    bool vakonomic = true;  ///< the genuine vakonomic body
    bool openLoop = true;   ///< the perturbed body under the nominal lambda(t)
    bool closedLoop = true; ///< the perturbed body under feedback
    bool legend = true;     ///< the legend strip under the drawing area

    bool operator==(const CanvasLook&) const = default;
};

/// Relative luminance (ITU-R BT.709) of a colour, 0 (black) ... 1 (white): what a greyscale
/// projector or print shows.
double luminance(const QColor& c);

} // namespace chaplygin::ui
