// A randomized GUI test: a seeded stream of random events (clicks, drags and wheel turns on the
// canvas, slider moves, typed garbage, menu actions, undo and redo, playback) through QTest on
// the offscreen platform. After each event: no crash, the document valid, nothing non-finite
// about to be drawn. The seed is printed with every failure; CHAPLYGIN_GUI_SEED and
// CHAPLYGIN_GUI_EVENTS replay or lengthen a run. A second stream mixes in the extremes: bursts
// of wheel notches to both ends of the zoom range, the longest horizons, every slider at its ends,
// fields typed with the extremes of a double, and strokes of every size.
#include "canvas/scene_canvas.h"
#include "document/file_dialogs.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "panels/parameters_panel.h"
#include "panels/path_panel.h"
#include "plots/plots_panel.h"
#include "scene/scene_json.h"
#include "shell/main_window.h"
#include "shell/playback.h"
#include "shell/presentation_mode.h"
#include "shell/timeline_bar.h"
#include "systems/system.h"
#include "widgets/number_field.h"

#include <QAction>
#include <QComboBox>
#include <QElapsedTimer>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QSet>
#include <QSlider>
#include <QWidget>
#include <QtTest>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <memory>
#include <random>

#include <sys/resource.h>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

constexpr unsigned kDefaultSeed = 20261130;
// the sanitizers' build runs each event several times slower: a shorter stream there, the whole
// one in the release suite
#if defined(__SANITIZE_ADDRESS__)
constexpr int kDefaultEvents = 1500;
constexpr int kDefaultExtremeEvents = 300;
#else
constexpr int kDefaultEvents = 5000;
constexpr int kDefaultExtremeEvents = 1500;
#endif

// the most CPU time an event of the extremes' stream may take on the UI thread in the release
// build [s]: a zoom burst, a long horizon or a long stroke is work the program bounds, never a
// stall
constexpr double kSlowestEventS = 5;

// the program's documented bound on its resident memory under any sequence of events [MB]
constexpr double kPeakMemoryMb = 1024;

unsigned envNumber(const char* name, unsigned fallback) {
    bool ok = false;
    unsigned v = qEnvironmentVariable(name).toUInt(&ok);
    return ok ? v : fallback;
}

bool isFinite(double v) {
    return std::isfinite(v);
}

// the calling thread's CPU time [s]: what an event costs the UI thread, however loaded the
// machine is
double threadCpuSeconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

} // namespace

class TestRandomEvents : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase();
    void randomEventStream();
    void extremeEventStream();

  private:
    /// Sends `events` events from the seed's stream, checking the window after each; with
    /// extremes, every other event is one of extremeEvent's. Keeps the slowest event's time.
    void runStream(unsigned seed, int events, bool extremes);
    /// One random event; returns a short description for the failure message.
    QString randomEvent();
    /// One event at the program's extremes (zoom range ends, longest horizons, slider ends,
    /// extreme doubles typed, strokes of every size).
    QString extremeEvent();
    /// A stroke of n samples on the canvas in draw mode, starting at a.
    void stroke(QPoint a, const QList<QPoint>& samples);
    /// Empty when the window is consistent, else what is wrong.
    QString check();

    std::unique_ptr<MainWindow> m_window;
    std::mt19937 m_rng;
    QList<QAction*> m_actions;
    double m_slowestS = 0; ///< the UI thread's most CPU time for one event, its events and paint

    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(m_rng); }
    double uniform(double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(m_rng);
    }
    QPoint pointIn(const QWidget* w) {
        return {pick(std::max(w->width(), 1)), pick(std::max(w->height(), 1))};
    }
    QString garbage();
};

void TestRandomEvents::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_random_tests"));
    // every file dialog is cancelled; nothing modal may open
    setDialogHook([](const QString&, const QString&, const QString&) { return DialogChoice{}; });
}

