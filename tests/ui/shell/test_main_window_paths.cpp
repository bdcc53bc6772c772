// GUI tests of the main window's paths, driving the real widgets under the offscreen platform: a
// graph y(x) and a parametric curve typed, a typing error that keeps the last valid path, a path
// drawn with the mouse and its points dragged and deleted.
#include "canvas/scene_canvas.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "panels/parameters_panel.h"
#include "panels/path_panel.h"
#include "shell/main_window.h"
#include "widgets/number_field.h"
#include "window_fixture.h"

#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QUndoStack>
#include <QtTest>

#include <cmath>

using namespace chaplygin;
using namespace chaplygin::ui;
using namespace chaplygin::ui::test;

class TestMainWindowPaths : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_main_window_paths_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void typedValidPath();
    void typedInvalidPathKeepsLastValid();
    void drawPathWithMouse();
    void editDrawnPathPoints();
    void typedParametricPath();
};

void TestMainWindowPaths::typedValidPath() {
    PathPanel* panel = m_window->pathPanel();
    typeInto(panel->graphEdit(), QStringLiteral("0.3*x^2"));
    panel->fromSpin()->setValue(0);
    panel->toSpin()->setValue(3);
    QTest::keyClick(panel->graphEdit(), Qt::Key_Return);
    m_window->document()->flush();
    const Scene& scene = m_window->document()->scene();
    QCOMPARE(QString::fromStdString(scene.path.y), QStringLiteral("0.3*x^2"));
    QVERIFY(panel->errorText().isEmpty());
    // the new solution runs along the parabola: it ends at (3, 2.7)
    const auto& solution = m_window->document()->solution();
    PathNode end = solution->path()->end();
    QVERIFY(std::abs(end.x - 3) < 1e-9);
    QVERIFY(std::abs(end.y - 2.7) < 1e-9);
}

void TestMainWindowPaths::typedInvalidPathKeepsLastValid() {
    PathPanel* panel = m_window->pathPanel();
    auto before = m_window->document()->solution();
    Scene sceneBefore = m_window->document()->scene();
    typeInto(panel->graphEdit(), QStringLiteral("sin(x"));
    QTest::keyClick(panel->graphEdit(), Qt::Key_Return);
    m_window->document()->flush();
    QVERIFY2(!panel->errorText().isEmpty(), "an inline error is shown");
    QVERIFY2(panel->errorText().contains(QStringLiteral("position")),
             qPrintable(panel->errorText()));
    QVERIFY(panel->findChild<QLabel*>(QStringLiteral("pathError"))->isVisible());
    QCOMPARE(m_window->document()->solution(), before);
    QVERIFY(m_window->document()->scene() == sceneBefore);
    QCOMPARE(m_window->undoStack()->count(), 0);
    // a valid path afterwards clears the error
    typeInto(panel->graphEdit(), QStringLiteral("sin(x)"));
    QTest::keyClick(panel->graphEdit(), Qt::Key_Return);
    QTRY_VERIFY(panel->errorText().isEmpty()); // a slow path is built on the worker
    QCOMPARE(QString::fromStdString(m_window->document()->scene().path.y),
             QStringLiteral("sin(x)"));
}

void TestMainWindowPaths::drawPathWithMouse() {
    m_window->pathPanel()->cornersBox()->setCurrentIndex(0); // smooth
    m_window->pathPanel()->drawButton()->click();
    SceneCanvas* canvas = m_window->canvas();
    QVERIFY(canvas->drawMode());
    QPoint start(100, 200);
    QPointF startWorld = canvas->toWorld(QPointF(start)); // before the view refits to the new path
    QTest::mousePress(canvas, Qt::LeftButton, {}, start);
    for (int i = 1; i <= 30; ++i) {
        QPoint p(100 + 15 * i, 200 - int(60 * std::sin(i / 5.0)));
        QMouseEvent move(QEvent::MouseMove, p, canvas->mapToGlobal(p), Qt::NoButton, Qt::LeftButton,
                         {});
        QApplication::sendEvent(canvas, &move);
    }
    QPoint end(100 + 15 * 30, 200 - int(60 * std::sin(6.0)));
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, end);
    m_window->document()->flush();
    const PathSource& path = m_window->document()->scene().path;
    QCOMPARE(path.kind, PathKind::Polyline);
    QVERIFY2(path.points.size() >= 20, "the stroke is sampled");
    QCOMPARE(path.corners, CornerMode::Smooth);
    // the first point is where the mouse went down, in metres
    QVERIFY(std::abs(path.points.front().first - startWorld.x()) < 1e-9);
    QVERIFY(std::abs(path.points.front().second - startWorld.y()) < 1e-9);
    QVERIFY(m_window->document()->error().isEmpty());
    QCOMPARE(m_window->document()->solution()->scene().path.kind, PathKind::Polyline);
    QVERIFY(m_window->document()->solution()->path()->length() > 1.0);
}

