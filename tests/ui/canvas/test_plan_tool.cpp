// The Plan tool (docs/physics.md §10) driven with the mouse: its action in the menu, on the
// toolbar and on a key; the target dragged by its handles; the drawn tracks against the
// geodesic integrated here by RK4 from the planned start (not the closed form the tool draws);
// choosing a motion by a click; one undo step per change; tracking the chosen motion. Playing a
// motion is test_plan_playback.cpp, the plan in the scene file and in view
// test_plan_file_and_view.cpp.
#include "canvas/plan_tool.h"
#include "canvas/scene_canvas.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "plan_tool_fixture.h"
#include "scene/scene_plan.h"
#include "shell/main_window.h"
#include "shell/timeline_bar.h"

#include <QAction>
#include <QMenuBar>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

using namespace chaplygin;
using namespace chaplygin::ui;
using namespace chaplygin::ui::test;

namespace {

// the sideways shift by b from (0, 0, 0) with b = v_T = 1 (the shared notes' known answer, an
// independent shooting computation): two minimisers on the Maxwell set
constexpr double kSidewaysTime = 3.340383019231;

double distanceToSegment(QPointF p, QPointF a, QPointF b) {
    const QPointF ab = b - a, ap = p - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(ap, ab) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(ap.x() - t * ab.x(), ap.y() - t * ab.y());
}

double distanceToPolyline(QPointF p, const std::vector<QPointF>& line) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k + 1 < line.size(); ++k)
        best = std::min(best, distanceToSegment(p, line[k], line[k + 1]));
    return best;
}

void sendMove(QWidget* w, QPointF at, Qt::KeyboardModifiers modifiers) {
    QMouseEvent move(QEvent::MouseMove, at, w->mapToGlobal(at), Qt::NoButton, Qt::LeftButton,
                     modifiers);
    QApplication::sendEvent(w, &move);
}

// a drag of the left button from `from` to `to` in `steps` moves
void drag(QWidget* w, QPointF from, QPointF to, Qt::KeyboardModifiers modifiers, int steps = 12) {
    QTest::mousePress(w, Qt::LeftButton, modifiers, from.toPoint());
    for (int i = 1; i <= steps; ++i)
        sendMove(w, from + (to - from) * (double(i) / steps), modifiers);
    QTest::mouseRelease(w, Qt::LeftButton, modifiers, to.toPoint());
}

} // namespace

class TestPlanTool : public QObject, private test::PlanToolFixture {
    Q_OBJECT
  private slots:
    void initTestCase() { startSuite("ui_plan_tool_tests"); }
    void init() { openPlanWindow(); }
    void cleanup() { closeWindow(); }

    void reachedFromMenuToolbarAndKey();
    void draggingTheTargetDrawsTheOptimalMotions();
    void theHeadingHandleTurnsTheTarget();
    void aClickChoosesAnotherMotion();
    void undoRestoresThePlan();
    void trackingThePlanMakesItThePath();

  private:
    /// The drawn track of motion i against the RK4 integration of its start: every drawn
    /// vertex and every integrated point within 0.25 device pixels of the other curve; its
    /// end on the target.
    void checkDrawnTrack(int i);
};

void TestPlanTool::reachedFromMenuToolbarAndKey() {
    QAction* plan = m_window->planAction();
    QVERIFY(plan && plan->isCheckable());
    QVERIFY(m_window->timeline()->actions().contains(plan));
    QVERIFY(test::inMenuBar(m_window->menuBar(), plan));
    QVERIFY(!m_canvas->planMode());
    QTest::keySequence(m_window.get(), plan->shortcut());
    QVERIFY(m_canvas->planMode());
    QVERIFY(plan->isChecked());
    // drawing ends it
    m_canvas->setDrawMode(true);
    QVERIFY(!m_canvas->planMode());
    QVERIFY(!plan->isChecked());
    m_canvas->setDrawMode(false);
    plan->trigger();
    QVERIFY(m_canvas->planMode());
}

