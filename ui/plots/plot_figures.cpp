#include "plots/plot_figures.h"

#include <QCoreApplication>

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

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
    g->setData(x, y, true);
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

void labels(QCPAxisRect* rect, const QString& x, const QString& y) {
    rect->axis(QCPAxis::atBottom)->setLabel(x);
    rect->axis(QCPAxis::atLeft)->setLabel(y);
}

// the legend goes in a row under a lone plot (so it never hides a curve), or inside a panel
void legendIn(QCPAxisRect* rect, QCustomPlot& plot) {
    auto* legend = new QCPLegend;
    QCPLayoutGrid* grid = plot.plotLayout();
    if (grid->elementCount() == 1 && grid->element(0, 0) == rect) {
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
    for (QCPAbstractPlottable* p : rect->plottables())
        p->rescaleAxes(p != rect->plottables().first());
    QCPAxis* x = rect->axis(QCPAxis::atBottom);
    QCPAxis* y = rect->axis(QCPAxis::atLeft);
    for (QCPAxis* a : {x, y})
        a->setRange(paddedRange(a->range().lower, a->range().upper));
    if (equalAspect) {
        // equal scales on x and y whatever the size: redone after every layout
        QRectF data(QPointF(x->range().lower, y->range().lower),
                    QPointF(x->range().upper, y->range().upper));
        QObject::connect(rect->parentPlot(), &QCustomPlot::afterLayout, rect,
                         [rect, data] { fitEqualAspect(*rect, data); });
        fitEqualAspect(*rect, data);
    }
}

void timePlot(QCustomPlot& plot, QCPAxisRect* rect, PlotKind kind, const PlotSeries& s) {
    switch (kind) {
    case PlotKind::Psi:
        addGraph(rect, s.t, s.psi, QCoreApplication::translate("PlotFigures", "controlled \u03a8"),
                 kControlled);
        addGraph(rect, s.freeT, s.freePsi,
                 QCoreApplication::translate("PlotFigures", "free \u03a8"), kFree, Qt::DashLine);
        addGraph(rect, s.vakT, s.vakPsi,
                 QCoreApplication::translate("PlotFigures", "vakonomic \u03a8"), kVakonomic,
                 Qt::DashDotLine);
        labels(rect, QStringLiteral("t [s]"), QStringLiteral("\u03a8 [rad]"));
        break;
    case PlotKind::Chi:
        addGraph(rect, s.t, s.chi, QCoreApplication::translate("PlotFigures", "controlled \u03c7"),
                 kControlled);
        addGraph(rect, s.freeT, s.freeChi,
                 QCoreApplication::translate("PlotFigures", "free \u03c7 (constant)"), kFree,
                 Qt::DashLine);
        addGraph(rect, s.vakT, s.vakChi,
                 QCoreApplication::translate("PlotFigures", "vakonomic \u03c7"), kVakonomic,
                 Qt::DashDotLine);
        labels(rect, QStringLiteral("t [s]"),
               QStringLiteral("\u03c7 = \u03a8 \u2212 (a/b)\u03c6 [rad]"));
        break;
    case PlotKind::Lambda:
        addGraph(rect, s.t, s.lambda, QStringLiteral("\u03bb = m b d\u03c7/dt"), kControlled);
        addGraph(rect, s.vakT, s.vakLambda,
                 QCoreApplication::translate("PlotFigures", "vakonomic \u03bb (eq. 21)"),
                 kVakonomic, Qt::DashDotLine);
        labels(rect, QStringLiteral("t [s]"), QStringLiteral("\u03bb [kg m/s]"));
        break;
    case PlotKind::Energy:
        addGraph(rect, s.t, s.energy, QCoreApplication::translate("PlotFigures", "controlled T"),
                 kControlled);
        addGraph(rect, s.freeT, s.freeEnergy, QCoreApplication::translate("PlotFigures", "free T"),
                 kFree, Qt::DashLine);
        addGraph(rect, s.vakT, s.vakEnergy,
                 QCoreApplication::translate("PlotFigures", "vakonomic T"), kVakonomic,
                 Qt::DashDotLine);
        labels(rect, QStringLiteral("t [s]"),
               QCoreApplication::translate("PlotFigures", "kinetic energy T [J]"));
        break;
    default:
        break;
    }
    rescale(rect);
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
           QCoreApplication::translate("PlotFigures", "lateral error e [m]"));
    addGraph(rects[1], s.pertT, s.openTheta,
             QCoreApplication::translate("PlotFigures", "open loop \u03b8"), t_palette.openLoop,
             Qt::DotLine);
    addGraph(rects[1], s.pertT, s.fbTheta,
             QCoreApplication::translate("PlotFigures", "feedback \u03b8"), t_palette.closedLoop);
    labels(rects[1], QStringLiteral("t [s]"),
           QCoreApplication::translate("PlotFigures", "heading error \u03b8 [rad]"));
    for (QCPAxisRect* r : rects) {
        rescale(r);
        legendIn(r, plot);
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
        return;
    }
    if (kind == PlotKind::TrackingError) {
        trackingErrorPlot(plot, series);
        return;
    }
    QCPLayoutGrid* grid = plot.plotLayout();
    grid->clear();
    auto* rect = new QCPAxisRect(&plot);
    grid->addElement(0, 0, rect);
    if (kind == PlotKind::Trajectory)
        trajectoryPlot(plot, rect, series);
    else
        timePlot(plot, rect, kind, series);
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
    for (;; --columns) {
        legend->setWrap(columns);
        legend->setFillOrder(QCPLegend::foColumnsFirst, true); // rearranges the items in place
        if (columns <= 1 || legend->minimumOuterSizeHint().width() <= plot.width())
            return;
    }
}

void fitTicksToHeight(QCustomPlot& plot) {
    // a low plot (presentation mode on a 1024x768 projector) gets fewer value ticks, so their
    // labels never overlap: about one per 2.5 label heights of the axis rectangle
    int legendHeight = 0;
    for (int i = 0; i < plot.plotLayout()->elementCount(); ++i)
        if (auto* l = qobject_cast<QCPLegend*>(plot.plotLayout()->elementAt(i)))
            legendHeight = l->minimumOuterSizeHint().height();
    for (QCPAxisRect* rect : plot.axisRects()) {
        QCPAxis* y = rect->axis(QCPAxis::atLeft);
        const int label = QFontMetrics(y->tickLabelFont()).height();
        // the rectangle's height once laid out, else the plot's less the legend and the t axis
        const int height =
            rect->height() > 0 ? rect->height() : plot.height() - legendHeight - 3 * label;
        y->ticker()->setTickStepStrategy(QCPAxisTicker::tssMeetTickCount);
        y->ticker()->setTickCount(std::clamp(static_cast<int>(height / (2.5 * label)), 2, 5));
    }
}

} // namespace chaplygin::ui
