#pragma once
#include "canvas/canvas_tool.h"

#include <QPointF>
#include <QRectF>
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>

namespace chaplygin::ui {

class CanvasCurves;
class CanvasView;
class SceneDocument;
struct CanvasStyle;

/// Measuring on the canvas, which leaves the scene unchanged: a drag is a ruler (its length [m]
/// and direction [deg]); a drag from an end of the ruler is the protractor's second arm (the
/// angle between the two); a drag from a body is measured from its heading; hovering the path or
/// a trail probes the motion at its nearest point (t, s, x, y, phi, kappa, rho, Psi, exact
/// values from the document's Solution). The ends snap to the bodies, the path's ends, the
/// ruler's ends, then the path and the trails, within a few pixels.
class MeasureTool : public CanvasTool {
    Q_OBJECT
  public:
    /// What the canvas shows now: its time [s], which of the other bodies are drawn, and the
    /// curves as drawn (the path and the trails flattened at the view's scale).
    struct Shown {
        double time = 0;
        bool vakonomic = true, openLoop = false, closedLoop = false;
        const CanvasCurves* curves = nullptr;
        QRectF area; ///< the drawing area [px]: the read-outs stay inside it
    };
    /// The bodies whose path or trail a probe reads: the controlled body along the path, the
    /// free ghost, the genuine vakonomic body and the two perturbed bodies.
    enum class Body { Controlled, Free, Vakonomic, OpenLoop, ClosedLoop };
    /// A measured segment [m]; `heading` [rad] when its start snapped to a body.
    struct Arm {
        QPointF from, to;
        std::optional<double> heading;
        double length() const;
        /// Counter-clockwise from the x axis, in (-pi, pi] [rad].
        double direction() const;
    };
    /// The motion at the nearest point of a path or trail (SI units; NaN where the body has no
    /// such value: s off the path).
    struct Probe {
        Body body = Body::Controlled;
        double t = 0, s = 0, x = 0, y = 0, phi = 0, kappa = 0, psi = 0;
        QPointF pixel; ///< where it is drawn
    };

    MeasureTool(const CanvasView& view, const CanvasStyle& style, const SceneDocument* document,
                std::function<Shown()> shown, QObject* parent);

    /// Whether the canvas's mouse measures (Edit > Measure, M on the canvas).
    bool enabled() const { return m_enabled; }
    /// Turns measuring on or off; off forgets what was measured.
    void setEnabled(bool on);
    /// Forgets the arms and the probe.
    void clear();

    bool press(const QMouseEvent& e) override;
    bool move(const QMouseEvent& e) override;
    void release(const QMouseEvent& e) override;
    bool hover(const QMouseEvent& e) override;
    bool active() const override { return m_dragging; }
    void cancel() override;
    Qt::CursorShape cursor() const override { return Qt::CrossCursor; }
    void paint(QPainter& p) const override;

    /// The ruler: the last drag, or the protractor's second arm.
    const std::optional<Arm>& ruler() const { return m_ruler; }
    /// The protractor's first arm (the ruler before the drag that started at its end).
    const std::optional<Arm>& firstArm() const { return m_first; }
    /// The angle between the protractor's arms at their common vertex, 0 ... pi [rad].
    std::optional<double> protractorAngle() const;
    /// The ruler's direction from the heading of the body it starts on, (-pi, pi] [rad].
    std::optional<double> headingAngle() const;
    const std::optional<Probe>& probe() const { return m_probe; }
    /// The read-out's lines of the ruler (and protractor) and of the probe.
    QStringList rulerText() const;
    QStringList probeText() const;

  private:
    struct Snap {
        QPointF world;
        std::optional<double> heading;
    };
    /// The point a press or a move at `pixel` means: a body, an end of the path or of the
    /// ruler, else the nearest point of the path or a trail, within the snapping distance.
    Snap snap(QPointF pixel) const;
    /// The nearest point of the path or a drawn trail within the probing distance, if any.
    std::optional<Probe> probeAt(QPointF pixel) const;
    double snapPx() const;
    /// A read-out's box with its top left corner at `at` [px], `gap` [px] right of and below its
    /// point; awayFromMiddle: on the side of the point away from the widget's middle.
    void paintLabel(QPainter& p, QPointF at, double gap, const QStringList& lines,
                    bool awayFromMiddle) const;

    const CanvasView& m_view;
    const CanvasStyle& m_style;
    const SceneDocument* m_document;
    std::function<Shown()> m_shown;
    bool m_enabled = false;
    bool m_dragging = false;
    bool m_fromRulerEnd = false; // the drag under way started at an end of the ruler
    std::optional<Arm> m_first, m_ruler;
    std::optional<Probe> m_probe;
};

} // namespace chaplygin::ui
