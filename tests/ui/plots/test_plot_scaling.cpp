// Plots scaled for the controlled quantities: the value axes follow the controlled body and the
// pinned runs (their extremes taken from the Solution, not from the plot), the free and
// vakonomic curves are clipped at the frame with a mark, "Fit all curves" shows them whole, no
// NaN or 1e6 swamps a plot, and the tick labels stay apart at every window size and in
// presentation mode. Offscreen, real widgets.
#include "document/pin_set.h"
#include "plots/axis_fitting.h"
#include "plots/pixel_ticker.h"
#include "plots/plot_context_menu.h"
#include "plots/plot_figures.h"
#include "plots/plots_panel.h"
#include "plots/time_axes.h"
#include "shell/playback.h"
#include "shell/presentation_mode.h"
#include "window_fixture.h"

#include <QAction>
#include <QFontInfo>
#include <QtTest>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

struct Extent {
    double lo = INFINITY, hi = -INFINITY;
    void add(double v) {
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    double size() const { return hi - lo; }
};

// a quantity of the Solution at 4001 even times (finer than any plot's samples)
Extent extentOf(const Solution& s, const std::function<double(const Solution&, double)>& f) {
    Extent e;
    for (int i = 0; i <= 4000; ++i)
        e.add(f(s, s.tEnd() * i / 4000));
    return e;
}

double controlledPsi(const Solution& s, double t) {
    return s.at(t).control.psi;
}
double controlledLambda(const Solution& s, double t) {
    return s.at(t).control.lambda;
}
double controlledChi(const Solution& s, double t) {
    return s.at(t).control.chi;
}
double vakPsi(const Solution& s, double t) {
    return s.vakonomicAt(t).psi;
}
double vakLambda(const Solution& s, double t) {
    return s.vakonomicAt(t).lambda;
}
double freePsi(const Solution& s, double t) {
    return s.freeAt(t).psi;
}

QString describe(const QCPRange& axis, const Extent& e) {
    return QStringLiteral("axis [%1, %2], controlled [%3, %4]")
        .arg(axis.lower)
        .arg(axis.upper)
        .arg(e.lo)
        .arg(e.hi);
}

// the axis holds the controlled extent (to the plot's own sampling: the live plots sample the
// path table's nodes) and the controlled curve fills at least 60 % of it
void checkFollows(const QCPRange& axis, const Extent& controlled, const char* what) {
    const double slack = 1e-3 * controlled.size();
    QVERIFY2(axis.lower <= controlled.lo + slack && axis.upper >= controlled.hi - slack,
             qPrintable(QLatin1String(what) + QStringLiteral(": ") + describe(axis, controlled)));
    QVERIFY2(controlled.size() >= 0.6 * axis.size(),
             qPrintable(QLatin1String(what) + QStringLiteral(" swamped: ") +
                        describe(axis, controlled)));
}

bool hasMark(QCPAxisRect* rect, const QString& arrow, const QString& name) {
    for (const QString& mark : clipMarks(*rect))
        if (mark.contains(arrow) && mark.contains(name))
            return true;
    return false;
}

const QString kUp = QStringLiteral("\u2191"), kDown = QStringLiteral("\u2193");

} // namespace

class TestPlotScaling : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_plot_scaling_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void sinusoidAxesFollowTheControlledBody();
    void fitAllCurvesShowsEveryCurveAndIsUndone();
    void pinnedRunsSetTheRangeToo();
    void highCurvatureControlledCurvesAreNotFlat();
    void nanAndHugeValuesDoNotSwampAPlot();
    void exportedFiguresUseTheSameScaling();
    void tickStepsAreReadable();
    void tickLabelsApartAtEverySize();

  private:
    void checkTicksApart(QCustomPlot* plot, const QString& when);
};

