#include "plots/plot_figures.h"

#include "plots/axis_fitting.h"
#include "plots/time_axes.h"

#include <QCoreApplication>

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace chaplygin::ui {
namespace {

// the look of the plot being drawn (setPlotLook); set by drawPlot
CanvasStyle t_look;
struct Palette {
    QColor controlled, free, path, vakonomic, openLoop, closedLoop;
} t_palette;
const QColor& kControlled = t_palette.controlled;
const QColor& kFree = t_palette.free;
const QColor& kPath = t_palette.path;
const QColor& kVakonomic = t_palette.vakonomic;

QCPGraph* addGraph(QCPAxisRect* rect, const QVector<double>& x, const QVector<double>& y,
                   const QString& name, const QColor& color, Qt::PenStyle style = Qt::SolidLine) {
    QCPGraph* g =
        rect->parentPlot()->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    // an infinite value is a gap, as NaN is, not a line to the end of the axis
    QVector<double> finite = y;
    for (double& v : finite)
        if (std::isinf(v))
            v = std::numeric_limits<double>::quiet_NaN();
    g->setData(x, finite, true);
    g->setName(name);
    g->setPen(QPen(color, 1.5 * t_look.lineScale, style));
    return g;
}

QCPCurve* addCurve(QCPAxisRect* rect, const QVector<double>& x, const QVector<double>& y,
                   const QString& name, const QColor& color, Qt::PenStyle style = Qt::SolidLine) {
    auto* c = new QCPCurve(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    c->setData(x, y);
    c->setName(name);
    c->setPen(QPen(color, 1.5 * t_look.lineScale, style));
    return c;
}

// the axis labels; a low plot shows yShort instead of y (setAxisLabels)
void labels(QCPAxisRect* rect, const QString& x, const QString& y, const QString& yShort = {}) {
    setAxisLabels(rect->axis(QCPAxis::atBottom), {x});
    setAxisLabels(rect->axis(QCPAxis::atLeft),
                  yShort.isEmpty() ? QStringList{y} : QStringList{y, yShort});
}

// the legend goes in a row under a lone plot (so it never hides a curve), under a panel when
// `under` is the grid and column that hold it, or inside a panel
void legendIn(QCPAxisRect* rect, QCustomPlot& plot, QCPLayoutGrid* under = nullptr,
              int column = 0) {
    auto* legend = new QCPLegend;
    QCPLayoutGrid* grid = plot.plotLayout();
    if (under) {
        under->addElement(1, column, legend);
        under->setRowStretchFactor(1, 0.001);
        legend->setFillOrder(QCPLegend::foRowsFirst); // one entry a row: a narrow panel
        legend->setBorderPen(Qt::NoPen);
        legend->setMargins(QMargins(4, 0, 4, 2));
    } else if (grid->elementCount() == 1 && grid->element(0, 0) == rect) {
        grid->addElement(1, 0, legend);
        grid->setRowStretchFactor(1, 0.001);
        legend->setFillOrder(QCPLegend::foColumnsFirst);
        legend->setBorderPen(Qt::NoPen);
        legend->setMargins(QMargins(4, 0, 4, 2));
    } else {
        rect->insetLayout()->addElement(legend, Qt::AlignTop | Qt::AlignRight);
        legend->setBrush(QColor(255, 255, 255, 210));
    }
    legend->setLayer("legend");
    // compact: small entries with short lines
    QFont font = plot.font();
    font.setPointSizeF(std::max(7.0, 0.85 * font.pointSizeF()));
    legend->setFont(font);
    legend->setIconSize(int(20 * t_look.lineScale), int(10 * t_look.lineScale));
    legend->setRowSpacing(0);
    for (int i = 0; i < plot.plottableCount(); ++i) {
        QCPAbstractPlottable* p = plot.plottable(i);
        if (p->keyAxis()->axisRect() == rect)
            p->addToLegend(legend);
    }
}

void rescale(QCPAxisRect* rect, bool equalAspect = false) {
    // every finite point of every curve, with margins
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    auto add = [&](double x, double y) {
        if (!std::isfinite(x) || !std::isfinite(y))
            return;
        lo[0] = std::min(lo[0], x);
        hi[0] = std::max(hi[0], x);
        lo[1] = std::min(lo[1], y);
        hi[1] = std::max(hi[1], y);
    };
    for (QCPAbstractPlottable* p : rect->plottables()) {
        if (auto* g = qobject_cast<QCPGraph*>(p))
            for (const QCPGraphData& d : *g->data())
                add(d.key, d.value);
        if (auto* c = qobject_cast<QCPCurve*>(p))
            for (const QCPCurveData& d : *c->data())
                add(d.key, d.value);
    }
    QCPAxis* x = rect->axis(QCPAxis::atBottom);
    QCPAxis* y = rect->axis(QCPAxis::atLeft);
    x->setRange(paddedRange(lo[0], hi[0]));
    y->setRange(paddedRange(lo[1], hi[1]));
    if (equalAspect) {
        // equal scales on x and y whatever the size: redone after every layout (installTickers)
        const QRectF data(QPointF(x->range().lower, y->range().lower),
                          QPointF(x->range().upper, y->range().upper));
        rect->setProperty("chaplyginEqualAspect", data);
        fitEqualAspect(*rect, data);
    }
}

// a time plot: the controlled body sets the value range; the free and vakonomic bodies are
// clipped at the frame with a mark where they leave (time_axes.h)
void timePlot(QCustomPlot& plot, QCPAxisRect* rect, PlotKind kind, const PlotSeries& s) {
    // a planned motion has no controlled body: its genuine vakonomic body is the curve drawn
    // solid, and every curve sets the value range (docs/physics.md §10)
    auto controlled = [rect](const QVector<double>& t, const QVector<double>& y,
                             const QString& name) {
        if (!t.isEmpty())
            setControlled(*addGraph(rect, t, y, name, kControlled));
    };
    auto free = [rect](const QVector<double>& t, const QVector<double>& y, const QString& name) {
        setClipped(*addGraph(rect, t, y, name, kFree, Qt::DashLine),
                   QCoreApplication::translate("PlotFigures", "free"));
    };
    auto vakonomic = [rect, &s](const QVector<double>& t, const QVector<double>& y,
                                const QString& name) {
        setClipped(
            *addGraph(rect, t, y, name, kVakonomic, s.planned ? Qt::SolidLine : Qt::DashDotLine),
            QCoreApplication::translate("PlotFigures", "vakonomic"));
    };
    auto named = [&s](const char* scene, const char* planned) {
        return QCoreApplication::translate("PlotFigures", s.planned ? planned : scene);
    };
    switch (kind) {
    case PlotKind::Psi:
        controlled(s.t, s.psi, QCoreApplication::translate("PlotFigures", "controlled \u03a8"));
        free(s.freeT, s.freePsi, QCoreApplication::translate("PlotFigures", "free \u03a8"));
        vakonomic(s.vakT, s.vakPsi,
                  named(QT_TRANSLATE_NOOP("PlotFigures", "vakonomic \u03a8"),
                        QT_TRANSLATE_NOOP("PlotFigures", "planned \u03a8 (vakonomic)")));
        labels(rect, QStringLiteral("t [s]"), QStringLiteral("\u03a8 [rad]"),
               QStringLiteral("\u03a8\n[rad]"));
        break;
    case PlotKind::Chi:
        controlled(s.t, s.chi, QCoreApplication::translate("PlotFigures", "controlled \u03c7"));
        free(s.freeT, s.freeChi,
             QCoreApplication::translate("PlotFigures", "free \u03c7 (constant)"));
        vakonomic(s.vakT, s.vakChi,
                  named(QT_TRANSLATE_NOOP("PlotFigures", "vakonomic \u03c7"),
                        QT_TRANSLATE_NOOP("PlotFigures", "planned \u03c7 (vakonomic)")));
        labels(rect, QStringLiteral("t [s]"),
               QStringLiteral("\u03c7 = \u03a8 \u2212 (a/b)\u03c6 [rad]"),
               QStringLiteral("\u03c7 [rad]"));
        break;
    case PlotKind::Lambda:
        controlled(s.t, s.lambda, QStringLiteral("\u03bb = m b d\u03c7/dt"));
        vakonomic(s.vakT, s.vakLambda,
                  named(QT_TRANSLATE_NOOP("PlotFigures", "vakonomic \u03bb (eq. 21)"),
                        QT_TRANSLATE_NOOP("PlotFigures", "planned \u03bb (eq. 21)")));
        labels(rect, QStringLiteral("t [s]"), QStringLiteral("\u03bb [kg m/s]"),
               QStringLiteral("\u03bb\n[kg m/s]"));
        break;
    case PlotKind::Energy:
        controlled(s.t, s.energy, QCoreApplication::translate("PlotFigures", "controlled T"));
        free(s.freeT, s.freeEnergy, QCoreApplication::translate("PlotFigures", "free T"));
        vakonomic(s.vakT, s.vakEnergy,
                  named(QT_TRANSLATE_NOOP("PlotFigures", "vakonomic T"),
                        QT_TRANSLATE_NOOP("PlotFigures", "planned T (vakonomic)")));
        labels(rect, QStringLiteral("t [s]"),
               QCoreApplication::translate("PlotFigures", "kinetic energy T [J]"),
               QStringLiteral("T [J]"));
        break;
    default:
        break;
    }
    fitTimeAxes(*rect);
    legendIn(rect, plot);
}

void trajectoryPlot(QCustomPlot& plot, QCPAxisRect* rect, const PlotSeries& s) {
    addCurve(rect, s.pathX, s.pathY, QCoreApplication::translate("PlotFigures", "prescribed path"),
             kPath, Qt::DotLine);
    addCurve(rect, s.x, s.y, QCoreApplication::translate("PlotFigures", "controlled body (P)"),
             kControlled);
    addCurve(rect, s.freeX, s.freeY, QCoreApplication::translate("PlotFigures", "free body (P)"),
             kFree, Qt::DashLine);
    addCurve(rect, s.vakX, s.vakY, QCoreApplication::translate("PlotFigures", "vakonomic body (P)"),
             kVakonomic, Qt::DashDotLine);
    labels(rect, QStringLiteral("x [m]"), QStringLiteral("y [m]"));
    rescale(rect, true);
    legendIn(rect, plot);
}

// the perturbed bodies' errors against their closest path points (docs/physics.md §9): e above,
// the heading error below, open loop and closed loop
void trackingErrorPlot(QCustomPlot& plot, const PlotSeries& s) {
    QCPLayoutGrid* grid = plot.plotLayout();
    grid->clear();
    auto* panels = new QCPLayoutGrid;
    grid->addElement(0, 0, panels);
    QCPAxisRect* rects[2];
    for (int i = 0; i < 2; ++i) {
        rects[i] = new QCPAxisRect(&plot);
        panels->addElement(0, i, rects[i]);
    }
    addGraph(rects[0], s.pertT, s.openE, QCoreApplication::translate("PlotFigures", "open loop e"),
             t_palette.openLoop, Qt::DotLine);
    addGraph(rects[0], s.pertT, s.fbE, QCoreApplication::translate("PlotFigures", "feedback e"),
             t_palette.closedLoop);
    labels(rects[0], QStringLiteral("t [s]"),
           QCoreApplication::translate("PlotFigures", "lateral error e [m]"),
           QStringLiteral("e [m]"));
    addGraph(rects[1], s.pertT, s.openTheta,
             QCoreApplication::translate("PlotFigures", "open loop \u03b8"), t_palette.openLoop,
             Qt::DotLine);
    addGraph(rects[1], s.pertT, s.fbTheta,
             QCoreApplication::translate("PlotFigures", "feedback \u03b8"), t_palette.closedLoop);
    labels(rects[1], QStringLiteral("t [s]"),
           QCoreApplication::translate("PlotFigures", "heading error \u03b8 [rad]"),
           QStringLiteral("\u03b8 [rad]"));
    for (int i = 0; i < 2; ++i) {
        rescale(rects[i]);
        legendIn(rects[i], plot, panels, i); // under each panel: a narrow panel stays visible
    }
}

// the paper's Figs. 2 and 3: s(t), x(t), y(t) and y(x) with the path
void paperFigure(QCustomPlot& plot, const PlotSeries& s) {
    QCPLayoutGrid* grid = plot.plotLayout();
    grid->clear();
    auto* panels = new QCPLayoutGrid;
    grid->addElement(0, 0, panels);
    QCPAxisRect* rects[4];
    for (int i = 0; i < 4; ++i) {
        rects[i] = new QCPAxisRect(&plot);
        panels->addElement(i / 2, i % 2, rects[i]);
    }
    addGraph(rects[0], s.t, s.s, QStringLiteral("s(t)"), kControlled);
    labels(rects[0], QStringLiteral("t [s]"), QStringLiteral("(a) s [m]"));
    addGraph(rects[1], s.t, s.x, QStringLiteral("x(t)"), kControlled);
    labels(rects[1], QStringLiteral("t [s]"), QStringLiteral("(b) x [m]"));
    addGraph(rects[2], s.t, s.y, QStringLiteral("y(t)"), kControlled);
    labels(rects[2], QStringLiteral("t [s]"), QStringLiteral("(c) y [m]"));
    addCurve(rects[3], s.pathX, s.pathY, QCoreApplication::translate("PlotFigures", "path"), kPath,
             Qt::DotLine);
    addCurve(rects[3], s.x, s.y, QCoreApplication::translate("PlotFigures", "tracked y(x)"),
             kControlled);
    labels(rects[3], QStringLiteral("x [m]"), QStringLiteral("(d) y [m]"));
    for (QCPAxisRect* r : rects) {
        rescale(r);
        legendIn(r, plot);
    }
}

} // namespace

QCPRange paddedRange(double lower, double upper) {
    if (!std::isfinite(lower) || !std::isfinite(upper) || lower > upper)
        return QCPRange(-1, 1);
    double centre = 0.5 * (lower + upper), size = upper - lower;
    double magnitude = std::max(std::abs(lower), std::abs(upper));
    // flat (to rounding): a band of +-10 % around the value, not an axis that magnifies noise
    if (size <= 1e-6 * magnitude || size < 1e-12) {
        double half = std::max(0.1 * magnitude, 1e-3);
        return QCPRange(centre - half, centre + half);
    }
    return QCPRange(lower - 0.05 * size, upper + 0.05 * size);
}

void fitEqualAspect(QCPAxisRect& rect, const QRectF& data) {
    QCPAxis* x = rect.axis(QCPAxis::atBottom);
    QCPAxis* y = rect.axis(QCPAxis::atLeft);
    double w = rect.width(), h = rect.height();
    if (w < 2 || h < 2 || !(data.width() >= 0) || !(data.height() >= 0))
        return;
    // metres per pixel: the larger of the two, so that the whole data box stays in view
    double u = std::max(data.width() / w, data.height() / h);
    if (!(u > 0) || !std::isfinite(u))
        return;
    QPointF c = data.center();
    x->setRange(c.x() - 0.5 * u * w, c.x() + 0.5 * u * w);
    y->setRange(c.y() - 0.5 * u * h, c.y() + 0.5 * u * h);
}

void setPlotLook(QCustomPlot& plot, const CanvasStyle& look) {
    QFont font = plot.font();
    double base = plot.property("chaplyginBaseFont").isValid()
                      ? plot.property("chaplyginBaseFont").toDouble()
                      : font.pointSizeF();
    plot.setProperty("chaplyginBaseFont", base);
    font.setPointSizeF(base * look.lineScale);
    plot.setFont(font);
    plot.setProperty("chaplyginLineScale", look.lineScale);
    plot.setProperty("chaplyginHighContrast", look.highContrast);
}

QString plotFileStem(PlotKind kind) {
    switch (kind) {
    case PlotKind::Psi:
        return QStringLiteral("psi");
    case PlotKind::Chi:
        return QStringLiteral("chi");
    case PlotKind::Lambda:
        return QStringLiteral("lambda");
    case PlotKind::Energy:
        return QStringLiteral("energy");
    case PlotKind::Trajectory:
        return QStringLiteral("trajectory");
    case PlotKind::PaperFigure:
        return QStringLiteral("paper_figure");
    case PlotKind::TrackingError:
        return QStringLiteral("tracking_error");
    }
    return QStringLiteral("plot");
}

QString plotTitle(PlotKind kind) {
    switch (kind) {
    case PlotKind::Psi:
        return QCoreApplication::translate("PlotFigures", "Control angle \u03a8(t)");
    case PlotKind::Chi:
        return QCoreApplication::translate("PlotFigures", "Driving angle \u03c7(t)");
    case PlotKind::Lambda:
        return QCoreApplication::translate("PlotFigures", "Control multiplier \u03bb(t)");
    case PlotKind::Energy:
        return QCoreApplication::translate("PlotFigures", "Kinetic energy T(t)");
    case PlotKind::Trajectory:
        return QCoreApplication::translate("PlotFigures", "Trajectories of the knife point P");
    case PlotKind::PaperFigure:
        return QCoreApplication::translate(
            "PlotFigures", "s(t), x(t), y(t) and y(x), as in the paper's Figs. 2-3");
    case PlotKind::TrackingError:
        return QCoreApplication::translate(
            "PlotFigures", "Pushed bodies: lateral error e(t) and heading error \u03b8(t)");
    }
    return {};
}

void drawPlot(QCustomPlot& plot, PlotKind kind, const PlotSeries& series) {
    t_look = CanvasStyle();
    if (plot.property("chaplyginLineScale").isValid()) {
        t_look.lineScale = plot.property("chaplyginLineScale").toDouble();
        t_look.highContrast = plot.property("chaplyginHighContrast").toBool();
        t_look = t_look.sanitized();
    }
    t_palette = {t_look.controlled(), t_look.free(),     t_look.path(),
                 t_look.vakonomic(),  t_look.openLoop(), t_look.closedLoop()};
    plot.setAutoAddPlottableToLegend(false);
    plot.clearPlottables();
    plot.clearItems();
    if (kind == PlotKind::PaperFigure) {
        paperFigure(plot, series);
    } else if (kind == PlotKind::TrackingError) {
        trackingErrorPlot(plot, series);
    } else {
        QCPLayoutGrid* grid = plot.plotLayout();
        grid->clear();
        auto* rect = new QCPAxisRect(&plot);
        grid->addElement(0, 0, rect);
        if (kind == PlotKind::Trajectory)
            trajectoryPlot(plot, rect, series);
        else
            timePlot(plot, rect, kind, series);
    }
    fitAxesAfterLayout(plot);
}

void addCaption(QCustomPlot& plot, const QString& caption) {
    QCPLayoutGrid* grid = plot.plotLayout();
    grid->insertRow(0);
    auto* text = new QCPTextElement(&plot, caption, QFont(plot.font().family(), 9));
    grid->addElement(0, 0, text);
}

void fitLegendToWidth(QCustomPlot& plot) {
    QCPLegend* legend = nullptr;
    for (int i = 0; i < plot.plotLayout()->elementCount(); ++i)
        if (auto* l = qobject_cast<QCPLegend*>(plot.plotLayout()->elementAt(i)))
            legend = l;
    if (!legend || legend->fillOrder() != QCPLegend::foColumnsFirst)
        return;
    int columns = 0; // entries (a wrapped legend has empty cells too)
    for (int i = 0; i < legend->itemCount(); ++i)
        columns += legend->item(i) ? 1 : 0;
    if (const int cap = legend->property("maxColumns").toInt(); cap > 0)
        columns = std::min(columns, cap);
    // the legend's own font size, before any shrinking below
    if (!legend->property("fullFontSize").isValid())
        legend->setProperty("fullFontSize", legend->font().pointSizeF());
    const double full = legend->property("fullFontSize").toDouble();
    auto setItemFont = [legend](double size) {
        for (int i = 0; i < legend->itemCount(); ++i)
            if (QCPAbstractLegendItem* item = legend->item(i)) {
                QFont f = item->font();
                f.setPointSizeF(size);
                item->setFont(f);
            }
    };
    setItemFont(full);
    for (;; --columns) {
        legend->setWrap(columns);
        legend->setFillOrder(QCPLegend::foColumnsFirst, true); // rearranges the items in place
        if (columns <= 1 || legend->minimumOuterSizeHint().width() <= plot.width())
            break;
    }
    // one entry a row and still too wide (a narrow plot in presentation): smaller names, whole
    for (double size = full; legend->minimumOuterSizeHint().width() > plot.width() && size > 6.5;) {
        size -= 0.5;
        setItemFont(size);
    }
}

} // namespace chaplygin::ui
