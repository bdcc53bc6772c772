#include "plots/sweep_plot.h"

#include <QCoreApplication>

#include "common/atomic_file.h"
#include "plots/plot_export.h"
#include "plots/plot_figures.h"

#include <qcustomplot.h>

#include <QDir>

#include <algorithm>

namespace chaplygin::ui {

void drawSweep(QCustomPlot& plot, const SweepReport& report, SweepQuantity quantity) {
    plot.clearPlottables();
    QVector<double> x, y;
    for (const SweepRow& row : report.rows) {
        x << row.value;
        y << sweepQuantityValue(row, quantity);
    }
    QCPGraph* graph = plot.addGraph();
    graph->setData(x, y, true);
    graph->setPen(QPen(QColor(0x1f, 0x77, 0xb4), 1.5));
    graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QColor(0x1f, 0x77, 0xb4),
                                           QColor(0x1f, 0x77, 0xb4), 6));
    graph->setName(
        QCoreApplication::translate("SweepQuantity", sweepQuantityLabel(quantity).c_str()));
    plot.xAxis->setLabel(QString::fromStdString(report.spec.parameter));
    plot.yAxis->setLabel(
        QCoreApplication::translate("SweepQuantity", sweepQuantityLabel(quantity).c_str()));
    if (!x.isEmpty()) {
        double lo = std::min(report.spec.from, report.spec.to),
               hi = std::max(report.spec.from, report.spec.to);
        double pad = hi > lo ? 0.04 * (hi - lo) : 0.5;
        plot.xAxis->setRange(lo - pad, hi + pad);
        auto [ymin, ymax] = std::minmax_element(y.begin(), y.end());
        double span = *ymax - *ymin;
        double ypad = span > 1e-12 * std::max(std::fabs(*ymax), 1.0)
                          ? 0.08 * span
                          : 0.05 * std::max(std::fabs(*ymax), 1e-3);
        plot.yAxis->setRange(*ymin - ypad, *ymax + ypad);
    }
}

void exportSweep(const SweepReport& report, const QString& caption, const QString& dir,
                 const QStringList& formats) {
    if (!QDir().mkpath(dir))
        throw IoError("cannot create the plot directory '" + dir.toStdString() + "'");
    for (int q = 0; q < kSweepQuantityCount; ++q) {
        auto quantity = static_cast<SweepQuantity>(q);
        QCustomPlot plot;
        drawSweep(plot, report, quantity);
        addCaption(plot, caption);
        QCPLayoutGrid* grid = plot.plotLayout();
        grid->insertRow(0);
        grid->addElement(
            0, 0,
            new QCPTextElement(&plot,
                               QCoreApplication::translate("SweepPlot", "Sweep of %1: %2")
                                   .arg(QString::fromStdString(report.spec.parameter),
                                        QCoreApplication::translate(
                                            "SweepQuantity", sweepQuantityLabel(quantity).c_str())),
                               QFont(plot.font().family(), 12, QFont::Bold)));
        for (const QString& format : formats) {
            QByteArray bytes = renderPlot(plot, format, 900, 600);
            QString file = QDir(dir).filePath(
                QStringLiteral("sweep_%1.%2")
                    .arg(QString::fromStdString(sweepQuantityColumn(quantity)), format));
            if (bytes.isEmpty())
                throw IoError("cannot render '" + file.toStdString() + "'");
            writeFileAtomically(file.toStdString(), bytes.toStdString());
        }
    }
}

} // namespace chaplygin::ui