void TestPlotScaling::sinusoidAxesFollowTheControlledBody() {
    choosePreset("sinusoid");
    PlotsPanel* plots = m_window->plotsPanel();
    plots->replotNow();
    const Solution& s = *m_window->document()->solution();
    QCPAxisRect* psi = plots->plot(0)->axisRect();
    QCPAxisRect* lambda = plots->plot(2)->axisRect();
    const QCPRange psiAxis = psi->axis(QCPAxis::atLeft)->range();
    const QCPRange lambdaAxis = lambda->axis(QCPAxis::atLeft)->range();
    checkFollows(psiAxis, extentOf(s, controlledPsi), "psi");
    checkFollows(lambdaAxis, extentOf(s, controlledLambda), "lambda");
    checkFollows(plots->plot(1)->axisRect()->axis(QCPAxis::atLeft)->range(),
                 extentOf(s, controlledChi), "chi");
    // the vakonomic body no longer sets the range: its Psi (to -8 rad) and lambda (to -1.5) leave
    // through the bottom, each with its mark there
    QVERIFY2(extentOf(s, vakPsi).lo < psiAxis.lower - 0.5,
             qPrintable(describe(psiAxis, extentOf(s, vakPsi))));
    QVERIFY(extentOf(s, vakLambda).lo < lambdaAxis.lower);
    QVERIFY2(hasMark(psi, kDown, QStringLiteral("vakonomic")),
             qPrintable(clipMarks(*psi).join('|')));
    QVERIFY(hasMark(lambda, kDown, QStringLiteral("vakonomic")));
    QVERIFY(!hasMark(lambda, kUp, QStringLiteral("vakonomic"))); // it never leaves at the top
    // the mark stands at the frame, where the curve leaves
    for (int i = 0; i < plots->plot(0)->itemCount(); ++i)
        if (auto* mark = qobject_cast<QCPItemText*>(plots->plot(0)->item(i))) {
            const QPointF at = mark->position->pixelPosition();
            QVERIFY(std::abs(at.y() - psi->bottom()) <= 1 || std::abs(at.y() - psi->top()) <= 1 ||
                    mark->position->parentAnchorY());
            QVERIFY(at.x() >= psi->left() - 1 && at.x() <= psi->right() + 1);
        }
}

void TestPlotScaling::fitAllCurvesShowsEveryCurveAndIsUndone() {
    choosePreset("sinusoid");
    PlotsPanel* plots = m_window->plotsPanel();
    const Solution& s = *m_window->document()->solution();
    QCustomPlot* psi = plots->plot(0);
    QAction* fitAll = plots->fitAllAction(0);
    QVERIFY(fitAll && fitAll->isCheckable() && !fitAll->isChecked());
    QVERIFY(plots->contextMenu(0)->actions().contains(fitAll)); // in the plot's context menu
    fitAll->setChecked(true);
    plots->replotNow();
    const QCPRange all = psi->axisRect()->axis(QCPAxis::atLeft)->range();
    for (auto f : {controlledPsi, vakPsi, freePsi}) {
        const Extent e = extentOf(s, f);
        QVERIFY2(all.lower <= e.lo && all.upper >= e.hi, qPrintable(describe(all, e)));
    }
    QVERIFY(clipMarks(*psi->axisRect()).isEmpty());
    // the choice is the plot's: it survives a recompute, and the other plots keep theirs
    Scene faster = m_window->document()->scene();
    faster.speed = 1.5;
    m_window->document()->edit(faster, QStringLiteral("faster"));
    m_window->document()->flush();
    QVERIFY(clipMarks(*psi->axisRect()).isEmpty());
    QVERIFY(psi->axisRect()->axis(QCPAxis::atLeft)->range().lower <=
            extentOf(*m_window->document()->solution(), vakPsi).lo);
    QVERIFY(!plots->fitAllAction(2)->isChecked());
    QVERIFY(!clipMarks(*plots->plot(2)->axisRect()).isEmpty());
    fitAll->setChecked(false);
    checkFollows(psi->axisRect()->axis(QCPAxis::atLeft)->range(),
                 extentOf(*m_window->document()->solution(), controlledPsi), "psi again");
    QVERIFY(!clipMarks(*psi->axisRect()).isEmpty());
}

void TestPlotScaling::pinnedRunsSetTheRangeToo() {
    // a run pinned at b = 2.2 turns harder (Psi from 0.43 to 2.71 rad): the axis holds it
    Scene scene = presetScene("sinusoid");
    PinnedRun pin{scene.path, scene.system, scene.mode, scene.speed, scene.tEnd};
    pin.system.params["b"] = 2.2;
    pin.system.params.erase("I");
    scene.pins.push_back(pin);
    m_window->loadScene(scene);
    m_window->document()->flush();
    PinSet* pins = m_window->document()->pins();
    QCOMPARE(pins->count(), 1);
    const Solution& pinned = *pins->run(0).solution;
    Extent both = extentOf(*m_window->document()->solution(), controlledPsi);
    const Extent pinnedPsi = extentOf(pinned, controlledPsi);
    both.add(pinnedPsi.lo);
    both.add(pinnedPsi.hi);
    QVERIFY(pinnedPsi.lo < extentOf(*m_window->document()->solution(), controlledPsi).lo - 0.2);
    m_window->plotsPanel()->replotNow();
    checkFollows(m_window->plotsPanel()->plot(0)->axisRect()->axis(QCPAxis::atLeft)->range(), both,
                 "psi with the pin");
}

