// A planned motion played (docs/physics.md §10): the Plan tool's play action animates the chosen
// motion; while it is chosen, the plots of Psi, chi, lambda and T against RK4 integrations of the
// knife and of the free sleigh from the planned start, the Accuracy dock with its end and its
// certificate, the timeline on the motion's clock and File > Export plots are its own.
#include "canvas/plan_tool.h"
#include "canvas/scene_canvas.h"
#include "document/plot_series.h"
#include "document/scene_document.h"
#include "free_knife_rk4.h"
#include "panels/accuracy_readout.h"
#include "plan_tool_fixture.h"
#include "plots/plots_panel.h"
#include "scene/scene_plan.h"
#include "shell/main_window.h"
#include "shell/plan_timeline.h"
#include "shell/playback.h"
#include "shell/timeline_bar.h"

#include <QAction>
#include <QElapsedTimer>
#include <QRegularExpression>
#include <QSlider>
#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

using namespace chaplygin;
using namespace chaplygin::ui;
using namespace chaplygin::ui::test;

namespace {

// the graph of `plot` named `name`, or null
QCPGraph* graphNamed(QCustomPlot* plot, const QString& name) {
    for (int i = 0; i < plot->graphCount(); ++i)
        if (plot->graph(i)->name() == name)
            return plot->graph(i);
    return nullptr;
}

} // namespace

class TestPlanPlayback : public QObject, private test::PlanToolFixture {
    Q_OBJECT
  private slots:
    void initTestCase() { startSuite("ui_plan_playback_tests"); }
    void init() { openPlanWindow(); }
    void cleanup() { closeWindow(); }

    void playAnimatesTheChosenMotion();
    void thePlotsAndTheAccuracyDockShowTheChosenMotion();
    void theTimelineAndTheExportFollowThePlayedMotion();
};

void TestPlanPlayback::playAnimatesTheChosenMotion() {
    m_canvas->setPlanMode(true);
    QAction* play = m_window->findChild<QAction*>(QStringLiteral("playPlanAction"));
    QVERIFY(play && play->isEnabled());
    QVERIFY(m_window->timeline()->actions().contains(play));
    QCOMPARE(m_tool->playTime(), -1.0);
    play->trigger();
    QVERIFY(m_tool->playing());
    QTRY_VERIFY_WITH_TIMEOUT(m_tool->playTime() > 0.5, 3000);
    QVERIFY(m_tool->chosenSummary().contains(QStringLiteral("k = ")));
    // the straight path's end, 4 s ahead: the last frame is the motion's end
    QTRY_VERIFY_WITH_TIMEOUT(!m_tool->playing(), 8000);
    QCOMPARE(m_tool->playTime(), 4.0);
    m_canvas->setPlanMode(false);
    QVERIFY(!play->isEnabled());
    QCOMPARE(m_tool->playTime(), -1.0);
}

