#include "plots/plot_export.h"

#include "common/atomic_file.h"
#include "document/pin_set.h"
#include "plots/pinned_plots.h"

#include <qcustomplot.h>

#include <QBuffer>
#include <QDir>
#include <QPdfWriter>
#include <QSvgGenerator>

namespace chaplygin::ui {
namespace {

constexpr int kWidth = 900, kHeight = 600;

void paintInto(QCustomPlot& plot, QPaintDevice& device, int width, int height) {
    QCPPainter painter(&device);
    plot.toPainter(&painter, width, height);
    painter.end();
}

} // namespace

QByteArray renderPlot(QCustomPlot& plot, const QString& format, int width, int height) {
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    plot.resize(width, height);
    plot.replot();
    if (format == QLatin1String("png")) {
        QPixmap pixmap = plot.toPixmap(width, height, 2.0);
        pixmap.save(&buffer, "PNG");
    } else if (format == QLatin1String("pdf")) {
        QPdfWriter writer(&buffer);
        writer.setPageSize(QPageSize(QSizeF(width, height), QPageSize::Point));
        writer.setPageMargins(QMarginsF(0, 0, 0, 0));
        writer.setResolution(72);
        writer.setCreator(QStringLiteral("Chaplygin Lab"));
        paintInto(plot, writer, width, height);
    } else if (format == QLatin1String("svg")) {
        QSvgGenerator svg;
        svg.setOutputDevice(&buffer);
        svg.setSize(QSize(width, height));
        svg.setViewBox(QRect(0, 0, width, height));
        svg.setTitle(QStringLiteral("Chaplygin Lab plot"));
        paintInto(plot, svg, width, height);
    }
    return bytes;
}

namespace {

// each plot of `kinds` drawn from `series` with a title and the caption, into dir as
// <stem>.<format>; with pins, the time plots carry the pinned runs
void writePlots(const PlotSeries& series, const QList<PlotKind>& kinds, const QString& caption,
                const QString& dir, const QStringList& formats, PinSet* pins,
                const QList<PlotSeries>* pinned) {
    if (!QDir().mkpath(dir))
        throw IoError("cannot create the plot directory '" + dir.toStdString() + "'");
    for (PlotKind kind : kinds) {
        QCustomPlot plot;
        drawPlot(plot, kind, series);
        const bool timePlot = kind == PlotKind::Psi || kind == PlotKind::Chi ||
                              kind == PlotKind::Lambda || kind == PlotKind::Energy;
        if (pins && timePlot) // what the Plots dock shows
            addPinnedSeries(plot, kind, *pins, pinned);
        addCaption(plot, caption);
        QCPLayoutGrid* grid = plot.plotLayout();
        grid->insertRow(0);
        auto* title = new QCPTextElement(&plot, plotTitle(kind),
                                         QFont(plot.font().family(), 12, QFont::Bold));
        grid->addElement(0, 0, title);
        int height = kind == PlotKind::PaperFigure ? 800 : kHeight;
        for (const QString& format : formats) {
            QByteArray bytes = renderPlot(plot, format, kWidth, height);
            QString file = QDir(dir).filePath(plotFileStem(kind) + QLatin1Char('.') + format);
            if (bytes.isEmpty())
                throw IoError("cannot render '" + file.toStdString() + "'");
            writeFileAtomically(file.toStdString(), bytes.toStdString());
        }
    }
}

} // namespace

void exportPlots(const Solution& solution, const QString& dir, const QStringList& formats,
                 PinSet* pins) {
    PlotSeries series = collectSeries(solution, 800, 800);
    // the pinned runs as smooth as the run itself: sampled evenly, not at the path's nodes
    QList<PlotSeries> pinned;
    for (int i = 0; pins && i < pins->count(); ++i)
        pinned << (pins->run(i).solution ? collectSeries(*pins->run(i).solution, 2, 800)
                                         : PlotSeries{});
    QList<PlotKind> kinds{PlotKind::Psi,    PlotKind::Chi,        PlotKind::Lambda,
                          PlotKind::Energy, PlotKind::Trajectory, PlotKind::PaperFigure};
    if (series.perturbed)
        kinds << PlotKind::TrackingError;
    writePlots(series, kinds, sceneCaption(solution), dir, formats, pins, &pinned);
}

void exportPlanPlots(const Solution& solution, const PlanRequest& request,
                     const PlannedGeodesic& motion, const QString& dir,
                     const QStringList& formats) {
    writePlots(collectPlanSeries(request, motion, 800),
               {PlotKind::Psi, PlotKind::Chi, PlotKind::Lambda, PlotKind::Energy},
               planCaption(solution, request, motion), dir, formats, nullptr, nullptr);
}

} // namespace chaplygin::ui
