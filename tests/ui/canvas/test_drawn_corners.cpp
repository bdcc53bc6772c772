// Corners where the hand turned, through the canvas: a zig-zag of four straight mouse strokes with
// pixel jitter pivots three times, a drawn half circle never; the corner mode chosen after
// drawing applies at once in draw mode, as one undo step.
#include "canvas/scene_canvas.h"
#include "gui_test_support.h"
#include "panels/path_panel.h"
#include "widgets/number_field.h"
#include "window_fixture.h"

#include <QComboBox>
#include <QMouseEvent>
#include <QPushButton>
#include <QUndoStack>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

// the mouse moving through `corners` in steps of about 3 px, each event off the line by up to
// 1 px (a hand's jitter, in whole pixels as a mouse reports them)
std::vector<QPoint> handPath(const std::vector<QPointF>& corners, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> shake(-1, 1);
    std::vector<QPoint> out;
    for (std::size_t k = 0; k + 1 < corners.size(); ++k) {
        const QPointF a = corners[k], b = corners[k + 1];
        const int steps = std::max(1, int(std::hypot(b.x() - a.x(), b.y() - a.y()) / 3));
        for (int i = 0; i < steps; ++i) {
            const QPointF p = a + (b - a) * (double(i) / steps);
            out.emplace_back(int(std::lround(p.x())) + shake(rng),
                             int(std::lround(p.y())) + shake(rng));
        }
    }
    out.push_back(corners.back().toPoint());
    return out;
}

// every other stroke 30 px right and lower: a press on a point of the last stroke would move
// that point instead of drawing
std::vector<QPointF> shifted(std::vector<QPointF> points, unsigned seed) {
    for (QPointF& p : points)
        p += seed % 2 == 0 ? QPointF(0, 0) : QPointF(30, 30);
    return points;
}

void drag(QWidget* canvas, const std::vector<QPoint>& points) {
    QTest::mousePress(canvas, Qt::LeftButton, {}, points.front());
    for (std::size_t i = 1; i + 1 < points.size(); ++i) {
        QMouseEvent move(QEvent::MouseMove, points[i], canvas->mapToGlobal(points[i]), Qt::NoButton,
                         Qt::LeftButton, {});
        QApplication::sendEvent(canvas, &move);
    }
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, points.back());
}

} // namespace

class TestDrawnCorners : public QObject, public test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_drawn_corners_tests"); }
    void init() { openWindowWithOwnSettings("ui_drawn_corners_tests"); }
    void cleanup() { closeWindow(); }
    void zigZagOfFourStrokesPivotsThreeTimes();
    void drawnHalfCircleDoesNotPivot();
    void cornerModeAppliesAtOnceInDrawMode();

  private:
    void startDrawing(CornerMode corners);
    int drawnPivots(const std::vector<QPoint>& stroke);
};

void TestDrawnCorners::startDrawing(CornerMode corners) {
    PathPanel* panel = m_window->pathPanel();
    if (!panel->drawButton()->isChecked())
        panel->drawButton()->click();
    QVERIFY(m_window->canvas()->drawMode());
    panel->cornersBox()->setCurrentIndex(panel->cornersBox()->findData(int(corners)));
}

int TestDrawnCorners::drawnPivots(const std::vector<QPoint>& stroke) {
    const QPointF press = m_window->canvas()->toWorld(QPointF(stroke.front()));
    drag(m_window->canvas(), stroke);
    m_window->document()->flush();
    const auto& solution = m_window->document()->solution();
    const PathSource& path = solution->scene().path;
    if (path.kind != PathKind::Polyline)
        return -1;
    // a new stroke from the press (the view may be fitted to it afterwards), a point every 10 px
    // or more
    if (path.points.front() != std::pair(press.x(), press.y()) || path.points.size() < 30)
        return -2;
    return solution->path()->pivotCount();
}

// four strokes of 113 px at +-45 degrees: the tool keeps a point every 10 px, some 38 in all,
// each a pixel off; 20 hands (seeds)
void TestDrawnCorners::zigZagOfFourStrokesPivotsThreeTimes() {
    startDrawing(CornerMode::Pivot);
    const std::vector<QPointF> zigZag = {
        {100, 300}, {180, 220}, {260, 300}, {340, 220}, {420, 300}};
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const int pivots = drawnPivots(handPath(shifted(zigZag, seed), seed));
        QCOMPARE(pivots, 3);
        QCOMPARE(m_window->document()->scene().path.corners, CornerMode::Pivot);
    }
}

// a half circle of radius 120 px over the top, some 34 points
void TestDrawnCorners::drawnHalfCircleDoesNotPivot() {
    startDrawing(CornerMode::Pivot);
    std::vector<QPointF> arc;
    for (int i = 0; i <= 60; ++i) {
        const double th = std::numbers::pi * (1 - i / 60.0);
        arc.emplace_back(300 + 120 * std::cos(th), 300 - 120 * std::sin(th));
    }
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const int pivots = drawnPivots(handPath(shifted(arc, seed), seed));
        QCOMPARE(pivots, 0);
    }
}

void TestDrawnCorners::cornerModeAppliesAtOnceInDrawMode() {
    startDrawing(CornerMode::Pivot);
    const std::vector<QPointF> zigZag = {
        {100, 300}, {180, 220}, {260, 300}, {340, 220}, {420, 300}};
    QCOMPARE(drawnPivots(handPath(zigZag, 5)), 3);
    const PathSource drawn = m_window->document()->scene().path;
    const int steps = m_window->undoStack()->count();
    // still drawing: "smooth" changes the stroke just drawn at once, in one undo step
    PathPanel* panel = m_window->pathPanel();
    QVERIFY(m_window->canvas()->drawMode());
    panel->cornersBox()->setCurrentIndex(panel->cornersBox()->findData(int(CornerMode::Smooth)));
    QTRY_COMPARE(m_window->document()->scene().path.corners, CornerMode::Smooth);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution()->path()->pivotCount(), 0);
    QCOMPARE(m_window->document()->scene().path.points, drawn.points);
    QCOMPARE(m_window->undoStack()->count(), steps + 1);
    QVERIFY(m_window->canvas()->drawMode());
    // so does the smoothing
    panel->smoothingSpin()->setValue(6.0);
    QTRY_COMPARE(m_window->document()->scene().path.smoothing, 6.0);
    QCOMPARE(m_window->undoStack()->count(), steps + 2);
    // undo gives the pivots back, and the panel shows them
    m_window->undoStack()->undo();
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().path, drawn);
    QCOMPARE(m_window->document()->solution()->path()->pivotCount(), 3);
    QCOMPARE(panel->cornersBox()->currentData().toInt(), int(CornerMode::Pivot));
}

QTEST_MAIN(TestDrawnCorners)
#include "test_drawn_corners.moc"