void TestPlanTool::checkDrawnTrack(int i) {
    const PlannedGeodesic& g = m_tool->planned().geodesics.at(std::size_t(i));
    const double b = m_window->document()->solution()->system().b;
    const double v = m_window->document()->scene().speed;
    const Pose from = m_tool->plan().from.value_or(Pose{});
    const int n = 20000;
    const auto knife = integrateKnife({from.x, from.y, from.phi, g.psi0, g.psidot0}, b, v, g.t, n);
    // the end on the target
    const Knife& end = knife.back();
    const Pose to = m_tool->plan().to;
    const double miss =
        std::abs(end.x - to.x) / b + std::abs(end.y - to.y) / b + angleMiss(end.phi, to.phi);
    QVERIFY2(miss < 1e-8, qPrintable(QString::number(miss)));
    // the drawn curve and the integrated one within 0.25 device pixels of each other
    const QTransform world = m_canvas->worldToPixel();
    const double px = CanvasCurves::kTolerancePx / m_canvas->devicePixelRatioF();
    std::vector<QPointF> exact;
    for (const Knife& k : knife)
        exact.push_back(world.map(QPointF(k.x, k.y)));
    std::vector<QPointF> drawn;
    for (QPointF p : m_tool->tracks().at(std::size_t(i)).points)
        drawn.push_back(world.map(p));
    QVERIFY(drawn.size() >= 2);
    double worst = 0;
    for (QPointF p : drawn)
        worst = std::max(worst, distanceToPolyline(p, exact));
    // where it can be seen: the drawn curve is exact in the view, coarser beyond it
    const QRectF view = QRectF(m_canvas->rect());
    for (std::size_t k = 0; k < exact.size(); k += 7)
        if (view.contains(exact[k]))
            worst = std::max(worst, distanceToPolyline(exact[k], drawn));
    QVERIFY2(worst <= px, qPrintable(QStringLiteral("%1 px").arg(worst)));
    // its last point is the target's handle
    QVERIFY(QLineF(drawn.back(), m_tool->targetHandle()).length() <= px);
}

void TestPlanTool::draggingTheTargetDrawsTheOptimalMotions() {
    m_canvas->setPlanMode(true);
    QTest::qWait(50); // the window's layout settled: the view stays during the drag
    QVERIFY(m_tool->error().isEmpty());
    // without a plan the target is the path's end, (4, 0, 0): straight ahead in 4 s
    QCOMPARE(m_tool->planned().geodesics.front().t, 4.0);
    const int steps = m_window->undoStack()->count();
    // dragged with Shift, snapping to half the grid step: exactly the sideways shift (0, 1, 0)
    const QPointF goal = m_canvas->toPixel({0, 1});
    // a move each frame: the plans are made on a worker, the latest pose next
    const QPointF grabbed = m_tool->targetHandle();
    QTest::mousePress(m_canvas, Qt::LeftButton, Qt::ShiftModifier, grabbed.toPoint());
    for (int i = 1; i <= 30; ++i) {
        sendMove(m_canvas, grabbed + (goal - grabbed) * (i / 30.0), Qt::ShiftModifier);
        QTest::qWait(16);
    }
    // the pose dragged to is planned and drawn while the button is still held
    QTRY_VERIFY2(m_tool->plannedRequest().to.y == 1.0 && m_tool->plannedRequest().to.x == 0.0,
                 qPrintable(QStringLiteral("planned (%1, %2), dragged to (%3, %4)")
                                .arg(m_tool->plannedRequest().to.x)
                                .arg(m_tool->plannedRequest().to.y)
                                .arg(m_tool->plan().to.x)
                                .arg(m_tool->plan().to.y)));
    QVERIFY(m_tool->active());
    QCOMPARE(m_tool->planned().geodesics.front().t, m_tool->planned().geodesics.at(1).t);
    QTest::mouseRelease(m_canvas, Qt::LeftButton, Qt::ShiftModifier, goal.toPoint());
    QCOMPARE(m_window->undoStack()->count(), steps + 1);
    m_window->document()->flush();
    QVERIFY(m_window->document()->scene().plan);
    QCOMPARE(m_window->document()->scene().plan->to.x, 0.0);
    QCOMPARE(m_window->document()->scene().plan->to.y, 1.0);
    QCOMPARE(m_window->document()->scene().plan->to.phi, 0.0);
    const auto& motions = m_tool->planned().geodesics;
    QVERIFY(motions.size() >= 2);
    // the Maxwell point: two optimal motions, both at the known least time, both drawn
    QVERIFY(motions[0].optimal && motions[1].optimal);
    QVERIFY(std::abs(motions[0].t - kSidewaysTime) < 1e-9);
    QVERIFY(std::abs(motions[1].t - kSidewaysTime) < 1e-9);
    QCOMPARE(m_tool->chosen(), 0);
    QCOMPARE(m_tool->tracks().size(), motions.size());
    checkDrawnTrack(0);
    checkDrawnTrack(1);
    for (int i = 2; i < int(motions.size()); ++i)
        checkDrawnTrack(i);
    qInfo("slowest plan while dragging (worker thread): %.2f ms, %d motions listed",
          m_tool->slowestPlanMs(), int(motions.size()));
}

void TestPlanTool::theHeadingHandleTurnsTheTarget() {
    m_canvas->setPlanMode(true);
    // the heading handle dragged a quarter turn about the target, with Shift: exactly pi/2
    const QPointF centre = m_tool->targetHandle();
    const QPointF handle = m_tool->headingHandle();
    const double r = QLineF(centre, handle).length();
    drag(m_canvas, handle, centre + QPointF(3, -r), Qt::ShiftModifier);
    m_window->document()->flush();
    QCOMPARE(m_tool->plan().to.phi, std::numbers::pi / 2);
    QCOMPARE(m_window->document()->scene().plan->to.phi, std::numbers::pi / 2);
    QVERIFY(!m_tool->planned().geodesics.empty());
    QVERIFY(m_tool->planned().certified);
    checkDrawnTrack(0);
}

