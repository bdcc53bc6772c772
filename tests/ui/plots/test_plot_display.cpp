// The plots as read in class: sensible ranges for flat series, equal aspect for the trajectory,
// the context menu export, titles off the ticks, compact legends, the Methods diagram. Offscreen,
// real widgets.
#include "panels/methods_panel.h"
#include "plots/plot_context_menu.h"
#include "plots/plot_figures.h"
#include "plots/plots_panel.h"
#include "shell/presentation_mode.h"
#include "window_fixture.h"

#include <QFile>
#include <QMenu>
#include <QtTest>
#include <qcustomplot.h>

#include <cmath>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

// the legend laid out in the plot (under it, not inset)
QCPLegend* legendOf(QCustomPlot* plot) {
    QCPLegend* legend = nullptr;
    for (QCPLayoutElement* e : plot->plotLayout()->elements(true))
        if (auto* l = qobject_cast<QCPLegend*>(e))
            legend = l;
    return legend;
}

} // namespace

class TestPlotDisplay : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_plot_display_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void flatSeriesGetsSensibleRange();
    void trajectoryPlotHasEqualAspect();
    void plotContextMenuExports();
    void plotTitleDoesNotOverlapTicks();
    void legendsAreCompact();
    void legendEntriesWholeWhenNarrowOrPresenting();
    void methodsTitlesAboveAndLegendShort();
    void valueTicksApartInPresentationAt1024();
};

void TestPlotDisplay::flatSeriesGetsSensibleRange() {
    // a constant 2.5 J with rounding noise: a +-10 % band, not a magnified 1e-10 wiggle
    QCPRange r = paddedRange(2.5, 2.5 + 1e-10);
    QVERIFY(std::abs(r.lower - 2.25) < 1e-9 && std::abs(r.upper - 2.75) < 1e-9);
    QCPRange zero = paddedRange(0, 0);
    QVERIFY(zero.lower < 0 && zero.upper > 0 && zero.size() < 0.01);
    QCPRange normal = paddedRange(0, 10);
    QCOMPARE(normal.lower, -0.5);
    QCOMPARE(normal.upper, 10.5);
    QCPRange bad = paddedRange(NAN, 1);
    QVERIFY(std::isfinite(bad.lower) && std::isfinite(bad.upper));
    // the energy plot of the energy mode: T is constant; the axis hugs it
    QCustomPlot* energy = m_window->plotsPanel()->plot(3);
    const double T = m_window->document()->series().energy.front();
    QCPRange y = energy->graph(0)->valueAxis()->range();
    QVERIFY(y.contains(T));
    QVERIFY(y.lower > 0);
    QVERIFY(y.size() <= 0.5 * T);
}

void TestPlotDisplay::trajectoryPlotHasEqualAspect() {
    QCustomPlot plot;
    drawPlot(plot, PlotKind::Trajectory, m_window->document()->series());
    for (QSize size : {QSize(900, 600), QSize(500, 700)}) {
        plot.resize(size);
        plot.replot();
        QCPAxisRect* rect = plot.axisRect();
        double mx = rect->axis(QCPAxis::atBottom)->range().size() / rect->width();
        double my = rect->axis(QCPAxis::atLeft)->range().size() / rect->height();
        QVERIFY2(std::abs(mx / my - 1) < 1e-9, qPrintable(QString::number(mx / my)));
        // the whole path stays in view
        const PlotSeries& s = m_window->document()->series();
        for (int i = 0; i < s.pathX.size(); ++i) {
            QVERIFY(rect->axis(QCPAxis::atBottom)->range().contains(s.pathX[i]));
            QVERIFY(rect->axis(QCPAxis::atLeft)->range().contains(s.pathY[i]));
        }
    }
}