QString TestRandomEvents::garbage() {
    static const QString alphabet =
        QStringLiteral("0123456789.,-+*/^()eExXuU sincoqrtlgpa\u00e9\u03c0%$#@!\\\"'");
    static const QStringList words = {QStringLiteral("sin(x)"), QStringLiteral("x^2"),
                                      QStringLiteral("1e308"),  QStringLiteral("-0"),
                                      QStringLiteral("nan"),    QStringLiteral("inf"),
                                      QStringLiteral("0.5*x"),  QStringLiteral("1/0"),
                                      QStringLiteral("cos(u)"), QStringLiteral("1e-300")};
    if (pick(3) == 0)
        return words[pick(int(words.size()))];
    QString s;
    for (int i = 0, n = pick(12); i < n; ++i)
        s += alphabet[pick(int(alphabet.size()))];
    return s;
}

QString TestRandomEvents::randomEvent() {
    SceneCanvas* canvas = m_window->canvas();
    Playback* playback = m_window->playback();
    switch (pick(16)) {
    case 0: { // click on the canvas
        QPoint p = pointIn(canvas);
        QTest::mouseClick(canvas, pick(2) ? Qt::LeftButton : Qt::RightButton, {}, p);
        return QStringLiteral("click canvas %1,%2").arg(p.x()).arg(p.y());
    }
    case 1: { // drag on the canvas (pan, or draw in draw mode)
        if (pick(4) == 0)
            m_window->pathPanel()->drawButton()->toggle();
        QPoint a = pointIn(canvas);
        QTest::mousePress(canvas, Qt::LeftButton, {}, a);
        for (int i = 0, n = 1 + pick(8); i < n; ++i) {
            QPoint b = pointIn(canvas);
            QMouseEvent move(QEvent::MouseMove, b, canvas->mapToGlobal(b), Qt::NoButton,
                             Qt::LeftButton, Qt::NoModifier);
            QApplication::sendEvent(canvas, &move);
        }
        QTest::mouseRelease(canvas, Qt::LeftButton, {}, pointIn(canvas));
        return QStringLiteral("drag canvas (draw mode %1)").arg(canvas->drawMode());
    }
    case 2: { // wheel
        QPoint p = pointIn(canvas);
        QWheelEvent wheel(p, canvas->mapToGlobal(p), {}, QPoint(0, (pick(9) - 4) * 120),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(canvas, &wheel);
        return QStringLiteral("wheel");
    }
    case 3: { // canvas keys
        static const Qt::Key keys[] = {Qt::Key_Plus,  Qt::Key_Minus, Qt::Key_F,    Qt::Key_B,
                                       Qt::Key_L,     Qt::Key_Left,  Qt::Key_Up,   Qt::Key_Down,
                                       Qt::Key_Right, Qt::Key_Space, Qt::Key_Home, Qt::Key_End};
        Qt::Key k = keys[pick(int(std::size(keys)))];
        QTest::keyClick(canvas, k);
        return QStringLiteral("key %1 on canvas").arg(int(k));
    }
    case 4: { // a parameter slider
        auto sliders = m_window->parametersPanel()->findChildren<QSlider*>();
        if (sliders.isEmpty())
            return QStringLiteral("no slider");
        QSlider* s = sliders[pick(int(sliders.size()))];
        int v = s->minimum() + pick(s->maximum() - s->minimum() + 1);
        s->setValue(v);
        return QStringLiteral("slider %1 = %2").arg(s->objectName()).arg(v);
    }
    case 5: { // typed into a spin box
        auto spins = m_window->findChildren<NumberField*>();
        NumberField* s = spins[pick(int(spins.size()))];
        if (!s->isVisible())
            return QStringLiteral("hidden spin box");
        s->setFocus();
        s->selectAll();
        // garbage goes into the parameters; the path's range gets numbers of a classroom's size
        // (a range of 10^4 m is valid, only slow to tabulate)
        const bool range =
            s == m_window->pathPanel()->fromSpin() || s == m_window->pathPanel()->toSpin();
        QString text = pick(2) && !range ? garbage() : QString::number(uniform(-5, 20), 'g', 4);
        // QTest types ASCII only; the rest goes into the path fields as text
        if (std::any_of(text.begin(), text.end(), [](QChar c) { return c.unicode() > 126; }))
            text = QString::number(uniform(-5, 20), 'g', 4);
        QTest::keyClicks(s, text);
        QTest::keyClick(s, Qt::Key_Return);
        return QStringLiteral("spin %1 <- '%2'").arg(s->objectName(), text);
    }
    case 6: { // typed path
        PathPanel* panel = m_window->pathPanel();
        QLineEdit* edit = pick(3) ? panel->graphEdit() : panel->xOfUEdit();
        if (!edit->isEnabled())
            edit = panel->graphEdit()->isEnabled() ? panel->graphEdit() : panel->yOfUEdit();
        QString text = garbage();
        edit->setText(text);
        QTest::keyClick(edit, Qt::Key_Return);
        return QStringLiteral("path <- '%1'").arg(text);
    }
    case 7: { // a menu action
        QAction* a = m_actions[pick(int(m_actions.size()))];
        if (a->isEnabled())
            a->trigger();
        return QStringLiteral("action '%1'").arg(a->text());
    }
    case 8:
        QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
        return QStringLiteral("undo");
    case 9:
        QTest::keyClick(m_window.get(), Qt::Key_Y, Qt::ControlModifier);
        return QStringLiteral("redo");
    case 10: { // playback
        switch (pick(4)) {
        case 0:
            playback->togglePlay();
            break;
        case 1:
            playback->advance(uniform(0, 0.2));
            break;
        case 2:
            playback->seek(uniform(-1, playback->tEnd() + 1));
            break;
        default:
            QTest::keyClick(m_window.get(), Qt::Key_Period,
                            pick(2) ? Qt::ShiftModifier : Qt::NoModifier);
        }
        return QStringLiteral("playback");
    }
    case 11: { // time slider
        QSlider* s = m_window->timeline()->slider();
        s->setValue(pick(s->maximum() + 1));
        return QStringLiteral("time slider");
    }
    case 12: { // click in a plot
        QCustomPlot* plot = m_window->plotsPanel()->plot(pick(4));
        if (!plot->isVisible())
            return QStringLiteral("hidden plot");
        QTest::mouseClick(plot, Qt::LeftButton, {}, pointIn(plot));
        return QStringLiteral("plot click");
    }
    case 13: // presentation mode (never full screen here: the window keeps its size)
        m_window->presentation()->toggle();
        return QStringLiteral("presentation %1").arg(m_window->presentation()->isActive());
    case 14: { // combo boxes: system, gyration, mode, corners, speed, preset
        auto combos = m_window->findChildren<QComboBox*>();
        QComboBox* c = combos[pick(int(combos.size()))];
        if (!c->isVisible() || c->count() == 0)
            return QStringLiteral("hidden combo");
        int i = pick(c->count());
        c->setCurrentIndex(i);
        emit c->activated(i);
        return QStringLiteral("combo %1 -> %2").arg(c->objectName()).arg(i);
    }
    default: // window size
        m_window->resize(640 + pick(1300), 480 + pick(600));
        return QStringLiteral("resize");
    }
}

void TestRandomEvents::stroke(QPoint a, const QList<QPoint>& samples) {
    SceneCanvas* canvas = m_window->canvas();
    if (!canvas->drawMode())
        m_window->pathPanel()->drawButton()->toggle();
    QTest::mousePress(canvas, Qt::LeftButton, {}, a);
    for (QPoint b : samples) {
        QMouseEvent move(QEvent::MouseMove, b, canvas->mapToGlobal(b), Qt::NoButton, Qt::LeftButton,
                         Qt::NoModifier);
        QApplication::sendEvent(canvas, &move);
    }
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, samples.isEmpty() ? a : samples.back());
}

