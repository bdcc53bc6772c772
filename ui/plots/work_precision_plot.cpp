#include "plots/work_precision_plot.h"

#include <QCoreApplication>

#include "common/atomic_file.h"
#include "document/method_names.h"
#include "plots/plot_export.h"

#include <qcustomplot.h>

#include <QDir>

#include <algorithm>
#include <map>

namespace chaplygin::ui {
namespace {

const QList<QColor> kPalette = {
    QColor(0x1f, 0x77, 0xb4), QColor(0xff, 0x7f, 0x0e), QColor(0x2c, 0xa0, 0x2c),
    QColor(0xd6, 0x27, 0x28), QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
    QColor(0xe3, 0x77, 0xc2), QColor(0x7f, 0x7f, 0x7f), QColor(0xbc, 0xbd, 0x22),
    QColor(0x17, 0xbe, 0xcf), QColor(0x00, 0x00, 0x00)};

// errors below rounding are drawn at 1e-16 so that the log axis can show them
constexpr double kFloor = 1e-16;

void panel(QCustomPlot& plot, QCPAxisRect* rect, const WorkPrecisionReport& report,
           MotionProblem problem) {
    std::map<std::string, std::vector<const WorkPrecisionRow*>> byMethod;
    for (const WorkPrecisionRow& r : report.rows)
        if (r.problem == problem && r.seconds > 0)
            byMethod[r.method].push_back(&r);
    QSharedPointer<QCPAxisTickerLog> ticker(new QCPAxisTickerLog);
    for (QCPAxis* axis : {rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft)}) {
        axis->setScaleType(QCPAxis::stLogarithmic);
        axis->setTicker(ticker);
        axis->setNumberFormat("eb");
        axis->setNumberPrecision(0);
    }
    rect->axis(QCPAxis::atBottom)
        ->setLabel(QCoreApplication::translate("WorkPrecisionPlot", "seconds per solve"));
    rect->axis(QCPAxis::atLeft)
        ->setLabel(QCoreApplication::translate("WorkPrecisionPlot", "max position error [m]"));
    auto* legend = new QCPLegend;
    rect->insetLayout()->addElement(legend, Qt::AlignTop | Qt::AlignRight);
    legend->setFont(QFont(plot.font().family(), 7));
    legend->setBrush(QColor(255, 255, 255, 210));
    int colour = 0;
    bool starInLegend = false; // one legend entry for every chosen star: the table has the details
    double xmin = INFINITY, xmax = 0, ymin = INFINITY, ymax = 0;
    for (auto& [name, rows] : byMethod) {
        std::sort(rows.begin(), rows.end(),
                  [](auto* a, auto* b) { return a->seconds < b->seconds; });
        QVector<double> x, y;
        for (const WorkPrecisionRow* r : rows) {
            x << r->seconds;
            y << std::max(r->error, kFloor);
            xmin = std::min(xmin, r->seconds);
            xmax = std::max(xmax, r->seconds);
            ymin = std::min(ymin, y.back());
            ymax = std::max(ymax, y.back());
        }
        auto* curve = new QCPCurve(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        curve->setData(x, y);
        curve->setName(shortMethodName(name)); // the table has the plain names
        QColor c = kPalette[colour++ % kPalette.size()];
        curve->setPen(QPen(c, 1.2));
        curve->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, c, 4));
        curve->addToLegend(legend);
        for (const WorkPrecisionRow* r : rows)
            if (r->chosen) {
                auto* star =
                    new QCPCurve(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
                star->setData(QVector<double>{r->seconds},
                              QVector<double>{std::max(r->error, kFloor)});
                star->setLineStyle(QCPCurve::lsNone);
                star->setScatterStyle(
                    QCPScatterStyle(QCPScatterStyle::ssStar, QPen(Qt::black, 2), Qt::NoBrush, 16));
                star->setName(
                    QCoreApplication::translate("WorkPrecisionPlot", "chosen: see the table"));
                if (!starInLegend)
                    star->addToLegend(legend);
                starInLegend = true;
            }
    }
    if (xmax > 0) {
        rect->axis(QCPAxis::atBottom)->setRange(xmin / 2, xmax * 2);
        rect->axis(QCPAxis::atLeft)->setRange(ymin / 10, ymax * 10);
    }
    // the title is the top axis's label: above the frame, never on the tick labels or the curves
    QCPAxis* top = rect->axis(QCPAxis::atTop);
    top->setVisible(true);
    top->setTicks(false);
    top->setTickLabels(false);
    top->setLabelFont(QFont(plot.font().family(), 10, QFont::Bold));
    top->setLabel(
        problem == MotionProblem::Controlled
            ? QCoreApplication::translate("WorkPrecisionPlot", "controlled, t \u2264 %1 s")
                  .arg(report.controlledEnd, 0, 'g', 4)
            : QCoreApplication::translate("WorkPrecisionPlot", "free, t \u2264 %1 s")
                  .arg(report.freeEnd, 0, 'g', 4));
}

} // namespace

void drawWorkPrecision(QCustomPlot& plot, const WorkPrecisionReport& report) {
    plot.setAutoAddPlottableToLegend(false);
    plot.clearPlottables();
    QCPLayoutGrid* grid = plot.plotLayout();
    grid->clear();
    auto* panels = new QCPLayoutGrid;
    grid->addElement(0, 0, panels);
    auto* controlled = new QCPAxisRect(&plot);
    auto* free = new QCPAxisRect(&plot);
    panels->addElement(0, 0, controlled);
    panels->addElement(0, 1, free);
    panel(plot, controlled, report, MotionProblem::Controlled);
    panel(plot, free, report, MotionProblem::Free);
}

void exportWorkPrecision(const WorkPrecisionReport& report, const QString& caption,
                         const QString& dir, const QStringList& formats) {
    if (!QDir().mkpath(dir))
        throw IoError("cannot create the plot directory '" + dir.toStdString() + "'");
    QCustomPlot plot;
    drawWorkPrecision(plot, report);
    addCaption(plot, caption);
    QCPLayoutGrid* grid = plot.plotLayout();
    grid->insertRow(0);
    grid->addElement(
        0, 0,
        new QCPTextElement(&plot,
                           QCoreApplication::translate(
                               "WorkPrecisionPlot", "Work-precision: error against cost per solve"),
                           QFont(plot.font().family(), 12, QFont::Bold)));
    for (const QString& format : formats) {
        QByteArray bytes = renderPlot(plot, format, 1200, 600);
        QString file = QDir(dir).filePath(QStringLiteral("work_precision.") + format);
        if (bytes.isEmpty())
            throw IoError("cannot render '" + file.toStdString() + "'");
        writeFileAtomically(file.toStdString(), bytes.toStdString());
    }
}

} // namespace chaplygin::ui
