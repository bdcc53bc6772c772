// Perturbed and corrected in the app (docs/physics.md §9): the open-loop and closed-loop bodies
// on the canvas with their toggles, the Perturbation dock's edits as undo steps saved in the scene
// file, the error plot with the Solution's values, and grabbing the body to push it.
#include "canvas/scene_canvas.h"
#include "control/path_feedback.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "panels/equations_panel.h"
#include "panels/perturbation_panel.h"
#include "plots/plots_panel.h"
#include "scene/presets.h"
#include "shell/main_window.h"
#include "shell/playback.h"
#include "shell/presentation_mode.h"
#include "widgets/number_field.h"

#include <QAction>
#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QFontMetricsF>
#include <QImage>
#include <QSlider>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>
#include <qcustomplot.h>

#include <cmath>
#include <memory>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestPerturbation : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase();
    void init();
    void cleanup();

    void bothBodiesDrawnWithTheirToggles();
    void paletteTellsThemApartInGreyscale();
    void panelEditsAreUndoStepsSavedInTheFile();
    void errorPlotShowsTheSolutionsErrors();
    void grabAndPushIsOneUndoStep();
    void equationsShowTheFeedbackLawAtT();
    void errorPlotHasTheTimeCursor();
    void exportedPlotsIncludeTheErrorPlot();
    void errorPlotLabelsWholeAt1280x800();

  private:
    PerturbationPanel* panel() const { return m_window->findChild<PerturbationPanel*>(); }
    void loadPushedScene() {
        QVERIFY(m_window->loadGalleryEntry(QStringLiteral("pushed-off-path")));
        m_window->document()->flush();
        QVERIFY(m_window->document()->solution()->perturbed());
    }
    std::unique_ptr<MainWindow> m_window;
    QTemporaryDir m_dir;
};

void TestPerturbation::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_perturbation_tests"));
    QVERIFY(m_dir.isValid());
}

void TestPerturbation::init() {
    m_window = test::showTestWindow();
    QVERIFY(m_window && m_window->document()->solution());
}

void TestPerturbation::cleanup() {
    m_window.reset();
}

void TestPerturbation::bothBodiesDrawnWithTheirToggles() {
    SceneCanvas* canvas = m_window->canvas();
    // without a perturbation there is nothing to draw
    QVERIFY(!m_window->document()->series().perturbed);
    QAction* open = m_window->findChild<QAction*>(QStringLiteral("showOpenLoopAction"));
    QAction* closed = m_window->findChild<QAction*>(QStringLiteral("showClosedLoopAction"));
    QVERIFY(open && closed && open->isChecked() && closed->isChecked());
    loadPushedScene();
    const double t = 8;
    m_window->playback()->seek(t);
    const MotionSample m = m_window->document()->solution()->at(t);
    // the open loop has drifted well clear of the controlled body, the feedback body is near it
    QVERIFY(std::hypot(m.pert.x - m.x, m.pert.y - m.y) > 1);
    auto colourAt = [&](double x, double y) {
        QImage image = canvas->grab().toImage();
        QPointF p = canvas->toPixel({x, y}) * image.devicePixelRatio();
        return image.pixelColor(p.toPoint());
    };
    // the centre of the open-loop board (a = 0.5 ahead of P): orange, red above blue
    const double cx = m.pert.x + 0.25 * std::cos(m.pert.phi);
    const double cy = m.pert.y + 0.25 * std::sin(m.pert.phi);
    const QColor shown = colourAt(cx, cy);
    QVERIFY2(shown.red() > shown.blue() + 60, qPrintable(shown.name()));
    const double fx = m.fb.x + 0.25 * std::cos(m.fb.phi) - 0.2 * std::sin(m.fb.phi);
    const double fy = m.fb.y + 0.25 * std::sin(m.fb.phi) + 0.2 * std::cos(m.fb.phi);
    const QColor closedShown = colourAt(fx, fy);
    // each toggle hides its own body only
    open->trigger();
    QVERIFY(!canvas->showsOpenLoop());
    const QColor hidden = colourAt(cx, cy);
    QVERIFY2(hidden.red() < hidden.blue() + 30, qPrintable(hidden.name()));
    QCOMPARE(colourAt(fx, fy), closedShown);
    closed->trigger();
    QVERIFY(colourAt(fx, fy) != closedShown);
    open->trigger();
    closed->trigger();
    QCOMPARE(colourAt(cx, cy), shown);
    QCOMPARE(colourAt(fx, fy), closedShown);
    // the green of the closed loop is there on the canvas (its trail)
    QImage image = canvas->grab().toImage();
    int green = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            green += c.green() > c.red() + 60 && c.green() > c.blue() + 60 ? 1 : 0;
        }
    QVERIFY2(green > 50, qPrintable(QString::number(green)));
}

