// The time plots' time at every scale: the wheel zooms the shared time range about the time under
// the mouse, a drag pans it, a double click shows the whole run, a window follows the time cursor,
// and every range stays finite, within the run and a few samples wide. The expected ranges come
// from the axes' pixel geometry and the document's series, computed here.
#include "canvas/scene_canvas.h"
#include "plots/plots_panel.h"
#include "plots/time_window.h"
#include "shell/playback.h"
#include "window_fixture.h"

#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QWheelEvent>
#include <QtTest>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

QCPAxis* timeAxis(QCustomPlot* plot) {
    return plot->axisRect()->axis(QCPAxis::atBottom);
}

// the time at pixel column x of a linear axis, from its rectangle and range
double timeAtPixel(QCustomPlot* plot, double x) {
    QCPAxisRect* rect = plot->axisRect();
    const QCPRange r = timeAxis(plot)->range();
    return r.lower + (x - rect->left()) / rect->width() * r.size();
}

void wheel(QCustomPlot* plot, QPointF at, int delta, Qt::KeyboardModifiers modifiers = {}) {
    QWheelEvent e(at, plot->mapToGlobal(at), QPoint(), QPoint(0, delta), Qt::NoButton, modifiers,
                  Qt::NoScrollPhase, false);
    QApplication::sendEvent(plot, &e);
}

void mouse(QCustomPlot* plot, QEvent::Type type, QPointF at, Qt::MouseButton button,
           Qt::MouseButtons buttons, Qt::KeyboardModifiers modifiers = {}) {
    QMouseEvent e(type, at, plot->mapToGlobal(at), button, buttons, modifiers);
    QApplication::sendEvent(plot, &e);
}

bool near(double a, double b, double scale) {
    return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(scale));
}

QString rangeText(const QCPRange& r) {
    return QStringLiteral("[%1, %2]").arg(r.lower, 0, 'g', 17).arg(r.upper, 0, 'g', 17);
}

} // namespace

class TestPlotTime : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_plot_time_tests"); }
    void init() {
        openWindow();
        m_window->plotsPanel()->replotNow();
    }
    void cleanup() { closeWindow(); }

    void wheelZoomsEveryPlotAboutTheMouseTime();
    void valueAxesFitWhatIsShown();
    void dragPansTheTimeAndDoesNotSeek();
    void doubleClickShowsTheWholeRun();
    void doubleClickDoesNotSeek();
    void windowFollowsTheCursorDuringPlayback();
    void wheelBurstsKeepRangesFiniteAndWithinTheRun();
    void timeWindowRefusesNonFiniteInput();
    void menusReachTheTimeFromTheKeyboard();

  private:
    PlotsPanel* plots() const { return m_window->plotsPanel(); }
    // every time plot shows `expected` (after the queued replots)
    void checkAllShow(const QCPRange& expected, const char* what);
};

void TestPlotTime::checkAllShow(const QCPRange& expected, const char* what) {
    plots()->replotNow();
    for (int i = 0; i < 4; ++i) {
        const QCPRange r = timeAxis(plots()->plot(i))->range();
        QVERIFY2(near(r.lower, expected.lower, expected.size()) &&
                     near(r.upper, expected.upper, expected.size()),
                 qPrintable(QStringLiteral("%1: plot %2 shows %3, expected %4")
                                .arg(what)
                                .arg(i)
                                .arg(rangeText(r), rangeText(expected))));
    }
}