QString TestRandomEvents::extremeEvent() {
    SceneCanvas* canvas = m_window->canvas();
    switch (pick(5)) {
    case 0: { // a burst of wheel notches towards one end of the zoom range
        const int sign = pick(2) ? 1 : -1;
        const int notches = 10 + pick(60);
        const QPoint p = pointIn(canvas);
        for (int i = 0; i < notches; ++i) {
            QWheelEvent wheel(p, canvas->mapToGlobal(p), {}, QPoint(0, sign * 120), Qt::NoButton,
                              Qt::NoModifier, Qt::NoScrollPhase, false);
            QApplication::sendEvent(canvas, &wheel);
        }
        return QStringLiteral("zoom burst %1 x %2").arg(notches).arg(sign);
    }
    case 1: { // the longest horizons: the long-horizon gallery scene, or a long path range
        if (pick(2)) {
            auto* action = m_window->findChild<QAction*>(QStringLiteral("gallery-long-horizon"));
            if (!action)
                return QStringLiteral("no long-horizon scene");
            action->trigger();
            return QStringLiteral("gallery long horizon");
        }
        NumberField* to = m_window->pathPanel()->toSpin();
        if (!to->isVisible() || !to->isEnabled())
            return QStringLiteral("hidden range");
        const QString text = QString::number(500 + pick(1501));
        to->setFocus();
        to->selectAll();
        QTest::keyClicks(to, text);
        QTest::keyClick(to, Qt::Key_Return);
        return QStringLiteral("range to <- %1").arg(text);
    }
    case 2: { // a slider at either end of its range
        auto sliders = m_window->parametersPanel()->findChildren<QSlider*>();
        if (sliders.isEmpty())
            return QStringLiteral("no slider");
        QSlider* s = sliders[pick(int(sliders.size()))];
        s->setValue(pick(2) ? s->minimum() : s->maximum());
        return QStringLiteral("slider %1 = %2").arg(s->objectName()).arg(s->value());
    }
    case 3: { // a field typed with an extreme of a double (the range fields: a classroom's size)
        static const char* const extremes[] = {"1e308", "-1e308", "1e-308", "5e-324", "0",
                                               "-0",    "1e15",   "-1e15",  "1e6",    "-1",
                                               "1e-12", "2*pi",   "1/3",    "-1e-300"};
        auto fields = m_window->findChildren<NumberField*>();
        NumberField* f = fields[pick(int(fields.size()))];
        if (!f->isVisible())
            return QStringLiteral("hidden field");
        const bool range =
            f == m_window->pathPanel()->fromSpin() || f == m_window->pathPanel()->toSpin();
        const QString text = range ? QString::number(uniform(-20, 20), 'g', 6)
                                   : QString::fromLatin1(extremes[pick(int(std::size(extremes)))]);
        f->setFocus();
        f->selectAll();
        QTest::keyClicks(f, text);
        QTest::keyClick(f, Qt::Key_Return);
        return QStringLiteral("field %1 <- '%2'").arg(f->name(), text);
    }
    default: { // a stroke: a single click, a few pixels, wholly outside the view, or very long
        QPoint a = pointIn(canvas);
        QList<QPoint> samples;
        switch (pick(4)) {
        case 0:
            break;
        case 1:
            samples << a + QPoint(1 + pick(3), pick(3));
            break;
        case 2: { // outside the widget, beyond one of its edges
            const QPoint off(pick(2) ? -canvas->width() - 50 : 2 * canvas->width() + 50,
                             pick(2) ? -canvas->height() - 50 : 2 * canvas->height() + 50);
            a = off;
            for (int i = 0, n = 2 + pick(20); i < n; ++i)
                samples << off + QPoint(pick(200), pick(200));
            break;
        }
        default: { // a long wandering stroke
            QPoint p = a;
            for (int i = 0, n = 100 + pick(400); i < n; ++i) {
                p += QPoint(pick(21) - 10, pick(21) - 10);
                samples << p;
            }
        }
        }
        stroke(a, samples);
        return QStringLiteral("stroke of %1 samples").arg(samples.size());
    }
    }
}