void TestPerturbation::paletteTellsThemApartInGreyscale() {
    const CanvasStyle s = CanvasStyle().presentation(PresentationMode::kDefaultScale);
    const QColor colours[] = {s.controlled(), s.vakonomic(), s.path(),
                              s.free(),       s.openLoop(),  s.closedLoop()};
    for (int i = 0; i < 6; ++i) {
        QVERIFY(luminance(colours[i]) < 0.6);
        for (int j = i + 1; j < 6; ++j)
            QVERIFY2(std::abs(luminance(colours[i]) - luminance(colours[j])) >= 0.09,
                     qPrintable(QStringLiteral("%1 vs %2").arg(i).arg(j)));
    }
    const CanvasStyle normal;
    QVERIFY(normal.openLoop() != normal.closedLoop() && normal.openLoop() != normal.free());
}

void TestPerturbation::panelEditsAreUndoStepsSavedInTheFile() {
    PerturbationPanel* p = panel();
    QVERIFY(p);
    QUndoStack* undo = m_window->undoStack();
    const int start = undo->count();
    QVERIFY(!m_window->document()->scene().perturbation);
    // the default: off; turned on it has P = 1 and no limit
    QVERIFY(!p->enabledBox()->isChecked() && !p->limitBox()->isChecked());
    p->enabledBox()->setChecked(true);
    m_window->document()->flush();
    QCOMPARE(undo->count(), start + 1);
    QVERIFY(m_window->document()->scene().perturbation);
    QCOMPARE(m_window->document()->scene().perturbation->feedbackRate, 1.0);
    QVERIFY(!m_window->document()->scene().perturbation->feedbackLimit);
    QVERIFY(m_window->document()->solution()->perturbed());
    // a slider drag is one undo step
    for (int v = 100; v <= 200; v += 10)
        p->rateSlider()->setValue(v);
    m_window->document()->flush();
    QCOMPARE(undo->count(), start + 2);
    const double rate = m_window->document()->scene().perturbation->feedbackRate;
    QVERIFY2(std::abs(rate - (0.1 + 200 * 0.01)) < 1e-9, qPrintable(QString::number(rate)));
    QCOMPARE(p->spin(QStringLiteral("feedback_rate"))->value(), rate);
    // an offset, the push and the limit, each one step
    p->spin(QStringLiteral("dy"))->setValue(0.2);
    p->pushBox()->setChecked(true);
    p->spin(QStringLiteral("t_push"))->setValue(2);
    p->spin(QStringLiteral("push_psi"))->setValue(0.1);
    p->limitBox()->setChecked(true);
    p->spin(QStringLiteral("feedback_limit"))->setValue(3);
    m_window->document()->flush();
    QCOMPARE(undo->count(), start + 8);
    Perturbation expected;
    expected.dy = 0.2;
    expected.tPush = 2;
    expected.pushPsi = 0.1;
    expected.feedbackRate = rate;
    expected.feedbackLimit = 3;
    QVERIFY(m_window->document()->scene().perturbation == expected);
    // saved and loaded back by the core's JSON
    const QString file = m_dir.filePath(QStringLiteral("perturbed.chaplygin.json"));
    QVERIFY(m_window->saveFile(file));
    QFile f(file);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QByteArray json = f.readAll();
    QVERIFY(json.contains("\"perturbation\"") && json.contains("\"feedback_limit\""));
    m_window->document()->setSceneNow(presetScene("sinusoid"));
    QVERIFY(m_window->openFile(file));
    QVERIFY(m_window->document()->scene().perturbation == expected);
    QCOMPARE(p->spin(QStringLiteral("dy"))->value(), 0.2);
    QVERIFY(p->pushBox()->isChecked());
    // undone back to no perturbation, the panel follows
    m_window->loadScene(presetScene("sinusoid"));
    p->enabledBox()->setChecked(true);
    p->spin(QStringLiteral("dy"))->setValue(0.3);
    m_window->document()->flush();
    undo->undo();
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().perturbation->dy, 0.0);
    QCOMPARE(p->spin(QStringLiteral("dy"))->value(), 0.0);
    undo->undo();
    m_window->document()->flush();
    QVERIFY(!m_window->document()->scene().perturbation);
    QVERIFY(!p->enabledBox()->isChecked());
}