void TestPlotTime::wheelZoomsEveryPlotAboutTheMouseTime() {
    QCustomPlot* chi = plots()->plot(1);
    QCPAxisRect* rect = chi->axisRect();
    const QCPRange whole = timeAxis(chi)->range();
    QList<QCPRange> wholes;
    for (int i = 0; i < 4; ++i)
        wholes << timeAxis(plots()->plot(i))->range();
    // one notch away from the reader at 30 % of the frame: 0.8 of the span about that time
    const QPointF at(rect->left() + 0.3 * rect->width(), rect->center().y());
    const double t = timeAtPixel(chi, at.x());
    wheel(chi, at, 120);
    const QCPRange in(t - 0.8 * (t - whole.lower), t + 0.8 * (whole.upper - t));
    checkAllShow(in, "one notch in");
    QCOMPARE(plots()->timeWindow().mode(), TimeWindow::Mode::Zoomed);
    // the time under the mouse stays under it
    QVERIFY(std::abs(timeAxis(chi)->coordToPixel(t) - at.x()) < 1e-6);
    // a second notch over another plot, at its 80 %: the same map of its own frame
    QCustomPlot* energy = plots()->plot(3);
    const QPointF at2(energy->axisRect()->left() + 0.8 * energy->axisRect()->width(),
                      energy->axisRect()->center().y());
    const double t2 = timeAtPixel(energy, at2.x());
    wheel(energy, at2, 120);
    checkAllShow(QCPRange(t2 - 0.8 * (t2 - in.lower), t2 + 0.8 * (in.upper - t2)), "two notches");
    // three notches toward the reader: wider than the run, so the whole run, each plot as before
    wheel(energy, at2, -360);
    QCOMPARE(plots()->timeWindow().mode(), TimeWindow::Mode::WholeRun);
    plots()->replotNow();
    for (int i = 0; i < 4; ++i)
        QCOMPARE(timeAxis(plots()->plot(i))->range(), wholes[i]);
}

void TestPlotTime::valueAxesFitWhatIsShown() {
    choosePreset("sinusoid");
    plots()->replotNow();
    QCustomPlot* psi = plots()->plot(0);
    const QCPRange wholeValues = psi->axisRect()->axis(QCPAxis::atLeft)->range();
    QCPAxisRect* rect = psi->axisRect();
    for (int notch = 0; notch < 6; ++notch)
        wheel(psi, QPointF(rect->left() + 0.5 * rect->width(), rect->center().y()), 120);
    plots()->replotNow();
    const QCPRange shown = timeAxis(psi)->range();
    // the controlled Psi within the time shown, from the series: its samples inside and the
    // straight line between samples at both edges
    const PlotSeries& s = m_window->document()->series();
    double lo = INFINITY, hi = -INFINITY;
    auto add = [&](double v) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    };
    for (int i = 0; i < s.t.size(); ++i) {
        if (shown.contains(s.t[i]))
            add(s.psi[i]);
        if (i > 0)
            for (double edge : {shown.lower, shown.upper})
                if (s.t[i - 1] < edge && edge < s.t[i])
                    add(s.psi[i - 1] +
                        (s.psi[i] - s.psi[i - 1]) * (edge - s.t[i - 1]) / (s.t[i] - s.t[i - 1]));
    }
    QVERIFY(lo < hi);
    const QCPRange values = rect->axis(QCPAxis::atLeft)->range();
    QVERIFY2(values.contains(lo) && values.contains(hi), qPrintable(rangeText(values)));
    // padded by 5 %, widened by the other curves by at most a quarter of that on each side
    const double padded = 1.1 * (hi - lo);
    QVERIFY2(values.lower >= lo - 0.05 * (hi - lo) - 0.25 * padded - 1e-12 &&
                 values.upper <= hi + 0.05 * (hi - lo) + 0.25 * padded + 1e-12,
             qPrintable(rangeText(values) + QStringLiteral(" for [%1, %2]").arg(lo).arg(hi)));
    // a sixth-notch zoom shows a part of the run whose Psi spans less than the whole run's axis
    QVERIFY(values.size() < wholeValues.size());
}