void TestPlanPlayback::thePlotsAndTheAccuracyDockShowTheChosenMotion() {
    Scene s = straightScene();
    s.plan = ScenePlan{};
    s.plan->to = {1.5, 2.0, -2.0};
    m_window->document()->loadNow(s);
    PlotsPanel* plots = m_window->plotsPanel();
    AccuracyReadout* accuracy = m_window->accuracyReadout();
    // a scene with a plan opens in plan mode: its plots at once
    QVERIFY(m_canvas->planMode());
    QVERIFY(plots->showsPlan());
    QVERIFY(accuracy->plan());
    m_canvas->setPlanMode(false);
    QVERIFY(!plots->showsPlan());
    QVERIFY(!accuracy->plan());
    m_canvas->setPlanMode(true);
    QCOMPARE(m_tool->chosen(), 0);
    QVERIFY(plots->showsPlan());
    // the motion played to its end: the cursor at the played time
    QAction* play = m_window->findChild<QAction*>(QStringLiteral("playPlanAction"));
    play->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(m_tool->playTime() > 0.3, 3000);
    QCOMPARE(plots->cursorTime(), m_tool->playTime());
    QTRY_VERIFY_WITH_TIMEOUT(!m_tool->playing(), 15000);

    const DerivedSystem& sys = m_window->document()->solution()->system();
    const double m = sys.mass, a = sys.a, b = sys.b, v = m_window->document()->scene().speed;
    QVERIFY(a != 0); // chi differs from Psi, and the ghost turns
    // each chosen motion: the plotted curves against RK4 integrations of the knife and of the
    // free sleigh from the planned start, at the plotted times
    auto checkCurves = [&](const PlannedGeodesic& g) {
        QCOMPARE(plots->cursorTime(), m_tool->playTime());
        QVERIFY(plots->showsPlan());
        const QString names[4][2] = {
            {QStringLiteral("planned \u03a8 (vakonomic)"), QStringLiteral("free \u03a8")},
            {QStringLiteral("planned \u03c7 (vakonomic)"),
             QStringLiteral("free \u03c7 (constant)")},
            {QStringLiteral("planned \u03bb (eq. 21)"), QString()},
            {QStringLiteral("planned T (vakonomic)"), QStringLiteral("free T")}};
        QCPGraph* body = graphNamed(plots->plot(0), names[0][0]);
        QVERIFY(body);
        const int n = body->dataCount();
        QVERIFY(n >= 100);
        const int sub = 40, steps = (n - 1) * sub;
        const auto knife = integrateKnife({0, 0, 0, g.psi0, g.psidot0}, b, v, g.t, steps);
        const auto ghost = reference::integrateFree(
            {0, 0, 0, v * std::sin(g.psi0), v * std::cos(g.psi0) / b}, a, b, g.t, steps);
        double worst[4][2] = {};
        for (int kind = 0; kind < 4; ++kind) {
            // no controlled body: the scene's curves are gone
            QVERIFY(!graphNamed(plots->plot(kind), QStringLiteral("controlled \u03a8")));
            for (int who = 0; who < 2; ++who) {
                if (names[kind][who].isEmpty()) // the free body has no multiplier
                    continue;
                QCPGraph* graph = graphNamed(plots->plot(kind), names[kind][who]);
                QVERIFY2(graph, qPrintable(names[kind][who]));
                QCOMPARE(graph->dataCount(), n);
                for (int i = 0; i < n; ++i) {
                    const QCPGraphData d = *graph->data()->at(i);
                    QVERIFY(std::abs(d.key - g.t * i / (n - 1)) <= 1e-12 * g.t);
                    const Knife& k = knife[std::size_t(i * sub)];
                    const reference::FreeKnife& f = ghost[std::size_t(i * sub)];
                    const double fpsi = std::atan2(f.sdot, b * f.phidot);
                    double miss = 0;
                    switch (kind) {
                    case 0: // Psi, the branch the closed form keeps continuous
                        miss = angleMiss(d.value, who == 0 ? k.psi : fpsi);
                        break;
                    case 1: // chi = Psi - (a/b) phi
                        miss = angleMiss(d.value,
                                         who == 0 ? k.psi - a / b * k.phi : fpsi - a / b * f.phi);
                        break;
                    case 2: // lambda = m (b Psidot - a phidot), phidot = v cos Psi / b
                        miss = std::abs(d.value - m * (b * k.lambda - a * v * std::cos(k.psi) / b));
                        break;
                    case 3: // T = (m/2)(sdot^2 + b^2 phidot^2)
                        miss = std::abs(
                            d.value -
                            (who == 0 ? 0.5 * m * v * v
                                      : 0.5 * m * (f.sdot * f.sdot + b * b * f.phidot * f.phidot)));
                        break;
                    }
                    worst[kind][who] = std::max(worst[kind][who], miss);
                }
            }
        }
        qInfo("motion of %.4f s, worst against RK4: Psi %.1e / free %.1e, chi %.1e / free %.1e, "
              "lambda %.1e, T %.1e / free %.1e",
              g.t, worst[0][0], worst[0][1], worst[1][0], worst[1][1], worst[2][0], worst[3][0],
              worst[3][1]);
        for (const auto& row : worst)
            for (double w : row)
                QVERIFY2(w < 1e-11, qPrintable(QString::number(w)));
        // the Accuracy dock: the end on the target and the certificate
        QVERIFY(accuracy->plan());
        QVERIFY(
            accuracy->findChild<QWidget*>(QStringLiteral("accuracyPlan"))->isVisibleTo(accuracy));
        QCOMPARE(accuracy->plan()->t, g.t);
        QVERIFY2(accuracy->plan()->endError < 1e-10,
                 qPrintable(QString::number(accuracy->plan()->endError)));
        QCOMPARE(accuracy->plan()->optimal, g.optimal);
        QVERIFY(!accuracy->planEndErrorText().isEmpty());
        QCOMPARE(accuracy->planOptimalText().startsWith(QStringLiteral("certified")), g.optimal);
    };
    {
        // what a plan made while dragging costs the UI thread for the plots
        QElapsedTimer clock;
        clock.start();
        plots->showPlan(
            collectPlanSeries(m_tool->plannedRequest(), m_tool->planned().geodesics[0]));
        plots->replotNow();
        qInfo("the plots of a planned motion drawn in %.2f ms", clock.nsecsElapsed() * 1e-6);
    }
    const PlannedGeodesic first = m_tool->planned().geodesics.at(0);
    QVERIFY(first.optimal);
    QCOMPARE(m_tool->playTime(), first.t);
    checkCurves(first);
    QCOMPARE(accuracy->plan()->index, 1);
    // the cursor drawn at the played time, and a click on a plot moves the played bodies there
    plots->replotNow();
    QCPAxis* axis = plots->plot(0)->axisRect()->axis(QCPAxis::atBottom);
    QVERIFY(plots->cursor(0)->isVisible());
    QVERIFY(std::abs(plots->cursor(0)->geometry().center().x() + 0.5 -
                     axis->coordToPixel(first.t)) <= 1.5);
    const QPoint at(int(std::lround(axis->coordToPixel(1.0))),
                    plots->plot(0)->axisRect()->center().y());
    QTest::mouseClick(plots->plot(0), Qt::LeftButton, {}, at);
    QTRY_VERIFY(!plots->seekPending()); // a click seeks once it cannot be a double click
    QVERIFY2(std::abs(m_tool->playTime() - 1.0) <=
                 2 * axis->range().size() / axis->axisRect()->width(),
             qPrintable(QString::number(m_tool->playTime())));
    QCOMPARE(plots->cursorTime(), m_tool->playTime());
    QCOMPARE(m_window->playback()->time(), 0.0); // the scene's clock stays
    // CHAPLYGIN_PLAN_SHOTS: a folder for the picture to look at
    if (const QString shots = qEnvironmentVariable("CHAPLYGIN_PLAN_SHOTS"); !shots.isEmpty()) {
        plots->replotNow();
        QVERIFY(m_window->grab().save(shots + QStringLiteral("/plan-played.png")));
    }

    // another motion chosen: its curves, not the first's; not the least time, not optimal
    const int last = int(m_tool->planned().geodesics.size()) - 1;
    QVERIFY(last >= 1);
    Scene other = m_window->document()->scene();
    other.plan->choice = last;
    m_window->document()->edit(other, QStringLiteral("choose"));
    m_window->document()->flush();
    QCOMPARE(m_tool->chosen(), last);
    const PlannedGeodesic later = m_tool->planned().geodesics.at(std::size_t(last));
    QVERIFY(!later.optimal);
    m_tool->showAt(0.5 * later.t);
    checkCurves(later);
    QCOMPARE(accuracy->plan()->index, last + 1);
    QCOMPARE(accuracy->plan()->count, last + 1);

    // out of plan mode: the scene's plots and no plan in the Accuracy dock
    m_canvas->setPlanMode(false);
    QVERIFY(!plots->showsPlan());
    QVERIFY(!accuracy->plan());
    QVERIFY(!accuracy->findChild<QWidget*>(QStringLiteral("accuracyPlan"))->isVisibleTo(accuracy));
    QCOMPARE(plots->cursorTime(), m_window->playback()->time());
    QCPGraph* controlled = graphNamed(plots->plot(0), QStringLiteral("controlled \u03a8"));
    QVERIFY(controlled);
    QCOMPARE(controlled->dataCount(), int(m_window->document()->series().t.size()));
    QVERIFY(!graphNamed(plots->plot(0), QStringLiteral("planned \u03a8 (vakonomic)")));
}