void TestPerturbation::errorPlotShowsTheSolutionsErrors() {
    QCustomPlot* plot = m_window->plotsPanel()->errorPlot();
    QVERIFY(plot);
    QVERIFY(!plot->isVisible());
    loadPushedScene();
    QVERIFY(plot->isVisible());
    const auto& solution = m_window->document()->solution();
    // e and theta, open and closed loop: four graphs with the core's tracking errors
    QCOMPARE(plot->graphCount(), 4);
    for (int g = 0; g < 4; ++g) {
        QCPGraph* graph = plot->graph(g);
        QVERIFY(graph->data()->size() > 100);
        std::vector<double> times;
        for (const QCPGraphData& d : *graph->data())
            times.push_back(d.key);
        const std::vector<TrackingError> errors = solution->trackingErrors(times);
        double worst = 0;
        int i = 0;
        for (const QCPGraphData& d : *graph->data()) {
            const TrackingError& r = errors[std::size_t(i++)];
            const double expected = g == 0   ? r.openE
                                    : g == 1 ? r.fbE
                                    : g == 2 ? r.openTheta
                                             : r.fbTheta;
            worst = std::max(worst, std::abs(d.value - expected));
        }
        QVERIFY2(worst < 1e-9, qPrintable(QString::number(worst)));
    }
    // the story of the scene: the push sends both off; the open loop stays off, feedback returns
    const QCPGraph* openE = plot->graph(0);
    const QCPGraph* fbE = plot->graph(1);
    QVERIFY(std::abs((openE->data()->constEnd() - 1)->value) > 1);
    QVERIFY(std::abs((fbE->data()->constEnd() - 1)->value) < 1e-3);
    // without a perturbation it goes again
    m_window->loadScene(presetScene("circle"));
    QVERIFY(!plot->isVisible());
}

void TestPerturbation::grabAndPushIsOneUndoStep() {
    SceneCanvas* canvas = m_window->canvas();
    m_window->loadScene(presetScene("sinusoid"));
    const double t = 2;
    m_window->playback()->seek(t);
    // zoomed in: a 12 px drag is a push of some 0.15 m
    canvas->zoomBy(4);
    QCOMPARE(canvas->time(), t);
    const MotionSample m = m_window->document()->solution()->at(t);
    const int before = m_window->undoStack()->count();
    // press on the body (at P), drag 12 px along its left normal
    const QPoint from = canvas->toPixel({m.x, m.y}).toPoint();
    const QPointF normal(-std::sin(m.phi), std::cos(m.phi)); // world, y up
    const QPoint to =
        canvas->toPixel(QPointF(m.x, m.y) + normal * (12 / canvas->scale())).toPoint();
    // the pixels in metres before the push refits the view to the new bodies
    const double metres = 12 / canvas->scale(), pixel = 1 / canvas->scale();
    const QPointF d = canvas->toWorld(to) - canvas->toWorld(from);
    const double expected = d.x() * normal.x() + d.y() * normal.y();
    QTest::mousePress(canvas, Qt::LeftButton, {}, from);
    QVERIFY(canvas->pushing());
    QTest::mouseMove(canvas, to);
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, to);
    QVERIFY(!canvas->pushing());
    m_window->document()->flush();
    QCOMPARE(m_window->undoStack()->count(), before + 1);
    const auto& p = m_window->document()->scene().perturbation;
    QVERIFY(p && p->tPush);
    QCOMPARE(*p->tPush, t);
    QVERIFY2(std::abs(p->pushDy - expected) < 1e-9 && std::abs(expected - metres) < 2 * pixel,
             qPrintable(QString::number(p->pushDy)));
    QVERIFY(m_window->document()->solution()->perturbed());
    // a drag away from the body pans, as before
    const QPoint far(5, canvas->height() / 2);
    QTest::mousePress(canvas, Qt::LeftButton, {}, far);
    QVERIFY(!canvas->pushing());
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, far + QPoint(20, 0));
    QCOMPARE(m_window->undoStack()->count(), before + 1);
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QVERIFY(!m_window->document()->scene().perturbation);
}