void TestMainWindowPaths::editDrawnPathPoints() {
    m_window->pathPanel()->cornersBox()->setCurrentIndex(1); // pivot
    m_window->pathPanel()->drawButton()->click();
    SceneCanvas* canvas = m_window->canvas();
    // three right-angle turns: each a pivot corner (over the corner angle, 35 degrees)
    test::dragStroke(canvas, QPoint(100, 300),
                     {QPoint(200, 300), QPoint(200, 200), QPoint(300, 200)}, QPoint(300, 300));
    m_window->document()->flush();
    auto points = m_window->document()->scene().path.points;
    QCOMPARE(points.size(), std::size_t(5));
    QCOMPARE(m_window->document()->scene().path.corners, CornerMode::Pivot);
    QCOMPARE(m_window->document()->solution()->path()->pivotCount(), 3);
    // drag vertex 2 by (0, +40) px
    QPoint from = canvas->toPixel(QPointF(points[2].first, points[2].second)).toPoint();
    QPoint to = from + QPoint(0, 40);
    QPointF target = canvas->toWorld(QPointF(to));
    QTest::mousePress(canvas, Qt::LeftButton, {}, from);
    QMouseEvent move(QEvent::MouseMove, to, canvas->mapToGlobal(to), Qt::NoButton, Qt::LeftButton,
                     {});
    QApplication::sendEvent(canvas, &move);
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, to);
    m_window->document()->flush();
    auto moved = m_window->document()->solution()->scene().path.points;
    QCOMPARE(moved.size(), std::size_t(5));
    QVERIFY(std::abs(moved[2].first - target.x()) < 1e-9);
    QVERIFY(std::abs(moved[2].second - target.y()) < 1e-9);
    QCOMPARE(moved[1], points[1]);
    // right click deletes a vertex
    QPoint third = canvas->toPixel(QPointF(moved[3].first, moved[3].second)).toPoint();
    QTest::mousePress(canvas, Qt::RightButton, {}, third);
    QTest::mouseRelease(canvas, Qt::RightButton, {}, third);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution()->scene().path.points.size(), std::size_t(4));
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QVERIFY(m_window->document()->solution()->scene().path.points == moved);
}

void TestMainWindowPaths::typedParametricPath() {
    PathPanel* panel = m_window->pathPanel();
    panel->parametricButton()->click();
    QVERIFY(!panel->graphEdit()->isEnabled());
    typeInto(panel->xOfUEdit(), QStringLiteral("3*cos(u)"));
    typeInto(panel->yOfUEdit(), QStringLiteral("3*sin(u)"));
    panel->fromSpin()->setValue(0);
    panel->toSpin()->setValue(M_PI);
    panel->applyButton()->click();
    m_window->document()->flush();
    QVERIFY2(panel->errorText().isEmpty(), qPrintable(panel->errorText()));
    const auto& solution = m_window->document()->solution();
    QCOMPARE(solution->scene().path.kind, PathKind::Parametric);
    // half a circle of radius 3 (the range box keeps the whole double of pi)
    QCOMPARE(solution->scene().path.to, M_PI);
    QVERIFY(std::abs(solution->path()->length() - 3 * M_PI) < 1e-9);
    // a typed error stays while a parameter changes; the path fields keep the user's text
    typeInto(panel->yOfUEdit(), QStringLiteral("3*sin(u"));
    panel->applyButton()->click();
    QTRY_VERIFY(!panel->errorText().isEmpty());
    m_window->parametersPanel()->spinBox(QStringLiteral("m"))->setValue(2.0);
    m_window->document()->flush();
    QCOMPARE(panel->yOfUEdit()->text(), QStringLiteral("3*sin(u"));
    QCOMPARE(m_window->document()->solution()->system().mass, 2.0);
    QVERIFY(std::abs(m_window->document()->solution()->path()->length() - 3 * M_PI) < 1e-9);
}

QTEST_MAIN(TestMainWindowPaths)
#include "test_main_window_paths.moc"
