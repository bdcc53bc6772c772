// The Measure tool on the canvas (ruler, protractor, probe) and the Values dock: reached from
// the menu, the toolbar and a key; the ruler's length and direction against the view's own
// pixel-to-metre map; snapping to the path's start and to a body (its heading); the protractor's
// angle; the probe on the circle preset against the circle's closed form; the scene and the undo
// stack untouched; the Values dock's copied text against Solution::at.
#include "canvas/measure_tool.h"
#include "canvas/scene_canvas.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "panels/values_panel.h"
#include "plots/plot_crosshair.h"
#include "plots/plots_panel.h"
#include "scene/csv_columns.h"
#include "scene/presets.h"
#include "scene/scene_json.h"
#include "shell/main_window.h"
#include "shell/playback.h"
#include "shell/timeline_bar.h"

#include <QAction>
#include <QClipboard>
#include <QDockWidget>
#include <QMenuBar>
#include <QPushButton>
#include <QTableWidget>
#include <QUndoStack>
#include <QtTest>
#include <qcustomplot.h>

#include <cmath>
#include <memory>
#include <numbers>

using namespace chaplygin;
using namespace chaplygin::ui;
using test::straightScene;

namespace {

void sendMove(QWidget* w, QPointF at, Qt::MouseButtons buttons) {
    QMouseEvent move(QEvent::MouseMove, at, w->mapToGlobal(at), Qt::NoButton, buttons, {});
    QApplication::sendEvent(w, &move);
}

// a drag of the left button between two whole pixels in `steps` moves
void drag(QWidget* w, QPoint from, QPoint to, int steps = 8) {
    QTest::mousePress(w, Qt::LeftButton, {}, from);
    for (int i = 1; i <= steps; ++i)
        sendMove(w, QPointF(from) + QPointF(to - from) * (double(i) / steps), Qt::LeftButton);
    QTest::mouseRelease(w, Qt::LeftButton, {}, to);
}

QPoint pixelOf(const SceneCanvas* canvas, QPointF world) {
    return canvas->toPixel(world).toPoint();
}

} // namespace

class TestMeasureTool : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase();
    void init();
    void cleanup();

    void reachedFromMenuToolbarAndKey();
    void theRulerMeasuresADrag();
    void theRulerSnapsToThePathStart();
    void aDragFromABodyIsMeasuredFromItsHeading();
    void aDragFromTheRulersEndIsAProtractor();
    void theProbeReadsTheCircleAtTheNearestPoint();
    void measuringLeavesTheSceneUnchanged();
    void theValuesDockCopiesTheSolutionAtTheShownTime();
    void hoveringAPlotReadsEveryCurveAtThatTime();

  private:
    MeasureTool* startMeasuring();
    std::unique_ptr<MainWindow> m_window;
    SceneCanvas* m_canvas = nullptr;
};

void TestMeasureTool::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_measure_tests"));
}

void TestMeasureTool::init() {
    m_window = test::showTestWindow();
    QVERIFY(m_window);
    m_window->document()->loadNow(straightScene());
    m_window->playback()->pause();
    m_window->playback()->seek(0);
    m_canvas = m_window->canvas();
}

void TestMeasureTool::cleanup() {
    m_window.reset();
}

MeasureTool* TestMeasureTool::startMeasuring() {
    m_canvas->setMeasureMode(true);
    return m_canvas->measureTool();
}

void TestMeasureTool::reachedFromMenuToolbarAndKey() {
    auto* measure = m_window->findChild<QAction*>(QStringLiteral("measureAction"));
    QVERIFY(measure && measure->isCheckable());
    QVERIFY(m_window->timeline()->actions().contains(measure));
    QVERIFY(test::inMenuBar(m_window->menuBar(), measure));
    QVERIFY(!m_canvas->measureMode());
    QTest::keySequence(m_window.get(), measure->shortcut());
    QVERIFY(m_canvas->measureMode());
    QVERIFY(measure->isChecked());
    // M on the canvas turns it off and on
    m_canvas->setFocus();
    QTest::keyClick(m_canvas, Qt::Key_M);
    QVERIFY(!m_canvas->measureMode());
    QVERIFY(!measure->isChecked());
    QTest::keyClick(m_canvas, Qt::Key_M);
    QVERIFY(m_canvas->measureMode());
    // the Plan tool and drawing end it
    m_canvas->setPlanMode(true);
    QVERIFY(!m_canvas->measureMode());
    QVERIFY(!measure->isChecked());
    measure->trigger();
    QVERIFY(m_canvas->measureMode());
    QVERIFY(!m_canvas->planMode());
    m_canvas->setDrawMode(true);
    QVERIFY(!m_canvas->measureMode());
}