namespace {

// a value as the Equations dock prints it: four digits, a true minus sign
QString shown(double v) {
    if (std::fabs(v) < 5e-13)
        v = 0;
    const QString s = QString::number(v, 'g', 4);
    return s.startsWith(u'-') ? QStringLiteral("\u2212") + s.mid(1) : s;
}

} // namespace

void TestPerturbation::equationsShowTheFeedbackLawAtT() {
    loadPushedScene();
    auto* equations = m_window->findChild<EquationsPanel*>();
    QVERIFY(equations);
    // without a perturbation there is no law on the page
    m_window->loadScene(presetScene("sinusoid"));
    m_window->document()->flush();
    equations->setTime(4);
    QVERIFY(!equations->html().contains(QStringLiteral("z\u2082")));
    loadPushedScene();
    const double t = 4; // a second after the push: every term of the law is at work
    m_window->playback()->seek(t);
    QCOMPARE(equations->time(), t);
    const QString html = equations->html();
    const Solution& solution = *m_window->document()->solution();
    const PerturbedState fb = solution.feedback()->at(t);
    const FeedbackLawValues& law = fb.law;
    // the core's chained form (control/path_feedback.h) at the closest point's geometry
    PathError err;
    err.e = law.closest.e;
    err.theta = law.theta;
    err.kappaBody = law.kappaBody;
    err.kappa = law.closest.point.kappa;
    err.dkappa = law.closest.point.dkappa;
    err.ddkappa = law.closest.point.ddkappa;
    const ChainedForm z = chainedForm(err);
    const double P = m_window->document()->scene().perturbation->feedbackRate;
    const double u = triplePoleInput(z, P);
    const DerivedSystem& sys = solution.system();
    // the lateral error against the tracking errors' own projection, and the law's identities
    std::vector<double> times; // the projection follows the body from t = 0
    for (int i = 0; i <= 400; ++i)
        times.push_back(t * i / 400);
    const TrackingError atT = solution.trackingErrors(times).back();
    QVERIFY2(std::abs(z.z2 - atT.fbE) < 1e-9,
             qPrintable(QStringLiteral("%1 %2").arg(z.z2).arg(atT.fbE)));
    QVERIFY(std::abs(err.theta - atT.fbTheta) < 1e-9);
    QVERIFY(std::abs(u - (-P * P * P * z.z2 - 3 * P * P * z.z3 - 3 * P * z.z4)) < 1e-12);
    QVERIFY(std::abs(z.z2) > 1e-3 && std::abs(z.z3) > 1e-3 && std::abs(u) > 1e-3);
    const double lambda = sys.mass * (sys.b * fb.psidot - sys.a * fb.phidot);
    const double psidot = -sys.b * law.sdotPath * curvatureRate(z, u) /
                          (1 + sys.b * sys.b * law.kappaBody * law.kappaBody);
    QVERIFY(std::abs(psidot - fb.psidot) < 1e-12);
    // the formulas in proper notation, the names of the parameters panel, and the values at t
    for (const QString& formula :
         {QStringLiteral("Feedback law"), QStringLiteral("z\u2082 = e"),
          QStringLiteral("z\u2083 = (1 \u2212 \u03bae) tan \u03b8"),
          QStringLiteral("u = \u2212P\u00b3z\u2082 \u2212 3P\u00b2z\u2083 \u2212 3Pz\u2084"),
          QStringLiteral("\u03a8\u0307 = \u2212b \u1e61_p \u03ba_b\u2032"),
          QStringLiteral("\u03bb_fb = m_eff(b\u03a8\u0307 \u2212 a\u03c6\u0307)"),
          QStringLiteral("feedback rate P = %1 1/m").arg(shown(P))})
        QVERIFY2(html.contains(formula), qPrintable(formula));
    for (auto [name, value] : {std::pair{"z2", z.z2},
                               {"theta", err.theta},
                               {"z3", z.z3},
                               {"z4", z.z4},
                               {"u", u},
                               {"psidot", psidot},
                               {"lambda", lambda}})
        QVERIFY2(html.contains(QStringLiteral("<b>= %1</b>").arg(shown(value))),
                 qPrintable(QStringLiteral("%1 = %2 is not on the page").arg(name, shown(value))));
    // live: another time, other values
    m_window->playback()->seek(6);
    const FeedbackLawValues later = solution.feedback()->at(6).law;
    QVERIFY(equations->html().contains(QStringLiteral("<b>= %1</b>").arg(shown(later.u))));
}