// While a motion is chosen in plan mode the timeline is its own: it runs over the motion's
// duration, follows the played time, and moves the played bodies; File > Export plots writes the
// motion's plots (its genuine vakonomic body and the free ghost), not the scene's.
void TestPlanPlayback::theTimelineAndTheExportFollowThePlayedMotion() {
    Scene s = straightScene();
    s.plan = ScenePlan{};
    s.plan->to = {0.6, 0.4, 1.0};
    m_window->document()->loadNow(s);
    QVERIFY(m_canvas->planMode());
    TimelineBar* timeline = m_window->timeline();
    Playback* scene = m_window->playback();
    const double sceneEnd = m_window->document()->solution()->tEnd();
    QCOMPARE(scene->tEnd(), sceneEnd);
    QCOMPARE(m_tool->chosen(), 0);
    const PlannedGeodesic g = m_tool->planned().geodesics.at(0);
    QVERIFY2(std::abs(g.t - sceneEnd) > 0.5, // the two durations tell apart
             qPrintable(QStringLiteral("%1 %2").arg(g.t).arg(sceneEnd)));
    // the bar shows the plan's clock over the motion's duration
    QCOMPARE(timeline->playback(), &m_window->planTimeline()->clock());
    QCOMPARE(timeline->playback()->tEnd(), g.t);
    QVERIFY2(timeline->timeLabel()->text().contains(QStringLiteral("/ %1 s").arg(g.t, 0, 'f', 2)),
             qPrintable(timeline->timeLabel()->text()));
    // played: the bar's time is the played time, to the motion's end
    m_window->findChild<QAction*>(QStringLiteral("playPlanAction"))->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(m_tool->playTime() > 0.3, 3000);
    QCOMPARE(timeline->playback()->time(), m_tool->playTime());
    QTRY_VERIFY_WITH_TIMEOUT(!m_tool->playing(), 15000);
    QCOMPARE(m_tool->playTime(), g.t);
    QCOMPARE(timeline->playback()->time(), g.t);
    QCOMPARE(timeline->slider()->value(), timeline->slider()->maximum());
    // the slider moves the played bodies along the motion
    timeline->slider()->setValue(timeline->slider()->maximum() / 4);
    QVERIFY2(std::abs(m_tool->playTime() - 0.25 * g.t) <= 1e-12 * g.t,
             qPrintable(QString::number(m_tool->playTime())));
    QVERIFY(timeline->timeLabel()->text().contains(
        QStringLiteral("%1 s /").arg(0.25 * g.t, 0, 'f', 2)));
    // and the bar's play plays them, at the bar's speed
    timeline->playAction()->trigger();
    QVERIFY(timeline->playback()->isPlaying());
    QTRY_VERIFY_WITH_TIMEOUT(m_tool->playTime() > 0.3 * g.t, 3000);
    QCOMPARE(m_tool->playTime(), timeline->playback()->time());
    timeline->playAction()->trigger();
    QVERIFY(!timeline->playback()->isPlaying());
    // the scene's clock never moved
    QCOMPARE(scene->time(), 0.0);
    QCOMPARE(scene->tEnd(), sceneEnd);

    // the export: the chosen motion's four time plots, with its curves and its caption
    QTemporaryDir dir;
    const QString planned = dir.filePath(QStringLiteral("planned"));
    QVERIFY(m_window->exportPlotsTo(planned, {QStringLiteral("svg"), QStringLiteral("png")}));
    const QString curves[4][2] = {
        {QStringLiteral("psi"), QStringLiteral("planned \u03a8 (vakonomic)")},
        {QStringLiteral("chi"), QStringLiteral("planned \u03c7 (vakonomic)")},
        {QStringLiteral("lambda"), QStringLiteral("planned \u03bb (eq. 21)")},
        {QStringLiteral("energy"), QStringLiteral("planned T (vakonomic)")}};
    const QString ghost[4] = {QStringLiteral("free \u03a8"), QStringLiteral("free \u03c7"),
                              QString(), QStringLiteral("free T")};
    for (int i = 0; i < 4; ++i) {
        QFile svg(planned + QLatin1Char('/') + curves[i][0] + QStringLiteral(".svg"));
        QVERIFY2(svg.open(QIODevice::ReadOnly), qPrintable(svg.fileName()));
        // the words drawn: the SVG's text items in order (a Greek letter is a run of its own)
        QString text;
        const QRegularExpression item(QStringLiteral(">([^<]*)</text>"));
        for (const auto& m : item.globalMatch(QString::fromUtf8(svg.readAll())))
            text += m.captured(1);
        const auto has = [&](const QString& words) { return text.contains(words.toHtmlEscaped()); };
        QVERIFY2(has(curves[i][1]), qPrintable(curves[i][0]));
        if (!ghost[i].isEmpty())
            QVERIFY2(has(ghost[i]), qPrintable(curves[i][0]));
        QVERIFY2(!has(QStringLiteral("controlled")), qPrintable(curves[i][0]));
        QVERIFY2(has(QStringLiteral("planned motion from")), qPrintable(curves[i][0]));
        QVERIFY2(has(QStringLiteral("t = %1 s").arg(g.t, 0, 'g', 10)), qPrintable(curves[i][0]));
        QVERIFY(
            !QImage(planned + QLatin1Char('/') + curves[i][0] + QStringLiteral(".png")).isNull());
    }
    // CHAPLYGIN_PLAN_SHOTS: the window with the bar on the plan's clock and the exported plots
    if (const QString shots = qEnvironmentVariable("CHAPLYGIN_PLAN_SHOTS"); !shots.isEmpty()) {
        QVERIFY(m_window->grab().save(shots + QStringLiteral("/plan-timeline.png")));
        QVERIFY(m_window->exportPlotsTo(shots + QStringLiteral("/plan-plots"),
                                        {QStringLiteral("png")}));
    }
    // the scene's trajectory and the paper's figure are the scene's, not the plan's
    QVERIFY(!QFile::exists(planned + QStringLiteral("/trajectory.svg")));
    // the exported curve is the motion's: its time axis ends at the motion's end, and the data
    // drawn are those the Plots dock shows for it (checked against RK4 above)
    const PlotSeries series = collectPlanSeries(m_tool->plannedRequest(), g, 800);
    QCOMPARE(series.vakT.back(), g.t);

    // out of plan mode: the scene's clock on the bar again, where it was, and the scene's plots
    m_canvas->setPlanMode(false);
    QCOMPARE(timeline->playback(), scene);
    QCOMPARE(scene->time(), 0.0);
    QVERIFY(
        timeline->timeLabel()->text().contains(QStringLiteral("/ %1 s").arg(sceneEnd, 0, 'f', 2)));
    const QString sceneDir = dir.filePath(QStringLiteral("scene"));
    QVERIFY(m_window->exportPlotsTo(sceneDir, {QStringLiteral("svg")}));
    QFile psi(sceneDir + QStringLiteral("/psi.svg"));
    QVERIFY(psi.open(QIODevice::ReadOnly));
    const QByteArray scenePsi = psi.readAll();
    QVERIFY(scenePsi.contains(">controlled "));
    QVERIFY(!scenePsi.contains("planned motion from"));
}

QTEST_MAIN(TestPlanPlayback)
#include "test_plan_playback.moc"