void TestMeasureTool::theRulerMeasuresADrag() {
    MeasureTool* tool = startMeasuring();
    // two pixels well above the path (y = 0) and the bodies at the origin
    const QPoint from = pixelOf(m_canvas, {1.1, 1.3}), to = pixelOf(m_canvas, {2.9, 0.6});
    drag(m_canvas, from, to);
    QVERIFY(tool->ruler());
    QVERIFY(!tool->firstArm());
    const QPointF a = m_canvas->toWorld(from), b = m_canvas->toWorld(to);
    const double length = std::hypot(b.x() - a.x(), b.y() - a.y());
    const double direction = std::atan2(b.y() - a.y(), b.x() - a.x());
    QVERIFY(direction < 0); // down and to the right
    QCOMPARE_LT(std::abs(tool->ruler()->length() - length), 1e-12 * length);
    QCOMPARE_LT(std::abs(tool->ruler()->direction() - direction), 1e-12);
    QVERIFY(!tool->headingAngle());
    const QString text = tool->rulerText().join(QLatin1Char('\n'));
    QVERIFY2(text.contains(QString::number(length, 'g', 5)), qPrintable(text));
    QVERIFY2(text.contains(QString::number(direction * 180 / std::numbers::pi, 'f', 1)),
             qPrintable(text));
    // a click clears it
    QTest::mouseClick(m_canvas, Qt::LeftButton, {}, to + QPoint(40, 40));
    QVERIFY(!tool->ruler());
}

void TestMeasureTool::theRulerSnapsToThePathStart() {
    // the bodies away from the start
    m_window->playback()->seek(0.6 * m_window->document()->solution()->tEnd());
    MeasureTool* tool = startMeasuring();
    const QPoint start = pixelOf(m_canvas, {0, 0});
    const QPoint to = pixelOf(m_canvas, {1.5, 1.2});
    drag(m_canvas, start + QPoint(4, -3), to);
    QVERIFY(tool->ruler());
    QCOMPARE(tool->ruler()->from, QPointF(0, 0));
    QVERIFY(!tool->ruler()->heading);
    const QPointF b = m_canvas->toWorld(to);
    QCOMPARE_LT(std::abs(tool->ruler()->length() - std::hypot(b.x(), b.y())), 1e-12);
    // far from everything it does not snap
    drag(m_canvas, start + QPoint(0, -40), to);
    QCOMPARE_LT(std::abs(tool->ruler()->from.y() - m_canvas->toWorld(start + QPoint(0, -40)).y()),
                1e-12);
}

void TestMeasureTool::aDragFromABodyIsMeasuredFromItsHeading() {
    const auto solution = m_window->document()->solution();
    const double t = 0.4 * solution->tEnd();
    m_window->playback()->seek(t);
    const MotionSample m = solution->at(m_window->playback()->time());
    MeasureTool* tool = startMeasuring();
    const QPoint body = pixelOf(m_canvas, {m.x, m.y});
    const QPoint to = body + QPoint(90, -120);
    drag(m_canvas, body + QPoint(3, 2), to);
    QVERIFY(tool->ruler() && tool->ruler()->heading);
    QCOMPARE_LT(std::abs(tool->ruler()->from.x() - m.x), 1e-12);
    QCOMPARE_LT(std::abs(tool->ruler()->from.y() - m.y), 1e-12);
    const QPointF b = m_canvas->toWorld(to);
    const double expected =
        std::remainder(std::atan2(b.y() - m.y, b.x() - m.x) - m.phi, 2 * std::numbers::pi);
    QCOMPARE_LT(std::abs(*tool->headingAngle() - expected), 1e-12);
    QVERIFY(expected > 0.5); // up and to the right of a heading along +x
}

