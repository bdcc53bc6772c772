#include "plots/axis_fitting.h"

#include "plots/pixel_ticker.h"
#include "plots/plot_figures.h"
#include "plots/time_axes.h"

#include <QFontMetricsF>

#include <qcustomplot.h>

#include <algorithm>

namespace chaplygin::ui {

namespace {

const char* const kLabels = "chaplyginLabels";

double longestLine(const QFontMetricsF& metrics, const QString& text) {
    double widest = 0;
    for (const QString& line : text.split(QLatin1Char('\n')))
        widest = std::max(widest, metrics.horizontalAdvance(line));
    return widest;
}

void chooseLabel(QCPAxis* axis) {
    const QStringList labels = axis->property(kLabels).toStringList();
    if (labels.isEmpty())
        return;
    QCPAxisRect* rect = axis->axisRect();
    const QFontMetricsF metrics(axis->labelFont());
    QString chosen = labels.last();
    if (axis->orientation() == Qt::Vertical) {
        for (const QString& label : labels)
            if (longestLine(metrics, label) <= rect->height() - 4) {
                chosen = label;
                break;
            }
    } else {
        // the rectangle's height without the label, against four tick labels
        const double tick = QFontMetricsF(axis->tickLabelFont()).height();
        const double label = axis->label().isEmpty()
                                 ? 0
                                 : metrics.height() * (axis->label().count(QLatin1Char('\n')) + 1) +
                                       axis->labelPadding();
        const double without = rect->height() + label;
        chosen = without - metrics.height() - axis->labelPadding() >= 4 * tick ? labels.first()
                                                                               : QString();
    }
    if (chosen != axis->label())
        axis->setLabel(chosen);
}

// the layout's phases again, with the labels chosen and the ticks made for the lengths the last
// layout gave, until the axis rectangles keep their size
void layOutAgain(QCustomPlot& plot) {
    QCPLayoutGrid* layout = plot.plotLayout();
    for (int pass = 0; pass < 4; ++pass) {
        QList<QRect> before;
        for (QCPAxisRect* rect : plot.axisRects()) {
            before << rect->rect();
            for (QCPAxis* axis : rect->axes())
                chooseLabel(axis);
            const QVariant data = rect->property("chaplyginEqualAspect");
            if (data.isValid())
                fitEqualAspect(*rect, data.toRectF());
        }
        layout->update(QCPLayoutElement::upPreparation);
        layout->update(QCPLayoutElement::upMargins);
        layout->update(QCPLayoutElement::upLayout);
        QList<QRect> after;
        for (QCPAxisRect* rect : plot.axisRects())
            after << rect->rect();
        if (after == before)
            break;
    }
    for (QCPAxisRect* rect : plot.axisRects())
        placeClipMarks(*rect);
}

} // namespace

void setAxisLabels(QCPAxis* axis, const QStringList& labels) {
    axis->setProperty(kLabels, labels);
    axis->setLabel(labels.value(0));
}

void fitAxesAfterLayout(QCustomPlot& plot) {
    const QList<QCPAxisRect*> rects = plot.axisRects();
    if (rects.isEmpty())
        return;
    for (QCPAxisRect* rect : rects)
        for (QCPAxis* axis : rect->axes())
            axis->setTicker(QSharedPointer<QCPAxisTicker>(new PixelTicker(axis)));
    // the connection ends with the first axis rectangle, that is with the next drawPlot
    QObject::connect(&plot, &QCustomPlot::afterLayout, rects.first(),
                     [&plot] { layOutAgain(plot); });
}

} // namespace chaplygin::ui
