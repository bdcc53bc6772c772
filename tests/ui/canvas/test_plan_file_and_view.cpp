// The plan in the scene file and in view (docs/physics.md §10): saved and opened again with its
// chosen motion, a bad plan in a file refused naming its field, the handles, the tracks and the
// Plan tool's actions whole at 1024x768 and in presentation, and a scene with a plan opened with
// every motion (integrated here by RK4) in view.
#include "canvas/plan_tool.h"
#include "canvas/scene_canvas.h"
#include "common/input_error.h"
#include "document/scene_document.h"
#include "plan_tool_fixture.h"
#include "scene/scene_json.h"
#include "scene/scene_plan.h"
#include "shell/main_window.h"
#include "shell/presentation_mode.h"
#include "shell/timeline_bar.h"

#include <QAction>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>
#include <numbers>
#include <optional>
#include <string>

using namespace chaplygin;
using namespace chaplygin::ui;
using namespace chaplygin::ui::test;

class TestPlanFileAndView : public QObject, private test::PlanToolFixture {
    Q_OBJECT
  private slots:
    void initTestCase() { startSuite("ui_plan_file_and_view_tests"); }
    void init() { openPlanWindow(); }
    void cleanup() { closeWindow(); }

    void thePlanIsSavedAndRestored();
    void aBadPlanInAFileIsRefusedNamingItsField();
    void fitsAt1024x768AndInPresentation();
    void aSceneWithAPlanOpensFramingEveryMotion();
};

void TestPlanFileAndView::thePlanIsSavedAndRestored() {
    Scene s = straightScene();
    ScenePlan plan;
    plan.from = Pose{0.5, -0.25, 0.3};
    plan.to = {1.5, 2.0, -2.0};
    plan.horizon = 15;
    s.plan = plan;
    m_window->document()->loadNow(s);
    const int count = int(planOf(plan, *m_window->document()->solution()).geodesics.size());
    QVERIFY(count >= 2);
    s.plan->choice = count - 1;
    m_window->document()->loadNow(s);
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("plan.chaplygin.json"));
    m_window->document()->save(file);
    SceneDocument other;
    other.open(file);
    QVERIFY(other.scene().plan);
    QVERIFY(*other.scene().plan == *s.plan);
    // and the window shows it, in plan mode
    m_canvas->setPlanMode(false);
    m_window->document()->open(file);
    QVERIFY(m_canvas->planMode());
    QCOMPARE(m_tool->chosen(), count - 1);
    QCOMPARE(m_tool->plan().horizon, std::optional<double>(15));
}

void TestPlanFileAndView::aBadPlanInAFileIsRefusedNamingItsField() {
    QTemporaryDir dir;
    auto write = [&](const std::string& text) {
        const QString file = dir.filePath(QStringLiteral("bad.chaplygin.json"));
        std::ofstream(file.toStdString()) << text;
        return file;
    };
    std::string base = sceneToJson(straightScene());
    base.resize(base.rfind('}'));
    const auto expectRefused = [&](const std::string& plan, const QString& where) {
        const QString file = write(base + ", \"plan\": " + plan + "}");
        const Scene before = m_window->document()->scene();
        try {
            m_window->document()->open(file);
            QFAIL("the file was accepted");
        } catch (const InputError& e) {
            const SceneError error = SceneError::of(e);
            QVERIFY2(error.where == where,
                     qPrintable(error.where + QStringLiteral(": ") + error.message));
        }
        QVERIFY(m_window->document()->scene() == before);
    };
    expectRefused("{\"to\": [1, 2, 0], \"horizon\": -1}",
                  QStringLiteral("scene file /plan/horizon"));
    expectRefused("{\"to\": [1, null, 0]}", QStringLiteral("scene file /plan/to/1"));
    expectRefused("{\"to\": [1, 2, 0], \"choice\": 400}", QStringLiteral("plan choice"));
    // no motion within a horizon too short for the target
    expectRefused("{\"to\": [3, 0, 0], \"horizon\": 1}", QStringLiteral("plan to"));
}