void TestMeasureTool::aDragFromTheRulersEndIsAProtractor() {
    MeasureTool* tool = startMeasuring();
    const QPoint p1 = pixelOf(m_canvas, {0.8, 1.5}), p2 = pixelOf(m_canvas, {2.4, 1.0});
    const QPoint p3 = pixelOf(m_canvas, {3.2, 2.1});
    drag(m_canvas, p1, p2);
    drag(m_canvas, p2 + QPoint(2, -2), p3);
    QVERIFY(tool->firstArm() && tool->ruler());
    const QPointF a = m_canvas->toWorld(p1), v = m_canvas->toWorld(p2), c = m_canvas->toWorld(p3);
    // the shared vertex is the first ruler's end
    QCOMPARE(tool->ruler()->from, v);
    QCOMPARE(tool->firstArm()->from, v);
    const QPointF u = a - v, w = c - v;
    const double expected = std::acos((u.x() * w.x() + u.y() * w.y()) /
                                      (std::hypot(u.x(), u.y()) * std::hypot(w.x(), w.y())));
    QCOMPARE_LT(std::abs(*tool->protractorAngle() - expected), 1e-9);
    const QString text = tool->rulerText().join(QLatin1Char('\n'));
    QVERIFY2(text.contains(QString::number(expected * 180 / std::numbers::pi, 'f', 1)),
             qPrintable(text));
    // Esc forgets both arms
    m_canvas->setFocus();
    QTest::keyClick(m_canvas, Qt::Key_Escape);
    QVERIFY(!tool->ruler() && !tool->firstArm());
}

void TestMeasureTool::theProbeReadsTheCircleAtTheNearestPoint() {
    // the circle preset: R = 2 from (2, 0) counter-clockwise, b = 1, v_T = 1 (energy mode), so
    // sdot = v_T R / sqrt(b^2 + R^2) and kappa = 1/R (docs/physics.md §2)
    m_window->document()->loadNow(presetScene("circle"));
    m_window->playback()->pause();
    m_window->playback()->seek(0);
    MeasureTool* tool = startMeasuring();
    const double R = 2, b = 1;
    const QPoint hover = pixelOf(m_canvas, {R * std::cos(1.0), R * std::sin(1.0)}) + QPoint(2, 1);
    sendMove(m_canvas, hover, Qt::NoButton);
    QVERIFY(tool->probe());
    const MeasureTool::Probe& p = *tool->probe();
    QCOMPARE(int(p.body), int(MeasureTool::Body::Controlled));
    // the nearest point of the circle to the hovered point
    const QPointF w = m_canvas->toWorld(hover);
    const double theta = std::atan2(w.y(), w.x());
    const double sdot = R / std::sqrt(b * b + R * R);
    QCOMPARE_LT(std::abs(p.x - R * std::cos(theta)), 1e-7);
    QCOMPARE_LT(std::abs(p.y - R * std::sin(theta)), 1e-7);
    QCOMPARE_LT(std::abs(p.s - R * theta), 1e-7);
    QCOMPARE_LT(std::abs(p.t - R * theta / sdot), 1e-7);
    QCOMPARE_LT(std::abs(p.phi - (theta + std::numbers::pi / 2)), 1e-7);
    QCOMPARE_LT(std::abs(p.kappa - 1 / R), 1e-9);
    // Psi = atan2(sdot, b phidot) with phidot = kappa sdot
    QCOMPARE_LT(std::abs(p.psi - std::atan2(1.0, b / R)), 1e-9);
    const QString text = tool->probeText().join(QLatin1Char('\n'));
    QVERIFY2(text.contains(QString::number(1 / p.kappa, 'g', 5)), qPrintable(text));
    // away from the path and the trails: no probe
    sendMove(m_canvas, pixelOf(m_canvas, {0, 0}), Qt::NoButton);
    QVERIFY(!tool->probe());
}

void TestMeasureTool::measuringLeavesTheSceneUnchanged() {
    SceneDocument* doc = m_window->document();
    const std::string before = sceneToJson(doc->scene());
    const int count = doc->undoStack()->count(), index = doc->undoStack()->index();
    const bool modified = doc->isModified();
    m_window->playback()->seek(0.5 * doc->solution()->tEnd());
    MeasureTool* tool = startMeasuring();
    const MotionSample m = doc->solution()->at(m_window->playback()->time());
    const QPoint body = pixelOf(m_canvas, {m.x, m.y});
    drag(m_canvas, body, body + QPoint(100, -80));
    drag(m_canvas, body + QPoint(100, -80), body + QPoint(180, 10));
    sendMove(m_canvas, pixelOf(m_canvas, {3.5, 0}) + QPoint(0, 3), Qt::NoButton);
    QVERIFY(tool->ruler() && tool->firstArm() && tool->probe());
    m_canvas->setMeasureMode(false);
    QCOMPARE(sceneToJson(doc->scene()), before);
    QCOMPARE(doc->undoStack()->count(), count);
    QCOMPARE(doc->undoStack()->index(), index);
    QCOMPARE(doc->isModified(), modified);
    QVERIFY(!tool->ruler() && !tool->probe());
}