void TestPlotTime::dragPansTheTimeAndDoesNotSeek() {
    QCustomPlot* lambda = plots()->plot(2);
    QCPAxisRect* rect = lambda->axisRect();
    const QPointF middle(rect->left() + 0.5 * rect->width(), rect->center().y());
    for (int notch = 0; notch < 4; ++notch)
        wheel(lambda, middle, 120);
    plots()->replotNow();
    const QCPRange before = timeAxis(lambda)->range();
    const double perPixel = before.size() / rect->width();
    const double time = m_window->playback()->time();
    // a middle drag 100 px to the left shows 100 px of time later
    mouse(lambda, QEvent::MouseButtonPress, middle, Qt::MiddleButton, Qt::MiddleButton);
    mouse(lambda, QEvent::MouseMove, middle - QPointF(100, 0), Qt::NoButton, Qt::MiddleButton);
    mouse(lambda, QEvent::MouseButtonRelease, middle - QPointF(100, 0), Qt::MiddleButton,
          Qt::NoButton);
    const QCPRange later(before.lower + 100 * perPixel, before.upper + 100 * perPixel);
    checkAllShow(later, "middle drag");
    // a Shift drag with the left button 40 px to the right: 40 px earlier, and no seek
    mouse(lambda, QEvent::MouseButtonPress, middle, Qt::LeftButton, Qt::LeftButton,
          Qt::ShiftModifier);
    mouse(lambda, QEvent::MouseMove, middle + QPointF(40, 0), Qt::NoButton, Qt::LeftButton,
          Qt::ShiftModifier);
    mouse(lambda, QEvent::MouseButtonRelease, middle + QPointF(40, 0), Qt::LeftButton, Qt::NoButton,
          Qt::ShiftModifier);
    checkAllShow(QCPRange(later.lower - 40 * perPixel, later.upper - 40 * perPixel), "shift drag");
    QCOMPARE(m_window->playback()->time(), time);
    // dragged past the run's start: the range stops at it, its span kept
    mouse(lambda, QEvent::MouseButtonPress, middle, Qt::MiddleButton, Qt::MiddleButton);
    mouse(lambda, QEvent::MouseMove, middle + QPointF(1e6, 0), Qt::NoButton, Qt::MiddleButton);
    mouse(lambda, QEvent::MouseButtonRelease, middle + QPointF(1e6, 0), Qt::MiddleButton,
          Qt::NoButton);
    const QCPRange run = plots()->timeWindow().whole();
    checkAllShow(QCPRange(run.lower, run.lower + before.size()), "past the start");
    // a plain click still seeks, once the double-click interval has passed
    const double x = rect->left() + 0.25 * rect->width();
    const double t = timeAtPixel(lambda, x);
    QTest::mouseClick(lambda, Qt::LeftButton, {}, QPoint(int(x), int(middle.y())));
    QTRY_VERIFY(std::abs(m_window->playback()->time() - timeAtPixel(lambda, int(x))) < 1e-9 ||
                std::abs(m_window->playback()->time() - t) < perPixel);
}