QString TestRandomEvents::check() {
    SceneDocument* document = m_window->document();
    const auto& solution = document->solution();
    if (!solution)
        return QStringLiteral("no solution");
    const Scene& scene = solution->scene();
    try {
        deriveSystem(scene.system);
    } catch (const std::exception& e) {
        return QStringLiteral("the shown scene's system is invalid: %1").arg(e.what());
    }
    if (!(solution->tEnd() > 0) || !isFinite(solution->tEnd()))
        return QStringLiteral("t_end = %1").arg(solution->tEnd());
    Playback* playback = m_window->playback();
    double t = playback->time();
    if (!(t >= 0 && t <= playback->tEnd()) || !isFinite(t))
        return QStringLiteral("time %1 outside [0, %2]").arg(t).arg(playback->tEnd());
    MotionSample m = solution->at(std::clamp(t, 0.0, solution->tEnd()));
    for (double v : {m.x, m.y, m.phi, m.free.x, m.free.y, m.free.phi})
        if (!isFinite(v))
            return QStringLiteral("non-finite pose at t = %1: controlled (%2, %3, %4), free (%5, "
                                  "%6, %7); the scene:\n%8")
                .arg(t)
                .arg(m.x)
                .arg(m.y)
                .arg(m.phi)
                .arg(m.free.x)
                .arg(m.free.y)
                .arg(m.free.phi)
                .arg(QString::fromStdString(sceneToJson(scene)));
    SceneCanvas* canvas = m_window->canvas();
    QPointF p = canvas->toPixel({m.x, m.y});
    if (!isFinite(canvas->scale()) || !(canvas->scale() > 0) || !isFinite(p.x()) ||
        !isFinite(p.y()))
        return QStringLiteral("canvas maps the body at (%1, %2) m to %3,%4 at scale %5; the "
                              "scene:\n%6")
            .arg(m.x)
            .arg(m.y)
            .arg(p.x())
            .arg(p.y())
            .arg(canvas->scale())
            .arg(QString::fromStdString(sceneToJson(scene)));
    for (int i = 0; i < 4; ++i) {
        QCustomPlot* plot = m_window->plotsPanel()->plot(i);
        for (QCPAxisRect* rect : plot->axisRects())
            for (QCPAxis* axis : rect->axes())
                if (!isFinite(axis->range().lower) || !isFinite(axis->range().upper))
                    return QStringLiteral("plot %1 has a non-finite axis range").arg(i);
    }
    return {};
}

