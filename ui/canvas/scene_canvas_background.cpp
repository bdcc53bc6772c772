#include "canvas/scene_canvas.h"
#include "canvas/trail_stroke.h"

#include "canvas/layer_blit.h"
#include "canvas/legend_text.h"
#include "document/scene_document.h"

#include <QFontMetricsF>
#include <QLineF>
#include <QPainter>

#include <algorithm>
#include <cmath>

// the canvas's static layer: grid, path and legend, drawn into a pixmap that is redrawn only
// when the view or the solution changes
namespace chaplygin::ui {

namespace {

// the draw-mode hint wraps to the canvas's width
constexpr int kDrawHintFlags = Qt::AlignLeft | Qt::TextWordWrap;

// curvature colour: grey when straight, blue for left turns (kappa > 0), red for right turns
QColor curvatureColor(double kappa) {
    double w = std::tanh(std::abs(kappa));
    QColor turn = kappa > 0 ? QColor(40, 90, 230) : QColor(220, 60, 40);
    QColor flat(150, 150, 150);
    return QColor::fromRgbF(flat.redF() + w * (turn.redF() - flat.redF()),
                            flat.greenF() + w * (turn.greenF() - flat.greenF()),
                            flat.blueF() + w * (turn.blueF() - flat.blueF()));
}

// halfway to white, opaque (overlapping segments do not darken)
QColor pale(const QColor& c) {
    return QColor::fromRgbF(0.5 + 0.5 * c.redF(), 0.5 + 0.5 * c.greenF(), 0.5 + 0.5 * c.blueF());
}

} // namespace

void SceneCanvas::paintGrid(QPainter& p, const QTransform& world, const QRectF& area) const {
    double step = m_view.gridStep();
    const QTransform toWorld = world.inverted();
    QPointF a = toWorld.map(area.bottomLeft()), b = toWorld.map(area.topRight());
    // each line a run of whole device pixels, filled: a stroked line at a fractional position
    // is two half-toned pixels wide, laid out by the cosmetic stroker pixel by pixel
    const double s = std::abs(p.deviceTransform().m11());
    const double thick = std::max(1.0, std::round(m_look.style.lineScale)); // [device px]
    p.save();
    p.setRenderHint(QPainter::Antialiasing, false);
    p.setPen(Qt::NoPen);
    auto vertical = [&](double x, const QColor& c) { // x in world units
        const double px = std::round(s * world.map(QPointF{x, 0}).x() - 0.5 * thick) / s;
        p.fillRect(QRectF(px, area.top(), thick / s, area.height()), c);
    };
    auto horizontal = [&](double y, const QColor& c) {
        const double py = std::round(s * world.map(QPointF{0, y}).y() - 0.5 * thick) / s;
        p.fillRect(QRectF(area.left(), py, area.width(), thick / s), c);
    };
    // counted, not accumulated: far from the origin x + step may round back to x
    const double kx0 = std::floor(a.x() / step), kx1 = std::ceil(b.x() / step);
    const double ky0 = std::floor(a.y() / step), ky1 = std::ceil(b.y() / step);
    const bool countable =
        std::max({std::abs(kx0), std::abs(kx1), std::abs(ky0), std::abs(ky1)}) < 1e15;
    if (countable && kx1 - kx0 < 2000 && ky1 - ky0 < 2000) {
        const QColor line(232, 232, 232);
        for (double k = kx0; k <= kx1; ++k)
            vertical(k * step, line);
        for (double k = ky0; k <= ky1; ++k)
            horizontal(k * step, line);
    }
    const QColor axis(200, 200, 200);
    horizontal(0, axis);
    vertical(0, axis);
    p.restore();
}

QString SceneCanvas::scaleBarLabel() const {
    const double step = m_view.gridStep();
    return step >= 1 ? QStringLiteral("%1 m").arg(step) : QStringLiteral("%1 cm").arg(step * 100);
}

QFont SceneCanvas::scaleBarFont() const {
    QFont f = font();
    f.setPointSizeF(8 * m_look.style.lineScale);
    return f;
}

double SceneCanvas::scaleBarLeft() const {
    // the bar, one grid step long, ends 14 px from the right; its label is centred over it
    const double len = m_view.gridStep() * m_view.scale();
    const double centre = width() - 14 - len / 2;
    const double label = QFontMetricsF(scaleBarFont(), this).horizontalAdvance(scaleBarLabel());
    return std::min(centre - len / 2, centre - label / 2);
}

void SceneCanvas::paintScaleBar(QPainter& p) const {
    double step = m_view.gridStep();
    // scale bar, top right: one grid step
    double len = step * m_view.scale();
    QPointF right(width() - 14, topBandPx() - 2), left = right - QPointF(len, 0);
    p.setPen(m_look.style.pen(QColor(60, 60, 60), 1.5));
    p.drawLine(left, right);
    p.drawLine(left, left - QPointF(0, 5));
    p.drawLine(right, right - QPointF(0, 5));
    p.setFont(scaleBarFont());
    p.drawText(QRectF(left.x() - 40, left.y() - 8 - 14 * m_look.style.lineScale, len + 80,
                      14 * m_look.style.lineScale),
               Qt::AlignCenter, scaleBarLabel());
}

namespace {

// whether the segment from `from` to `to` [px], drawn `reach` px wide on each side, reaches
// `within`
bool segmentReaches(QPointF from, QPointF to, double reach, const QRectF& within) {
    return QRectF(from, to).normalized().adjusted(-reach, -reach, reach, reach).intersects(within);
}

// half the band's width, and more [px]
double bandReach(double lineScale) {
    return 3 * lineScale + 2;
}

} // namespace

bool SceneCanvas::bandReaches(const QTransform& world, const QRectF& within) const {
    const FlatCurve& flat = curves().path();
    const double reach = bandReach(m_look.style.lineScale);
    QPointF to = flat.points.empty() ? QPointF() : world.map(flat.points[0]);
    for (std::size_t i = 1; i < flat.points.size(); ++i) {
        const QPointF from = to;
        to = world.map(flat.points[i]);
        if (segmentReaches(from, to, reach, within))
            return true;
    }
    return false;
}

QPolygonF SceneCanvas::bandPoints(const QTransform& world) const {
    const FlatCurve& flat = curves().path();
    QPolygonF band;
    band.reserve(qsizetype(flat.points.size()));
    for (const QPointF& point : flat.points)
        band << world.map(point);
    return band;
}

double SceneCanvas::bandInkReach() const {
    return bandReach(m_look.style.lineScale);
}

namespace {

// the path's marks: circles of radius 5 (pivots) and 4 (start), a square 8 px wide (end), all
// with a pen 1.5 px wide, reach less than this [px] from their centres
double pathMarkReach(double lineScale) {
    return 8 + 1.5 * lineScale;
}

} // namespace

std::vector<InkMark> SceneCanvas::pathMarks(const QTransform& world) const {
    const auto& solution = m_document->solution();
    if (!solution)
        return {};
    const double reach = pathMarkReach(m_look.style.lineScale);
    const Path& path = *solution->path();
    std::vector<InkMark> marks;
    for (const PathPiece& piece : path.pieces())
        if (piece.kind == PathPiece::Kind::Pivot)
            marks.push_back({world.map(QPointF{piece.x, piece.y}), reach});
    marks.push_back({world.map(QPointF{path.start().x, path.start().y}), reach});
    marks.push_back({world.map(QPointF{path.end().x, path.end().y}), reach});
    return marks;
}

void SceneCanvas::paintPath(QPainter& p, const QTransform& world, const QRectF& within,
                            const QRectF& inked) const {
    const auto& solution = m_document->solution();
    // a wide pale band, so that the trail on top of it stays visible: one polyline per run of
    // one colour, through the flattened curve
    const FlatCurve& flat = curves().path();
    auto colourOf = [&](std::size_t i) {
        if (m_look.style.highContrast)
            return m_look.style.path().rgb();
        const double kappa = 0.5 * (flat.kappa[i - 1] + flat.kappa[i]);
        return pale(curvatureColor(std::isnan(kappa) ? 0 : kappa)).rgb();
    };
    const QRegion area = !inked.isNull()   ? QRegion(inked.toAlignedRect())
                         : within.isNull() ? paintableArea(p)
                                           : QRegion(within.toAlignedRect());
    QPolygonF run;
    QRgb runColour = 0;
    auto flush = [&] {
        if (run.size() > 1) {
            QPen pen = m_look.style.pen(QColor(runColour), 6);
            pen.setCapStyle(Qt::FlatCap);
            strokePolylineWithin(p, run, pen, area); // clipped: a zoomed-in band is huge
        }
        run.clear();
    };
    const double reach = bandReach(m_look.style.lineScale);
    // each point mapped once: `from` is point i - 1 in pixels, `to` point i
    QPointF to = flat.points.empty() ? QPointF() : world.map(flat.points[0]);
    for (std::size_t i = 1; i < flat.points.size(); ++i) {
        const QPointF from = to;
        to = world.map(flat.points[i]);
        if (!within.isNull()) {
            // only the segments that reach `within`: a run ends at a segment left out
            if (!segmentReaches(from, to, reach, within)) {
                flush();
                continue;
            }
        }
        const QRgb c = colourOf(i);
        if (c != runColour || run.isEmpty()) {
            // a run of the next colour starts over the last `reach` px of the one before:
            // their antialiased flat ends would leave a light seam across the band where they
            // meet
            QPolygonF overlap;
            double back = 0;
            for (qsizetype k = run.size() - 1; k > 0 && back < reach; --k) {
                back += QLineF(run[k - 1], run[k]).length();
                overlap.prepend(run[k - 1]);
            }
            flush();
            runColour = c;
            run = overlap;
            run << from;
        }
        run << to;
    }
    flush();
    // the marks: within pathMarkReach of their centres
    for (const PathPiece& piece : solution->path()->pieces()) {
        if (piece.kind != PathPiece::Kind::Pivot)
            continue;
        p.setPen(m_look.style.pen(QColor(120, 60, 160), 1.5));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(world.map(QPointF{piece.x, piece.y}), 5, 5);
    }
    // start (filled) and end (open) of the path
    const Path& path = *solution->path();
    p.setPen(m_look.style.pen(QColor(40, 40, 40), 1.5));
    p.setBrush(QColor(40, 40, 40));
    p.drawEllipse(world.map(QPointF{path.start().x, path.start().y}), 4, 4);
    p.setBrush(Qt::white);
    p.drawRect(
        QRectF(world.map(QPointF{path.end().x, path.end().y}) - QPointF(4, 4), QSizeF(8, 8)));
}

void SceneCanvas::paintLegend(QPainter& p) const {
    // the legend has its own strip under the drawing area: nothing moves under it
    const double k = m_look.style.lineScale;
    QFont f = font();
    f.setPointSizeF(9 * k);
    p.setFont(f);
    if (m_look.legend) {
        QRectF band(0, height() - legendBandPx(), width(), legendBandPx());
        p.fillRect(band, QColor(246, 246, 246));
        p.setPen(m_look.style.pen(QColor(200, 200, 200), 1));
        p.drawLine(band.topLeft(), band.topRight());
        double y = band.top() + 8 * k, dy = 16 * k, x = 10, len = 24 * k;
        // the perturbed bodies in a second column (docs/physics.md §9); the compact legend puts
        // the path and the vakonomic body there instead
        const bool perturbed = drawsOpenLoop() || drawsClosedLoop();
        const bool compact = compactLegend();
        const double x2 = 0.5 * width();
        const double pathX = compact ? x2 : x, pathY = compact ? y : y + 2 * dy;
        const double vakY = compact ? y + dy : y + 3 * dy;
        p.setPen(m_look.style.pen(m_look.style.controlled().darker(150), 2));
        p.drawLine(QPointF(x, y), QPointF(x + len, y));
        p.setPen(m_look.style.pen(m_look.style.free(), 2, Qt::DashLine));
        p.drawLine(QPointF(x, y + dy), QPointF(x + len, y + dy));
        if (m_look.vakonomic) {
            p.setPen(m_look.style.pen(m_look.style.vakonomic(), 2, Qt::DashDotLine));
            p.drawLine(QPointF(pathX, vakY), QPointF(pathX + len, vakY));
        }
        if (drawsOpenLoop()) {
            p.setPen(m_look.style.pen(m_look.style.openLoop(), 2, Qt::DotLine));
            p.drawLine(QPointF(x2, y), QPointF(x2 + len, y));
        }
        if (drawsClosedLoop()) {
            p.setPen(m_look.style.pen(m_look.style.closedLoop(), 2, Qt::DashDotDotLine));
            p.drawLine(QPointF(x2, y + dy), QPointF(x2 + len, y + dy));
        }
        for (int i = 0; i < 24; ++i) {
            QColor c = m_look.style.highContrast ? m_look.style.path()
                                                 : pale(curvatureColor((i - 11.5) / 4.0));
            QPen pen = m_look.style.pen(c, 6);
            pen.setCapStyle(Qt::FlatCap);
            p.setPen(pen);
            p.drawLine(QPointF(pathX + i * k, pathY), QPointF(pathX + (i + 1) * k, pathY));
        }
        p.setPen(Qt::black);
        double tx = x + len + 6;
        // an entry's text, or its short form where the text does not fit its room (a narrow
        // canvas in presentation type), or its shortest; elided only when even that does not fit
        auto text = [&](double row, const QString& full, const QString& brief, double left = -1,
                        const QString& shortest = {}) {
            const double from = left < 0 ? tx : left;
            const double right =
                left < 0 && (perturbed || compact) && row < 2 ? x2 - 8 : width() - 4;
            QRectF r(from, y + row * dy - 0.5 * dy, right - from, dy);
            p.drawText(r, Qt::AlignLeft | Qt::AlignVCenter,
                       fittingLegendText(p.font(), p.device(), r.width(), {full, brief, shortest}));
        };
        text(0, tr("controlled body and its trail (tracks the path)"),
             tr("controlled body (tracks the path)"), -1, tr("controlled body"));
        text(1, tr("free motion from the same start (ghost)"), tr("free motion (ghost)"));
        if (drawsOpenLoop())
            text(0, tr("pushed, open loop: the nominal \u03bb(t) as planned"),
                 tr("pushed, open loop"), x2 + len + 6);
        if (drawsClosedLoop())
            text(1, tr("pushed, closed loop: feedback steers it back"),
                 tr("pushed, closed loop (feedback)"), x2 + len + 6);
        const double right = x2 + len + 6;
        if (m_look.vakonomic)
            text(compact ? 1 : 3, tr("genuine vakonomic body: \u03bb obeys its own equation (21)"),
                 tr("vakonomic body, equation (21)"), compact ? right : -1);
        const QString briefPath = tr("path (\u25cf start, \u25a1 end)");
        text(compact ? 0 : 2,
             m_look.style.highContrast
                 ? briefPath
                 : tr("path (\u25cf start, \u25a1 end), coloured by its curvature \u03ba: red "
                      "right turn, grey straight, blue left turn"),
             briefPath, compact ? right : -1);
    }
    if (m_tools.drawMode) {
        p.setFont(drawHintFont());
        p.drawText(drawHintBox(), kDrawHintFlags, drawHintText());
    }
}

QFont SceneCanvas::drawHintFont() const {
    QFont f = font();
    f.setPointSizeF(9 * m_look.style.lineScale);
    return f;
}

QString SceneCanvas::drawHintText() const {
    return tr("Draw mode: drag to draw a new path; drag a square to move a point, "
              "right-click it to delete it");
}

QRectF SceneCanvas::drawHintBox() const {
    // wrapped to the canvas's width, as many lines as a narrow window needs
    const QRectF area(8, topBandPx(), width() - 16, 1e4);
    const QRectF used =
        QFontMetricsF(drawHintFont()).boundingRect(area, kDrawHintFlags, drawHintText());
    return QRectF(8, topBandPx(), width() - 16,
                  std::max(used.height(), 20 * m_look.style.lineScale));
}

QRectF SceneCanvas::drawHintBounds() const {
    if (!m_tools.drawMode)
        return {};
    return QFontMetricsF(drawHintFont())
        .boundingRect(drawHintBox(), kDrawHintFlags, drawHintText());
}

LayerKey SceneCanvas::layerKey() const {
    return {m_document->solution().get(),
            size(),
            m_view.scale(),
            m_view.centre(),
            m_tools.drawMode,
            devicePixelRatioF(),
            m_look.vakonomic,
            m_look.style,
            m_look.legend,
            drawsOpenLoop(),
            drawsClosedLoop()};
}

const QPixmap& SceneCanvas::background() {
    // grid, path and legend change only with the view or the solution: cached between frames
    return m_layers.background(layerKey(), [this](QPainter& p) {
        const qreal dpr = devicePixelRatioF();
        paintGrid(p, worldTransform(), rect());
        paintScaleBar(p);
        if (!m_document->solution())
            return;
        paintPath(p, worldTransform());
        // the draw-mode hint is painted with the legend; a layer at a fractional device pixel
        // ratio would land between device pixels
        if (m_tools.drawMode || dpr != std::round(dpr))
            paintLegend(p);
        else
            paintLegendLayer(p);
    });
}

void SceneCanvas::paintLegendLayer(QPainter& p) {
    if (!m_look.legend)
        return;
    // the legend depends on neither zoom nor centre: one layer serves every view
    LayerKey key = layerKey();
    key.scale = 0;
    key.centre = {};
    // two rows above the legend's band hold the antialiased edge of its top line
    const int top = height() - legendBandPx() - 2;
    p.drawPixmap(0, top, m_layers.legend(key, QSize(width(), height() - top), [&](QPainter& l) {
        l.translate(0, -top);
        paintLegend(l);
    }));
}

bool SceneCanvas::followsWithWorldLayer() const {
    const qreal dpr = devicePixelRatioF();
    return m_view.follows() && !m_tools.drawMode && dpr == std::round(dpr) &&
           m_document->solution();
}

QTransform SceneCanvas::worldLayerTransform() const {
    const int margin = m_layers.worldMargin();
    return m_view.transformAt(m_layers.worldCentre()) * QTransform::fromTranslate(margin, margin);
}

QPoint SceneCanvas::worldLayerOrigin() const {
    // the world moves left and down as the centre goes right and up
    const QPointF shift = (m_view.centre() - m_layers.worldCentre()) * m_view.scale(); // y up
    const int margin = m_layers.worldMargin();
    return {margin + qRound(shift.x()), margin - qRound(shift.y())};
}

void SceneCanvas::dropLayers() {
    m_layers.drop();
}

void SceneCanvas::paintStaticLayer(QPainter& p, const QRegion& region, const MotionSample* now) {
    const qreal dpr = devicePixelRatioF();
    // the trails within the scene's area (up to the canvas's top), the legend's strip under it
    const QRegion inside = region & sceneArea().toAlignedRect();
    if (!followsWithWorldLayer()) {
        const QPixmap& base = background();
        if (now && dpr == std::round(dpr)) {
            updateTrailLayer(*now, base, {});
            blitRegion(p, inside, m_layers.trailLayer());
            blitRegion(p, region - inside, base);
            return;
        }
        // a fractional device pixel ratio: the trails drawn on the widget, as a layer at that
        // ratio would not draw them
        blitRegion(p, region, base);
        if (now) {
            p.save();
            p.setRenderHint(QPainter::Antialiasing, true);
            p.setClipRect(sceneArea());
            paintTrails(p, *now, inside);
            p.restore();
        }
        return;
    }
    LayerKey key = layerKey();
    key.centre = {}; // the world layer moves with the centre
    const QPixmap& world =
        m_layers.worldLayer(key, m_view.centre(), m_view.scale(), std::max(width(), height()) / 2,
                            [this](QPainter& w, QSize big) {
                                const QTransform map = worldLayerTransform();
                                paintGrid(w, map, QRectF(QPointF(0, 0), QSizeF(big)));
                                paintPath(w, map);
                            });
    const QPoint source = worldLayerOrigin();
    if (now) {
        updateTrailLayer(*now, world, source);
        blitRegion(p, inside, m_layers.trailLayer(), source);
        blitRegion(p, region - inside, world, source);
    } else {
        blitRegion(p, region, world, source);
    }
    p.setRenderHint(QPainter::Antialiasing, true);
    paintScaleBar(p);
    paintLegendLayer(p);
}

} // namespace chaplygin::ui