void TestPlotScaling::highCurvatureControlledCurvesAreNotFlat() {
    // b kappa = 1000: the free and vakonomic Psi run to -1e6 rad and beyond; the controlled Psi,
    // chi and lambda still fill their plots
    QVERIFY(m_window->loadGalleryEntry(QStringLiteral("high-curvature")));
    m_window->document()->flush();
    PlotsPanel* plots = m_window->plotsPanel();
    plots->replotNow();
    const Solution& s = *m_window->document()->solution();
    QVERIFY(extentOf(s, freePsi).size() + extentOf(s, vakPsi).size() > 1e3);
    const char* names[] = {"psi", "chi", "lambda"};
    for (int i = 0; i < 3; ++i) {
        QCustomPlot* plot = plots->plot(i);
        const QCPRange axis = plot->axisRect()->axis(QCPAxis::atLeft)->range();
        QVERIFY(std::isfinite(axis.lower) && std::isfinite(axis.upper));
        // the plot's own controlled curve, as drawn
        Extent drawn;
        for (const QCPGraphData& d : *plot->graph(0)->data())
            drawn.add(d.value);
        checkFollows(axis, drawn, names[i]);
    }
    QVERIFY(!clipMarks(*plots->plot(0)->axisRect()).isEmpty());
}

void TestPlotScaling::nanAndHugeValuesDoNotSwampAPlot() {
    PlotSeries s;
    for (int i = 0; i <= 100; ++i) {
        const double t = 0.1 * i;
        s.t << t;
        s.psi << 1 + 0.5 * std::sin(t);
        s.freeT << t;
        s.freePsi << (i == 40 ? NAN : i == 60 ? INFINITY : -1e6 * t);
        s.vakT << t;
        s.vakPsi << (i == 50 ? NAN : 1 + 0.4 * std::cos(t));
    }
    s.psi[30] = NAN; // a gap in the controlled curve too
    QCustomPlot plot;
    plot.resize(600, 400);
    drawPlot(plot, PlotKind::Psi, s);
    plot.replot();
    const QCPRange axis = plot.axisRect()->axis(QCPAxis::atLeft)->range();
    Extent controlled;
    for (double v : s.psi)
        controlled.add(v);
    checkFollows(axis, controlled, "psi with NaN and 1e6");
    QVERIFY(hasMark(plot.axisRect(), kDown, QStringLiteral("free")));
    const QCPRange key = plot.axisRect()->axis(QCPAxis::atBottom)->range();
    QVERIFY(key.lower <= 0 && key.upper >= 10 && key.upper < 11);
    // all curves: every finite value, and still no NaN or infinity in the range
    setFitAllCurves(plot, true);
    const QCPRange all = plot.axisRect()->axis(QCPAxis::atLeft)->range();
    QVERIFY(std::isfinite(all.lower) && std::isfinite(all.upper));
    QVERIFY(all.lower <= -1e7 && all.upper >= 1.5);
}

void TestPlotScaling::exportedFiguresUseTheSameScaling() {
    // --plots and File > Export plots draw collectSeries(solution, 800, 800) with drawPlot: the
    // controlled body sets the range there too, at the figure's size
    choosePreset("sinusoid");
    const Solution& s = *m_window->document()->solution();
    const PlotSeries exact = collectSeries(s, 800, 800);
    for (auto [kind, f, name] : {std::tuple{PlotKind::Psi, &controlledPsi, "psi"},
                                 std::tuple{PlotKind::Lambda, &controlledLambda, "lambda"}}) {
        QCustomPlot figure;
        drawPlot(figure, kind, exact);
        figure.resize(900, 600);
        figure.replot();
        checkFollows(figure.axisRect()->axis(QCPAxis::atLeft)->range(), extentOf(s, f), name);
        QVERIFY(hasMark(figure.axisRect(), kDown, QStringLiteral("vakonomic")));
        checkTicksApart(&figure, QStringLiteral("exported ") + QLatin1String(name));
    }
}