void TestPlotDisplay::plotContextMenuExports() {
    QCustomPlot* plot = m_window->plotsPanel()->plot(2);
    const QSize shown = plot->size();
    QCOMPARE(plot->contextMenuPolicy(), Qt::CustomContextMenu);
    QMenu* menu = m_window->plotsPanel()->contextMenu(2);
    QVERIFY(menu && !menu->actions().isEmpty());
    test::DialogScript dialog;
    dialog.install();
    dialog.answer = m_dir.filePath(QStringLiteral("lambda-plot"));
    dialog.filter = QStringLiteral("SVG (*.svg)");
    menu->actions().first()->trigger();
    QVERIFY2(dialog.proposed.endsWith(QStringLiteral("/lambda.png")), qPrintable(dialog.proposed));
    QFile svg(m_dir.filePath(QStringLiteral("lambda-plot.svg")));
    QVERIFY(svg.open(QIODevice::ReadOnly));
    QVERIFY(svg.readAll().contains("<svg"));
    // the plot in the dock keeps its size
    QCOMPARE(plot->size(), shown);
    // a wrong extension is refused with a message naming the file
    try {
        exportPlotFile(*plot, m_dir.filePath(QStringLiteral("x.txt")));
        QFAIL("a .txt plot was written");
    } catch (const std::exception& e) {
        QVERIFY(QString::fromUtf8(e.what()).contains(QStringLiteral("x.txt")));
    }
    QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("x.txt"))));
    // the Methods diagram has the same menu
    QVERIFY(m_window->methodsPanel()->plotMenu());
}

void TestPlotDisplay::plotTitleDoesNotOverlapTicks() {
    // an exported plot: title row above the axis rect, never on its tick labels
    QCustomPlot plot;
    drawPlot(plot, PlotKind::Psi, m_window->document()->series());
    addCaption(plot, QStringLiteral("caption"));
    plot.resize(900, 600);
    plot.replot();
    QCPAxisRect* rect = plot.axisRect();
    auto* caption = qobject_cast<QCPTextElement*>(plot.plotLayout()->element(0, 0));
    QVERIFY(caption);
    // the tick labels of the left axis reach at most the top of the axis rect's outer margin
    QVERIFY(caption->outerRect().bottom() <= rect->outerRect().top() + 1);
    QVERIFY(rect->rect().top() - rect->outerRect().top() >= 0);
}

void TestPlotDisplay::legendsAreCompact() {
    m_window->resize(1280, 800);
    QApplication::processEvents();
    for (int i = 0; i < 4; ++i) {
        QCustomPlot* plot = m_window->plotsPanel()->plot(i);
        plot->replot();
        QCPLegend* legend = legendOf(plot);
        QVERIFY(legend);
        QVERIFY(legend->itemCount() <= 3);
        // one short row under the plot: its entries fit the width, it takes little height
        QVERIFY2(legend->minimumOuterSizeHint().width() <= plot->width(),
                 qPrintable(QStringLiteral("%1: %2 of %3")
                                .arg(i)
                                .arg(legend->minimumOuterSizeHint().width())
                                .arg(plot->width())));
        QVERIFY(legend->outerRect().height() < 0.2 * plot->height());
        QVERIFY(!legend->outerRect().intersects(plot->axisRect()->rect()));
        QVERIFY(legend->font().pointSizeF() <= plot->font().pointSizeF());
    }
}

void TestPlotDisplay::methodsTitlesAboveAndLegendShort() {
    choosePreset("line");
    MethodsPanel* panel = m_window->methodsPanel();
    m_window->showMethodsDock();
    panel->start();
    panel->waitForFinished();
    QCustomPlot* plot = panel->plot();
    plot->replot();
    QCOMPARE(plot->axisRectCount(), 2);
    for (QCPAxisRect* rect : plot->axisRects()) {
        // the title is the top axis's label, outside the frame; nothing is inset over the data
        QCPAxis* top = rect->axis(QCPAxis::atTop);
        QVERIFY(top->visible() && !top->label().isEmpty());
        QVERIFY(!top->tickLabels());
        for (int i = 0; i < rect->insetLayout()->elementCount(); ++i)
            QVERIFY(!qobject_cast<QCPTextElement*>(rect->insetLayout()->elementAt(i)));
        // one entry per method and a single one for every chosen star
        int methods = 0;
        for (QCPAbstractPlottable* p : rect->plottables())
            methods += p->name().startsWith(QLatin1String("chosen: ")) ? 0 : 1;
        QCPLegend* legend = nullptr;
        for (QCPLayoutElement* e : plot->plotLayout()->elements(true))
            if (auto* l = qobject_cast<QCPLegend*>(e)) {
                bool mine = false;
                for (int i = 0; i < l->itemCount(); ++i)
                    if (auto* item = qobject_cast<QCPPlottableLegendItem*>(l->item(i)))
                        mine = mine || item->plottable()->keyAxis()->axisRect() == rect;
                if (mine)
                    legend = l;
            }
        QVERIFY(legend);
        QVERIFY2(
            legend->itemCount() <= methods + 1,
            qPrintable(
                QStringLiteral("%1 entries for %2 methods").arg(legend->itemCount()).arg(methods)));
    }
}

