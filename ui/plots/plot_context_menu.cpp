#include "plots/plot_context_menu.h"

#include "common/atomic_file.h"
#include "common/input_error.h"
#include "document/file_dialogs.h"
#include "plots/plot_export.h"
#include "plots/time_axes.h"

#include <QFileInfo>
#include <QMenu>

#include <qcustomplot.h>

#include <algorithm>

namespace chaplygin::ui {

void exportPlotFile(QCustomPlot& plot, const QString& path) {
    const QString format = QFileInfo(path).suffix().toLower();
    if (format != QLatin1String("png") && format != QLatin1String("pdf") &&
        format != QLatin1String("svg"))
        throw InputError("'" + path.toStdString() + "'",
                         "choose a .png, .pdf or .svg file for the plot");
    // at least the size of a printed figure; the dock's plot may be small
    int w = std::max(plot.width(), 900), h = std::max(plot.height(), 600);
    QSize shown = plot.size();
    QByteArray bytes = renderPlot(plot, format, w, h);
    plot.resize(shown);
    plot.replot(QCustomPlot::rpQueuedReplot);
    if (bytes.isEmpty())
        throw IoError("cannot render '" + path.toStdString() + "'");
    writeFileAtomically(path.toStdString(), bytes.toStdString());
}

QAction* installFitAllAction(QCustomPlot* plot, QMenu& menu) {
    QAction* action = menu.addAction(QObject::tr("Fit all curves"));
    action->setObjectName(QStringLiteral("fitAllCurves"));
    action->setToolTip(QObject::tr("Show the free and vakonomic curves whole instead of clipping "
                                   "them at the frame"));
    action->setCheckable(true);
    QObject::connect(action, &QAction::toggled, plot, [plot](bool on) {
        setFitAllCurves(*plot, on);
        plot->replot(QCustomPlot::rpQueuedReplot);
    });
    return action;
}

QMenu* installPlotExportMenu(QCustomPlot* plot, std::function<QString()> stem,
                             std::function<void(const QString&)> onError) {
    auto* menu = new QMenu(plot);
    menu->setObjectName(QStringLiteral("plotExportMenu"));
    QAction* action = menu->addAction(QObject::tr("Export this plot\u2026"));
    QObject::connect(action, &QAction::triggered, plot, [plot, stem, onError] {
        QString path =
            chooseSaveFile(plot, QObject::tr("Export the plot"), QStringLiteral("plot"), stem(),
                           QObject::tr("PNG image (*.png);;PDF (*.pdf);;SVG (*.svg)"));
        if (path.isEmpty())
            return;
        try {
            exportPlotFile(*plot, path);
        } catch (const std::exception& e) {
            onError(QString::fromUtf8(e.what()));
        }
    });
    plot->setContextMenuPolicy(Qt::CustomContextMenu);
    QObject::connect(plot, &QWidget::customContextMenuRequested, menu,
                     [plot, menu](const QPoint& pos) { menu->popup(plot->mapToGlobal(pos)); });
    return menu;
}

} // namespace chaplygin::ui