void TestPlanFileAndView::fitsAt1024x768AndInPresentation() {
    Scene s = straightScene();
    s.plan = ScenePlan{};
    s.plan->to = {0, 1, 0};
    m_window->document()->loadNow(s);
    m_canvas->setPlanMode(true);
    // CHAPLYGIN_PLAN_SHOTS: a folder for the pictures to look at
    const QString shots = qEnvironmentVariable("CHAPLYGIN_PLAN_SHOTS");
    struct Case {
        QSize size;
        bool presenting;
        const char* name;
    };
    for (const Case& c :
         {Case{{1280, 800}, false, "plan-1280x800"}, Case{{1024, 768}, false, "plan-1024x768"},
          Case{{1024, 768}, true, "plan-presentation-1024x768"}}) {
        m_window->presentation()->setFullScreen(false);
        m_window->presentation()->setActive(c.presenting);
        m_window->resize(c.size);
        QApplication::processEvents();
        m_canvas->fitScene();
        const QRectF area = m_canvas->drawingArea();
        // the handles and both optimal tracks in the drawing area
        QVERIFY2(area.contains(m_tool->targetHandle()), c.name);
        QVERIFY2(area.contains(m_tool->startHandle()), c.name);
        QVERIFY2(area.contains(m_tool->headingHandle()), c.name);
        const QTransform world = m_canvas->worldToPixel();
        for (int i = 0; i < 2; ++i)
            for (QPointF p : m_tool->tracks().at(std::size_t(i)).points)
                QVERIFY2(area.adjusted(-1, -1, 1, 1).contains(world.map(p)), c.name);
        // the three actions on the toolbar, whole in the window
        for (const char* name : {"planAction", "playPlanAction", "trackPlanAction"}) {
            QAction* action = m_window->findChild<QAction*>(QLatin1String(name));
            QVERIFY(action);
            QWidget* button = m_window->timeline()->widgetForAction(action);
            QVERIFY2(button && button->isVisible(), name);
            const QRect box(button->mapTo(m_window.get(), QPoint()), button->size());
            QVERIFY2(m_window->rect().contains(box), name);
        }
        if (!shots.isEmpty())
            QVERIFY(m_window->grab().save(shots + QLatin1Char('/') + QLatin1String(c.name) +
                                          QStringLiteral(".png")));
    }
    m_window->presentation()->setActive(false);
}

void TestPlanFileAndView::aSceneWithAPlanOpensFramingEveryMotion() {
    // a target above the start, turned by pi: the motions loop far outside the path's box; the
    // scene opened from a file must show all of them (each integrated here by RK4)
    // opened in a small window grown afterwards, as the program opens a file given to it
    m_canvas->setPlanMode(false);
    m_window->resize(500, 400);
    QApplication::processEvents();
    Scene s = straightScene();
    s.path.points = {{0, 0}, {3, 0}};
    s.plan = ScenePlan{};
    s.plan->to = {1.5, 2.0, std::numbers::pi};
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("plan.chaplygin.json"));
    {
        std::ofstream out(file.toStdString());
        out << sceneToJson(s);
    }
    m_window->document()->open(file);
    QApplication::processEvents();
    m_window->resize(1200, 750);
    QApplication::processEvents();
    QVERIFY(m_canvas->planMode());
    const auto& motions = m_tool->planned().geodesics;
    QVERIFY(motions.size() >= 3);
    const double b = m_window->document()->solution()->system().b;
    const double v = m_window->document()->scene().speed;
    const QRectF area = m_canvas->drawingArea().adjusted(-1, -1, 1, 1);
    const QTransform world = m_canvas->worldToPixel();
    for (const PlannedGeodesic& g : motions)
        for (const Knife& k : integrateKnife({0, 0, 0, g.psi0, g.psidot0}, b, v, g.t, 2000))
            QVERIFY2(area.contains(world.map(QPointF(k.x, k.y))),
                     qPrintable(QStringLiteral("the motion of %1 s at (%2, %3) m is out of view")
                                    .arg(g.t)
                                    .arg(k.x)
                                    .arg(k.y)));
}

QTEST_MAIN(TestPlanFileAndView)
#include "test_plan_file_and_view.moc"