void TestPlotDisplay::legendEntriesWholeWhenNarrowOrPresenting() {
    // at 1024x768 and in presentation mode (fonts x1.6) the legend under each plot wraps into
    // rows instead of cutting its last entries off ("controlle", "vakonom")
    auto check = [this](const char* when) {
        QApplication::processEvents();
        for (int i = 0; i < 4; ++i) {
            QCustomPlot* plot = m_window->plotsPanel()->plot(i);
            plot->replot();
            QCPLegend* legend = legendOf(plot);
            QVERIFY(legend);
            QVERIFY2(legend->minimumOuterSizeHint().width() <= plot->width(),
                     qPrintable(QStringLiteral("%1, plot %2: the legend needs %3 px of %4")
                                    .arg(QLatin1String(when))
                                    .arg(i)
                                    .arg(legend->minimumOuterSizeHint().width())
                                    .arg(plot->width())));
            for (int k = 0; k < legend->itemCount(); ++k) // wrapped: some cells are empty
                if (QCPAbstractLegendItem* item = legend->item(k))
                    QVERIFY(plot->rect().contains(item->outerRect()));
        }
    };
    m_window->resize(1024, 768);
    m_window->balanceDocks();
    check("1024x768");
    m_window->resize(1280, 800);
    m_window->balanceDocks();
    m_window->presentation()->setFullScreen(false);
    m_window->presentation()->setActive(true);
    check("presentation at 1280x800");
    m_window->presentation()->setActive(false);
    check("1280x800");
}

void TestPlotDisplay::valueTicksApartInPresentationAt1024() {
    // a projector at 1024x768 in presentation mode (fonts x1.6): the plots are low, and their
    // value tick labels must not run into each other
    m_window->resize(1024, 768);
    m_window->balanceDocks();
    m_window->presentation()->setFullScreen(false);
    m_window->presentation()->setActive(true);
    QApplication::processEvents();
    for (int i = 0; i < 4; ++i) {
        QCustomPlot* plot = m_window->plotsPanel()->plot(i);
        plot->replot();
        QCPAxis* y = plot->axisRect()->axis(QCPAxis::atLeft);
        // digits have no descenders: labels overlap when their ascents do
        const int label = QFontMetrics(y->tickLabelFont()).ascent();
        const QVector<double> ticks = y->tickVector();
        QVERIFY2(ticks.size() >= 2,
                 qPrintable(QStringLiteral("plot %1: %2 tick(s), rect %3 px, plot %4 px")
                                .arg(i)
                                .arg(ticks.size())
                                .arg(plot->axisRect()->height())
                                .arg(plot->height())));
        for (int k = 1; k < ticks.size(); ++k) {
            const double apart =
                std::abs(y->coordToPixel(ticks[k]) - y->coordToPixel(ticks[k - 1]));
            QVERIFY2(apart >= label, qPrintable(QStringLiteral("plot %1: ticks %2 px apart, labels "
                                                               "%3 px high")
                                                    .arg(i)
                                                    .arg(apart)
                                                    .arg(label)));
        }
    }
    m_window->presentation()->setActive(false);
}

QTEST_MAIN(TestPlotDisplay)
#include "test_plot_display.moc"