void TestRandomEvents::randomEventStream() {
    const unsigned seed = envNumber("CHAPLYGIN_GUI_SEED", kDefaultSeed);
    const int events = int(envNumber("CHAPLYGIN_GUI_EVENTS", kDefaultEvents));
    std::printf("random GUI events: seed %u, %d events (CHAPLYGIN_GUI_SEED=%u replays)\n", seed,
                events, seed);
    runStream(seed, events, false);
}

void TestRandomEvents::extremeEventStream() {
    const unsigned seed = envNumber("CHAPLYGIN_GUI_SEED", kDefaultSeed);
    const int events = int(envNumber("CHAPLYGIN_GUI_EVENTS", kDefaultExtremeEvents));
    std::printf("random GUI events with the extremes: seed %u, %d events "
                "(CHAPLYGIN_GUI_SEED=%u replays)\n",
                seed, events, seed);
    runStream(seed, events, true);
    if (QTest::currentTestFailed())
        return;
    const double slowest = m_slowestS;
    std::printf("the most CPU time of one event on the UI thread %.3f s\n", slowest);
#if !defined(__SANITIZE_ADDRESS__)
    QVERIFY2(
        slowest < kSlowestEventS,
        qPrintable(QStringLiteral("seed %1: an event took %2 s of the UI thread's CPU, over %3 s")
                       .arg(seed)
                       .arg(slowest)
                       .arg(kSlowestEventS)));
#endif
}