void TestPlanTool::aClickChoosesAnotherMotion() {
    m_canvas->setPlanMode(true);
    Scene s = m_window->document()->scene();
    s.plan = ScenePlan{};
    s.plan->to = {0, 1, 0};
    s.plan->horizon = 5; // the two optima and a few more, apart enough to click
    m_window->document()->edit(s, QStringLiteral("plan"));
    m_window->document()->flush();
    QVERIFY(m_tool->planned().geodesics.size() >= 2);
    m_canvas->repaint();
    // a point of the second track far from every other
    const QTransform world = m_canvas->worldToPixel();
    std::vector<std::vector<QPointF>> others;
    for (std::size_t i = 0; i < m_tool->tracks().size(); ++i) {
        if (i == 1)
            continue;
        others.emplace_back();
        for (QPointF p : m_tool->tracks()[i].points)
            others.back().push_back(world.map(p));
    }
    QPointF click;
    double farthest = 0;
    for (QPointF p : m_tool->tracks()[1].points) {
        const QPointF at = world.map(p);
        double d = std::numeric_limits<double>::infinity();
        for (const auto& other : others)
            d = std::min(d, distanceToPolyline(at, other));
        if (d > farthest && m_canvas->drawingArea().adjusted(0, 60, 0, 0).contains(at)) {
            farthest = d;
            click = at;
        }
    }
    // beyond the tool's reach (6 px) of every other track
    QVERIFY2(farthest > 8, qPrintable(QString::number(farthest)));
    const int steps = m_window->undoStack()->count();
    QTest::mouseClick(m_canvas, Qt::LeftButton, {}, click.toPoint());
    m_window->document()->flush();
    QCOMPARE(m_window->undoStack()->count(), steps + 1);
    QCOMPARE(m_window->document()->scene().plan->choice, 1);
    QCOMPARE(m_tool->chosen(), 1);
    // the chosen one ends on the target too
    checkDrawnTrack(1);
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QCOMPARE(m_tool->chosen(), 0);
}

void TestPlanTool::trackingThePlanMakesItThePath() {
    m_canvas->setPlanMode(true);
    Scene s = m_window->document()->scene();
    s.plan = ScenePlan{};
    s.plan->to = {0, 1, 0};
    s.plan->choice = 1; // the backing-first twin of the sideways shift
    m_window->document()->edit(s, QStringLiteral("plan"));
    m_window->document()->flush();
    QAction* track = m_window->findChild<QAction*>(QStringLiteral("trackPlanAction"));
    QVERIFY(track && track->isEnabled());
    const int steps = m_window->undoStack()->count();
    track->trigger();
    m_window->document()->flush();
    QCOMPARE(m_window->undoStack()->count(), steps + 1);
    const auto& solution = m_window->document()->solution();
    QCOMPARE(solution->scene().path.kind, PathKind::Geodesic);
    // the controlled body and the genuine vakonomic body coincide, and reach the target
    QVERIFY(std::abs(solution->tEnd() - kSidewaysTime) < 1e-9);
    double worst = 0;
    for (int i = 0; i <= 50; ++i) {
        const MotionSample m = solution->at(solution->tEnd() * i / 50);
        worst = std::max(
            {worst, std::abs(m.x - m.vak.x), std::abs(m.y - m.vak.y), angleMiss(m.phi, m.vak.phi)});
    }
    QVERIFY2(worst < 1e-8, qPrintable(QString::number(worst)));
    const MotionSample end = solution->at(solution->tEnd());
    QVERIFY(std::abs(end.x) + std::abs(end.y - 1) + angleMiss(end.phi, 0) < 1e-8);
    // the plan stays, its start where the new path begins
    QCOMPARE(m_tool->chosen(), 1);
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution()->scene().path.kind, PathKind::Polyline);
}

void TestPlanTool::undoRestoresThePlan() {
    m_canvas->setPlanMode(true);
    const Pose before = m_tool->plan().to;
    const QPointF from = m_tool->targetHandle();
    drag(m_canvas, from, from + QPointF(-80, -60), {});
    m_window->document()->flush();
    QVERIFY(m_window->document()->scene().plan);
    const Pose moved = m_window->document()->scene().plan->to;
    QVERIFY(std::hypot(moved.x - before.x, moved.y - before.y) > 0.1);
    QCOMPARE(m_tool->plan().to.x, moved.x);
    drag(m_canvas, m_tool->targetHandle(), m_tool->targetHandle() + QPointF(30, 30), {});
    m_window->document()->flush();
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().plan->to.x, moved.x);
    QCOMPARE(m_tool->plan().to.y, moved.y);
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QVERIFY(!m_window->document()->scene().plan);
    QCOMPARE(m_tool->plan().to.x, before.x);
    QCOMPARE(m_tool->plan().to.y, before.y);
}

QTEST_MAIN(TestPlanTool)
#include "test_plan_tool.moc"