void TestPlotScaling::tickStepsAreReadable() {
    QCOMPARE(PixelTicker::readableStep(0.7), 1.0);
    QCOMPARE(PixelTicker::readableStep(1.0), 1.0);
    QCOMPARE(PixelTicker::readableStep(1.3), 2.0);
    QCOMPARE(PixelTicker::readableStep(2.2), 2.5);
    QCOMPARE(PixelTicker::readableStep(3.0), 5.0);
    QCOMPARE(PixelTicker::readableStep(6.0), 10.0);
    QVERIFY(std::abs(PixelTicker::readableStep(0.031) - 0.05) < 1e-15);
    QCOMPARE(PixelTicker::readableStep(2.1e5), 2.5e5);
    QCOMPARE(PixelTicker::ticksIn(QCPRange(-0.1, 2.1), 1), 3);
    QCOMPARE(PixelTicker::ticksIn(QCPRange(0.1, 0.9), 1), 0);
    // a value axis 60 px high with 20 px labels and the range [0, 10]: 2.5 a step is too close
    // (15 px), 5 leaves three ticks 30 px apart
    QCustomPlot plot;
    plot.resize(400, 160);
    QCPAxis* y = plot.yAxis;
    QFont font = y->tickLabelFont();
    font.setPixelSize(20);
    y->setTickLabelFont(font);
    y->setRange(0, 10);
    fitAxesAfterLayout(plot);
    plot.replot();
    const double label = QFontMetricsF(font).height();
    const QVector<double> ticks = y->tickVector();
    QVERIFY(ticks.size() >= 2);
    const double apart = std::abs(y->coordToPixel(ticks[1]) - y->coordToPixel(ticks[0]));
    QVERIFY2(apart >= 1.15 * label, qPrintable(QString::number(apart)));
    QVERIFY2(apart <= 2 * 1.6 * label + 1, qPrintable(QString::number(apart)));
}

void TestPlotScaling::checkTicksApart(QCustomPlot* plot, const QString& when) {
    for (QCPAxisRect* rect : plot->axisRects()) {
        for (QCPAxis* axis : {rect->axis(QCPAxis::atLeft), rect->axis(QCPAxis::atBottom)}) {
            const bool vertical = axis->orientation() == Qt::Vertical;
            const QFontMetricsF metrics(axis->tickLabelFont());
            const QVector<double> ticks = axis->tickVector();
            const QVector<QString> labels = axis->tickVectorLabels();
            const QString where =
                QStringLiteral("%1, %2 %3 axis: ")
                    .arg(when, plot->objectName(),
                         vertical ? QStringLiteral("value") : QStringLiteral("time"));
            QVERIFY2(ticks.size() >= 2,
                     qPrintable(where + QStringLiteral("%1 tick(s) on %2 px, range [%3, %4]")
                                            .arg(ticks.size())
                                            .arg(vertical ? rect->height() : rect->width())
                                            .arg(axis->range().lower)
                                            .arg(axis->range().upper)));
            for (int k = 1; k < ticks.size(); ++k) {
                const double apart =
                    std::abs(axis->coordToPixel(ticks[k]) - axis->coordToPixel(ticks[k - 1]));
                // labels are centred on their ticks: they touch when the distance is less than
                // a label's height (value axis) or half of both labels' widths (time axis)
                const double need = vertical ? metrics.height()
                                             : 0.5 * (metrics.horizontalAdvance(labels[k]) +
                                                      metrics.horizontalAdvance(labels[k - 1])) +
                                                   metrics.horizontalAdvance(QLatin1Char('0'));
                QVERIFY2(apart >= need, qPrintable(where + QStringLiteral("ticks %1 and %2 are %3 "
                                                                          "px apart, need %4")
                                                               .arg(labels[k - 1], labels[k])
                                                               .arg(apart)
                                                               .arg(need)));
            }
        }
    }
}

void TestPlotScaling::tickLabelsApartAtEverySize() {
    // with the error plot too: the pushed scene
    QVERIFY(m_window->loadGalleryEntry(QStringLiteral("pushed-off-path")));
    m_window->document()->flush();
    PlotsPanel* plots = m_window->plotsPanel();
    auto check = [&](const QString& when, bool presenting) {
        QApplication::processEvents();
        for (int i = 0; i < 4; ++i) {
            plots->plot(i)->replot();
            checkTicksApart(plots->plot(i), when);
            if (presenting) // legible from the back of the room
                QVERIFY2(
                    QFontInfo(plots->plot(i)->axisRect()->axis(QCPAxis::atLeft)->tickLabelFont())
                            .pixelSize() >= 14,
                    qPrintable(when));
        }
        QVERIFY(plots->errorPlot()->isVisible());
        plots->errorPlot()->replot();
        checkTicksApart(plots->errorPlot(), when);
    };
    for (QSize size : {QSize(1024, 768), QSize(1280, 800), QSize(1920, 1080)}) {
        const QString name = QStringLiteral("%1x%2").arg(size.width()).arg(size.height());
        m_window->presentation()->setActive(false);
        m_window->resize(size);
        m_window->balanceDocks();
        check(name, false);
        m_window->presentation()->setFullScreen(false);
        m_window->presentation()->setActive(true);
        check(QStringLiteral("presentation at ") + name, true);
    }
    m_window->presentation()->setActive(false);
}

QTEST_MAIN(TestPlotScaling)
#include "test_plot_scaling.moc"