void TestPlotTime::doubleClickDoesNotSeek() {
    // a double click as the window system sends it: press, release, press, double click,
    // release; the first press's seek waits for the double-click interval and is dropped
    QCustomPlot* psi = plots()->plot(0);
    QCPAxisRect* rect = psi->axisRect();
    for (int notch = 0; notch < 5; ++notch)
        wheel(psi, rect->center(), 120);
    plots()->replotNow();
    const double time = m_window->playback()->time();
    const QPointF at(rect->left() + 0.7 * rect->width(), rect->center().y());
    QVERIFY(std::abs(timeAtPixel(psi, at.x()) - time) > 0.1); // a seek there would show
    mouse(psi, QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton);
    QVERIFY(plots()->seekPending());
    mouse(psi, QEvent::MouseButtonRelease, at, Qt::LeftButton, Qt::NoButton);
    mouse(psi, QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton);
    mouse(psi, QEvent::MouseButtonDblClick, at, Qt::LeftButton, Qt::LeftButton);
    mouse(psi, QEvent::MouseButtonRelease, at, Qt::LeftButton, Qt::NoButton);
    QVERIFY(!plots()->seekPending());
    QCOMPARE(plots()->timeWindow().mode(), TimeWindow::Mode::WholeRun);
    QTest::qWait(QApplication::doubleClickInterval() + 200);
    QCOMPARE(m_window->playback()->time(), time);
    QCOMPARE(m_window->canvas()->time(), time);
    // a drag with the button down scrubs at once, without waiting; the whole run was drawn
    // anew, its axis rectangle too
    rect = psi->axisRect();
    const QPointF to(rect->left() + 0.3 * rect->width(), rect->center().y());
    const double target = timeAtPixel(psi, to.x());
    mouse(psi, QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton);
    mouse(psi, QEvent::MouseMove, to, Qt::NoButton, Qt::LeftButton);
    QVERIFY(!plots()->seekPending());
    QVERIFY(std::abs(m_window->playback()->time() - target) <
            2 * plots()->timeWindow().whole().size() / rect->width());
    mouse(psi, QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
}

void TestPlotTime::doubleClickShowsTheWholeRun() {
    QCustomPlot* psi = plots()->plot(0);
    const QCPRange whole = timeAxis(psi)->range();
    QCPAxisRect* rect = psi->axisRect();
    const QPointF middle = rect->center();
    for (int notch = 0; notch < 5; ++notch)
        wheel(psi, middle, 120);
    plots()->replotNow();
    QVERIFY(timeAxis(psi)->range().size() < 0.5 * whole.size());
    QTest::mouseDClick(psi, Qt::LeftButton, {}, middle.toPoint());
    QCOMPARE(plots()->timeWindow().mode(), TimeWindow::Mode::WholeRun);
    checkAllShow(whole, "double click");
}

void TestPlotTime::windowFollowsTheCursorDuringPlayback() {
    Playback* playback = m_window->playback();
    const QCPRange whole = timeAxis(plots()->plot(0))->range();
    plots()->followCursorAction()->setChecked(true);
    QCOMPARE(plots()->timeWindow().mode(), TimeWindow::Mode::Following);
    const double span = kFollowPart * whole.size();
    int moves = 0;
    QCPRange last = timeAxis(plots()->plot(0))->range();
    for (double t = 0; t <= playback->tEnd(); t += playback->tEnd() / 300) {
        playback->seek(t);
        plots()->replotNow();
        for (int i = 0; i < 4; ++i) {
            const QCPRange r = timeAxis(plots()->plot(i))->range();
            QVERIFY2(r.contains(t) && near(r.size(), span, span),
                     qPrintable(QStringLiteral("t = %1: %2").arg(t).arg(rangeText(r))));
            // the cursor is drawn inside the frame
            QVERIFY(plots()->cursor(i)->isVisible());
        }
        const QCPRange r = timeAxis(plots()->plot(0))->range();
        moves += r != last ? 1 : 0;
        last = r;
    }
    // page by page: the window moves on about every 0.88 of its span (8 windows a run)
    QVERIFY2(moves >= 7 && moves <= 12, qPrintable(QString::number(moves)));
    // a notch of the wheel while following, the mouse far from the cursor: the span is 0.8 as
    // wide about the time cursor, which stays where it was on the axis; following still
    QCustomPlot* chi = plots()->plot(1);
    const double cursorX = timeAxis(chi)->coordToPixel(playback->time());
    wheel(chi, QPointF(chi->axisRect()->right() - 2, chi->axisRect()->center().y()), 120);
    plots()->replotNow();
    QVERIFY2(std::abs(timeAxis(chi)->coordToPixel(playback->time()) - cursorX) < 1e-6,
             qPrintable(QStringLiteral("%1 against %2")
                            .arg(timeAxis(chi)->coordToPixel(playback->time()))
                            .arg(cursorX)));
    QCOMPARE(plots()->timeWindow().mode(), TimeWindow::Mode::Following);
    playback->seek(0.3 * playback->tEnd());
    plots()->replotNow();
    const QCPRange r = timeAxis(chi)->range();
    QVERIFY(r.contains(0.3 * playback->tEnd()) && near(r.size(), 0.8 * span, span));
    // off: the window stays where it is
    plots()->followCursorAction()->setChecked(false);
    QCOMPARE(plots()->timeWindow().mode(), TimeWindow::Mode::Zoomed);
    playback->seek(0.9 * playback->tEnd());
    plots()->replotNow();
    QCOMPARE(timeAxis(chi)->range(), r);
}

void TestPlotTime::wheelBurstsKeepRangesFiniteAndWithinTheRun() {
    // the run's sample interval from the series; the narrowest span is kMinSamples of it
    const PlotSeries& s = m_window->document()->series();
    const double interval = (s.t.back() - s.t.front()) / (s.t.size() - 1);
    const QCPRange run = plots()->timeWindow().whole();
    std::mt19937 random(20261207);
    std::uniform_real_distribution<double> x(-200, 1500);
    const int deltas[] = {120, -120, 120 * 1000, -120 * 1000, 2147483647, -2147483647 - 1, 1, -1};
    double narrowest = INFINITY;
    for (int event = 0; event < 600; ++event) {
        QCustomPlot* plot = plots()->plot(int(random() % 4));
        wheel(plot, QPointF(x(random), 50), deltas[random() % 8]);
        const QCPRange r = plots()->timeWindow().range();
        QVERIFY2(std::isfinite(r.lower) && std::isfinite(r.upper) && r.lower < r.upper,
                 qPrintable(rangeText(r)));
        QVERIFY(r.lower >= run.lower && r.upper <= run.upper);
        QVERIFY(r.size() >= kMinSamples * interval * (1 - 1e-9));
        narrowest = std::min(narrowest, r.size());
        if (event % 50 == 0) {
            plots()->replotNow();
            for (int i = 0; i < 4; ++i) {
                const QCPRange values =
                    plots()->plot(i)->axisRect()->axis(QCPAxis::atLeft)->range();
                QVERIFY(std::isfinite(values.lower) && std::isfinite(values.upper) &&
                        values.lower < values.upper);
            }
        }
    }
    // the bursts reached the narrowest span: 8 samples
    QVERIFY2(
        near(narrowest, kMinSamples * interval, narrowest),
        qPrintable(QStringLiteral("%1 against %2").arg(narrowest).arg(kMinSamples * interval)));
}

void TestPlotTime::timeWindowRefusesNonFiniteInput() {
    TimeWindow w;
    w.setRun(QCPRange(-0.5, 10.5), 0.01);
    QCOMPARE(w.minSpan(), 0.08);
    w.zoomAbout(5, 0.5);
    QCOMPARE(w.range(), QCPRange(-0.5 + 0.5 * 5.5, 10.5 - 0.5 * 5.5));
    const QCPRange kept = w.range();
    for (double bad : {double(NAN), double(INFINITY), -double(INFINITY)}) {
        w.zoomAbout(bad, 0.5);
        w.zoomAbout(5, bad);
        w.wheel(5, bad);
        w.pan(kept, bad);
        w.followCursor(bad);
        QCOMPARE(w.range(), kept);
    }
    w.zoomAbout(5, 0); // no zoom by nothing
    QCOMPARE(w.range(), kept);
    // an empty or inverted run is refused: the run is kept
    w.setRun(QCPRange(3, 3), 0.01);
    w.setRun(QCPRange(NAN, 3), 0.01);
    QCOMPARE(w.whole(), QCPRange(-0.5, 10.5));
    // a run of two samples: the narrowest span is the run
    w.setRun(QCPRange(0, 1), 5);
    QCOMPARE(w.minSpan(), 1.0);
}

void TestPlotTime::menusReachTheTimeFromTheKeyboard() {
    auto* menu = m_window->menuBar()->findChild<QMenu*>(QStringLiteral("plotTimeMenu"));
    QVERIFY(menu);
    QVERIFY(menu->actions().contains(plots()->followCursorAction()));
    QVERIFY(menu->actions().contains(plots()->wholeRunAction()));
    QVERIFY(!menu->title().isEmpty() && menu->title().contains(QLatin1Char('&')));
    for (int i = 0; i < 4; ++i) {
        QVERIFY(plots()->contextMenu(i)->actions().contains(plots()->followCursorAction()));
        QVERIFY(plots()->contextMenu(i)->actions().contains(plots()->wholeRunAction()));
    }
    // zooming in from the menu keeps the time cursor where it is on the axis
    m_window->playback()->seek(4.0);
    QCustomPlot* psi = plots()->plot(0);
    const double before = timeAxis(psi)->coordToPixel(4.0);
    plots()->zoomInTimeAction()->trigger();
    plots()->replotNow();
    QVERIFY(std::abs(timeAxis(psi)->coordToPixel(4.0) - before) < 1e-6);
    plots()->wholeRunAction()->trigger();
    QCOMPARE(plots()->timeWindow().mode(), TimeWindow::Mode::WholeRun);
}

QTEST_MAIN(TestPlotTime)
#include "test_plot_time.moc"