void TestPerturbation::errorPlotHasTheTimeCursor() {
    loadPushedScene();
    PlotsPanel* plots = m_window->plotsPanel();
    QCustomPlot* plot = plots->errorPlot();
    QVERIFY(plot->isVisible());
    QCOMPARE(plot->axisRectCount(), 2);
    for (double t : {2.0, 7.5}) {
        m_window->playback()->seek(t);
        plots->replotNow();
        QCOMPARE(plots->cursorTime(), t);
        for (int i = 0; i < 2; ++i) {
            QWidget* cursor = plots->errorCursor(i);
            QCPAxisRect* rect = plot->axisRect(i);
            QVERIFY(cursor->isVisible());
            QCOMPARE(cursor->parentWidget(), plot);
            const double x = rect->axis(QCPAxis::atBottom)->coordToPixel(t);
            QVERIFY2(std::abs(cursor->geometry().center().x() - x) <= 1.5,
                     qPrintable(QStringLiteral("panel %1: cursor at %2, t = %3 at %4")
                                    .arg(i)
                                    .arg(cursor->geometry().center().x())
                                    .arg(t)
                                    .arg(x)));
            QCOMPARE(cursor->geometry().top(), rect->top());
            QCOMPARE(cursor->geometry().height(), rect->height());
        }
    }
    // a click on the error plot seeks there, in either panel
    QCPAxisRect* right = plot->axisRect(1);
    const double target = 9;
    const QPoint at(int(std::lround(right->axis(QCPAxis::atBottom)->coordToPixel(target))),
                    right->center().y());
    QTest::mouseClick(plot, Qt::LeftButton, {}, at);
    // once the double-click interval has passed: a double click does not seek
    QTRY_VERIFY2(std::abs(m_window->playback()->time() - target) < 0.2,
                 qPrintable(QString::number(m_window->playback()->time())));
}

void TestPerturbation::exportedPlotsIncludeTheErrorPlot() {
    const QStringList png{QStringLiteral("png")};
    const QString plain = m_dir.filePath(QStringLiteral("plain"));
    m_window->loadScene(presetScene("sinusoid"));
    QVERIFY(m_window->exportPlotsTo(plain, png));
    QVERIFY(QFile::exists(plain + QStringLiteral("/psi.png")));
    QVERIFY(!QFile::exists(plain + QStringLiteral("/tracking_error.png")));
    loadPushedScene();
    const QString pushed = m_dir.filePath(QStringLiteral("pushed"));
    QVERIFY(m_window->exportPlotsTo(pushed, png));
    const QStringList files = QDir(pushed).entryList({QStringLiteral("*.png")}, QDir::Files);
    QVERIFY2(files.contains(QStringLiteral("tracking_error.png")), qPrintable(files.join(' ')));
    QImage image(pushed + QStringLiteral("/tracking_error.png"));
    QVERIFY(!image.isNull() && image.width() >= 900);
}

void TestPerturbation::errorPlotLabelsWholeAt1280x800() {
    loadPushedScene();
    m_window->resize(1280, 800);
    m_window->balanceDocks();
    QApplication::processEvents();
    QCustomPlot* plot = m_window->plotsPanel()->errorPlot();
    plot->replot();
    for (QCPAxisRect* rect : plot->axisRects()) {
        QCPAxis* y = rect->axis(QCPAxis::atLeft);
        QVERIFY(!y->label().isEmpty());
        // the label runs along the axis, centred on the frame: it is whole when it is no longer
        // than the frame is high
        const QFontMetricsF metrics(y->labelFont());
        double longest = 0;
        for (const QString& line : y->label().split('\n'))
            longest = std::max(longest, metrics.horizontalAdvance(line));
        QVERIFY2(longest <= rect->height(),
                 qPrintable(QStringLiteral("'%1': %2 px along a %3 px frame")
                                .arg(y->label())
                                .arg(longest)
                                .arg(rect->height())));
        // nothing of the plot's own drawn over it: the legends are under the panels
        for (QCPLayoutElement* e : plot->plotLayout()->elements(true))
            if (auto* legend = qobject_cast<QCPLegend*>(e))
                QVERIFY(!legend->outerRect().intersects(rect->rect()));
    }
}

QTEST_MAIN(TestPerturbation)
#include "test_perturbation.moc"