void TestMeasureTool::theValuesDockCopiesTheSolutionAtTheShownTime() {
    auto* dock = m_window->findChild<QDockWidget*>(QStringLiteral("valuesDock"));
    QVERIFY(dock);
    QVERIFY(!dock->isVisible());
    dock->toggleViewAction()->trigger();
    QVERIFY(QTest::qWaitForWindowExposed(dock) || dock->isVisible());
    auto* values = dock->findChild<ValuesPanel*>();
    QVERIFY(values);
    const auto solution = m_window->document()->solution();
    m_window->playback()->seek(0.37 * solution->tEnd());
    const double t = m_window->playback()->time();
    QCOMPARE(values->time(), t);
    QApplication::clipboard()->clear();
    QTest::mouseClick(values->copyButton(), Qt::LeftButton);
    const QStringList lines =
        QApplication::clipboard()->text().split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    const auto columns = csvColumnsWritten(solution->perturbed());
    QCOMPARE(lines.size(), qsizetype(columns.size()) + 1);
    QCOMPARE(lines[0], QStringLiteral("column\tvalue\tunit"));
    const MotionSample m = solution->at(t);
    for (std::size_t i = 0; i < columns.size(); ++i) {
        const QStringList cells = lines[qsizetype(i) + 1].split(QLatin1Char('\t'));
        QCOMPARE(cells.size(), 3);
        QCOMPARE(cells[0].toStdString(), std::string(columns[i].name));
        QCOMPARE(cells[2].toStdString(), std::string(columns[i].unit));
        bool ok = false;
        const double value = cells[1].toDouble(&ok);
        QVERIFY(ok);
        // full precision: the same double
        QCOMPARE(value, columns[i].value(m));
    }
    // the table shows the same rows
    QCOMPARE(values->table()->rowCount(), int(columns.size()));
    QCOMPARE(values->table()->item(0, 0)->text(), QStringLiteral("t"));
}

void TestMeasureTool::hoveringAPlotReadsEveryCurveAtThatTime() {
    // the circle preset: the controlled body's Psi is constant, atan2(1, b kappa) with b = 1,
    // kappa = 1/2; the free body's Psi from the core's closed form (docs/physics.md §4)
    m_window->document()->loadNow(presetScene("circle"));
    m_window->plotsPanel()->replotNow();
    QCustomPlot* plot = m_window->plotsPanel()->plot(0); // Psi
    auto* crosshair = plot->findChild<PlotCrosshair*>();
    QVERIFY(crosshair);
    QCPAxisRect* rect = plot->axisRect(0);
    QVERIFY(rect->width() > 50);
    const QPointF at(rect->left() + 0.62 * rect->width(), rect->center().y());
    sendMove(plot, at, Qt::NoButton);
    QVERIFY(crosshair->time());
    const double t = rect->axis(QCPAxis::atBottom)->pixelToCoord(at.x());
    QCOMPARE(*crosshair->time(), t);
    QVERIFY(crosshair->readout()->isVisible());
    const auto solution = m_window->document()->solution();
    const MotionSample m = solution->at(t);
    bool controlled = false, free = false, vakonomic = false;
    for (const PlotCrosshair::Value& v : crosshair->values()) {
        if (v.name.startsWith(QStringLiteral("controlled"))) {
            controlled = true;
            QCOMPARE_LT(std::abs(v.value - std::atan2(1.0, 0.5)), 1e-9);
        } else if (v.name.startsWith(QStringLiteral("free"))) {
            free = true;
            // the plotted curve, linear between samples 0.035 s apart
            QCOMPARE_LT(std::abs(v.value - m.free.psi), 1e-3);
        } else if (v.name.startsWith(QStringLiteral("vakonomic"))) {
            vakonomic = true;
            QCOMPARE_LT(std::abs(v.value - m.vak.psi), 1e-3);
        }
    }
    QVERIFY(controlled && free && vakonomic);
    QVERIFY(crosshair->readout()->text().contains(QString::number(std::atan2(1.0, 0.5), 'g', 5)));
    // leaving the plot hides it
    QEvent leave(QEvent::Leave);
    QApplication::sendEvent(plot, &leave);
    QVERIFY(!crosshair->time());
    QVERIFY(!crosshair->readout()->isVisible());
}

QTEST_MAIN(TestMeasureTool)
#include "test_measure_tool.moc"