void TestRandomEvents::runStream(unsigned seed, int events, bool extremes) {
    m_rng.seed(seed);
    m_actions.clear();
    m_slowestS = 0;
    m_window = test::showTestWindow();
    QVERIFY(m_window);
    m_window->presentation()->setFullScreen(false);
    // menu actions without modal boxes or long jobs (the animation export has its own tests)
    QSet<QAction*> seen;
    for (QMenu* menu : m_window->findChildren<QMenu*>())
        for (QAction* a : menu->actions()) {
            const QString text = a->text();
            if (a->menu() || a->isSeparator() || text.contains(QStringLiteral("Quit")) ||
                text.contains(QStringLiteral("About")) ||
                text.contains(QStringLiteral("work-prec")) ||
                text.contains(QStringLiteral("animation")) || text.isEmpty() || seen.contains(a))
                continue;
            seen.insert(a);
            m_actions << a;
        }
    QVERIFY(m_actions.size() > 20);
    QStringList recent;
    for (int i = 0; i < events; ++i) {
        if (i % 1000 == 0)
            std::printf("  event %d\n", i);
        QElapsedTimer clock;
        clock.start();
        const double cpuStart = threadCpuSeconds();
        QString what = extremes && pick(2) ? extremeEvent() : randomEvent();
        const qint64 eventMs = clock.elapsed();
        recent << what;
        if (recent.size() > 8)
            recent.removeFirst();
        if (i % 8 == 0)
            QCoreApplication::processEvents();
        // the UI thread's own CPU time: the event, the events it queued and the paint, not the
        // wait for the path worker in flush
        double uiS = threadCpuSeconds() - cpuStart;
        if (i % 50 == 0) {
            m_window->document()->flush();
            const double paintStart = threadCpuSeconds();
            QImage shot = m_window->canvas()->grab().toImage(); // paint it
            uiS += threadCpuSeconds() - paintStart;
            QVERIFY2(!shot.isNull(), qPrintable(QStringLiteral("seed %1").arg(seed)));
        }
        m_slowestS = std::max(m_slowestS, uiS);
        QString problem = check();
        // the event's own time, and with the events it left queued, the paint and the check
        if (qEnvironmentVariableIsSet("CHAPLYGIN_GUI_TRACE"))
            std::printf("  %d %lld ms (%lld ms in all) %s\n", i, eventMs, clock.elapsed(),
                        qPrintable(what));
        QVERIFY2(problem.isEmpty(),
                 qPrintable(QStringLiteral("seed %1, event %2 (%3): %4\nlast events: %5")
                                .arg(seed)
                                .arg(i)
                                .arg(what, problem, recent.join(QStringLiteral("; ")))));
    }
    m_window->document()->flush();
    QVERIFY2(check().isEmpty(), qPrintable(QStringLiteral("seed %1 at the end").arg(seed)));
    m_window.reset();
    // memory bounded (docs/robustness.md, Bounded work and memory): the peak resident size of the
    // whole run. The sanitizers' allocator keeps freed memory in quarantine: no bound there
    struct rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    const double peakMb = double(usage.ru_maxrss) / 1024; // ru_maxrss is in kB on Linux
    std::printf("random GUI events: seed %u, %d events, peak resident memory %.0f MB\n", seed,
                events, peakMb);
#if !defined(__SANITIZE_ADDRESS__)
    QVERIFY2(peakMb < kPeakMemoryMb,
             qPrintable(QStringLiteral("seed %1: peak resident memory %2 MB, over %3 MB")
                            .arg(seed)
                            .arg(peakMb)
                            .arg(kPeakMemoryMb)));
#endif
}

QTEST_MAIN(TestRandomEvents)
#include "test_random_events.moc"
