// Following the body at a readable size: entering follow zooms to the scale where the body is a
// sixth of the drawing area's smaller side, the wheel and the zoom keys change that follow zoom
// and keep it, and leaving follow (or Fit) returns to the whole view.
#include "canvas/body_painter.h"
#include "canvas/scene_canvas.h"
#include "scene/scene.h"
#include "scene/solution.h"
#include "shell/playback.h"
#include "window_fixture.h"

#include <QAction>
#include <QWheelEvent>
#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

// y = sin x over [0, 200]: the whole path's scale makes the body a dot
Scene longSine() {
    Scene scene;
    scene.path.y = "sin(x)";
    scene.path.from = 0;
    scene.path.to = 200;
    return scene;
}

void wheel(QWidget* widget, QPointF at, int delta) {
    QWheelEvent e(at, widget->mapToGlobal(at), QPoint(), QPoint(0, delta), Qt::NoButton, {},
                  Qt::NoScrollPhase, false);
    QApplication::sendEvent(widget, &e);
}

} // namespace

class TestFollowZoom : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_follow_zoom_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void followShowsTheBodyAtAReadableSize();
    void wheelWhileFollowingKeepsTheFollowZoom();
    void leavingFollowReturnsToTheWholeView();
    void fitEndsFollowingAtTheFit();

  private:
    SceneCanvas* canvas() const { return m_window->canvas(); }
    // the controlled body's drawn box at time t, in pixels
    QRectF bodyPixels(double t) const {
        const Solution& s = *m_window->document()->solution();
        const MotionSample m = s.at(t);
        const QRectF box = bodyBounds(s.scene().system, s.system(), {m.x, m.y, m.phi});
        return QRectF(canvas()->toPixel(box.topLeft()), canvas()->toPixel(box.bottomRight()))
            .normalized();
    }
    double smallerSide() const {
        const QRectF area = canvas()->drawingArea();
        return std::min(area.width(), area.height());
    }
    void checkCentred(double t) {
        const MotionSample m = m_window->document()->solution()->at(t);
        const QPointF p = canvas()->toPixel({m.x, m.y});
        QVERIFY(std::abs(p.x() - canvas()->width() / 2.0) <= 0.5 + 1e-9);
        QVERIFY(std::abs(p.y() - canvas()->height() / 2.0) <= 0.5 + 1e-9);
    }
};

void TestFollowZoom::followShowsTheBodyAtAReadableSize() {
    // the long sine's body is a dot in the whole view; the circle's is larger than a sixth of
    // the canvas already, and following does not make it smaller
    for (const char* preset : {"long sine", "circle"}) {
        if (QLatin1String(preset) == QLatin1String("circle")) {
            choosePreset(preset);
        } else {
            m_window->document()->setSceneNow(longSine());
            QVERIFY(m_window->document()->error().isEmpty());
        }
        canvas()->fitScene();
        m_window->playback()->seek(1.0);
        const double wholeScale = canvas()->scale();
        const QRectF before = bodyPixels(1.0);
        m_window->followAction()->setChecked(true);
        QVERIFY(canvas()->followsBody());
        checkCentred(1.0);
        // the circle that holds the body is a sixth of the smaller side, or as large as before
        const Solution& s = *m_window->document()->solution();
        const double extent = bodyExtent(s.scene().system, s.system());
        const double expected = std::max(smallerSide() / 6 / (2 * extent), wholeScale);
        QVERIFY2(std::abs(canvas()->scale() / expected - 1) < 1e-12,
                 qPrintable(QStringLiteral("%1: %2 px/m, expected %3")
                                .arg(preset)
                                .arg(canvas()->scale())
                                .arg(expected)));
        const QRectF drawn = bodyPixels(1.0);
        const double size = std::max(drawn.width(), drawn.height());
        const double was = std::max(before.width(), before.height());
        qInfo("%s: the body %.1f px in the whole view, %.1f px following (smaller side %.0f px)",
              preset, was, size, smallerSide());
        // the body drawn fills most of that circle
        QVERIFY2(size > smallerSide() / 12 && size >= was - 1e-9,
                 qPrintable(QStringLiteral("%1: %2 px").arg(preset).arg(size)));
        if (QLatin1String(preset) != QLatin1String("circle"))
            QVERIFY(size > 3 * was);
        m_window->followAction()->setChecked(false);
    }
}

void TestFollowZoom::wheelWhileFollowingKeepsTheFollowZoom() {
    m_window->followAction()->setChecked(true);
    const double readable = canvas()->scale();
    // three notches away from the reader: 1.0015^360 times, following still
    wheel(canvas(), QPointF(40, 60), 360);
    QVERIFY(canvas()->followsBody());
    QVERIFY(std::abs(canvas()->scale() / readable - std::pow(1.0015, 360)) < 1e-12);
    m_window->playback()->seek(2.0);
    checkCentred(2.0);
    QCOMPARE(canvas()->scale(), readable * std::pow(1.0015, 360));
    // the zoom key too
    canvas()->zoomBy(0.8);
    QVERIFY(canvas()->followsBody());
    const double chosen = readable * std::pow(1.0015, 360) * 0.8;
    QVERIFY(std::abs(canvas()->scale() / chosen - 1) < 1e-12);
    // off and on again: the follow zoom is kept
    m_window->followAction()->setChecked(false);
    m_window->followAction()->setChecked(true);
    QVERIFY(std::abs(canvas()->scale() / chosen - 1) < 1e-12);
    // B on the canvas leaves and enters it the same way
    canvas()->setFocus();
    QTest::keyClick(canvas(), Qt::Key_B);
    QVERIFY(!canvas()->followsBody());
    QVERIFY(!m_window->followAction()->isChecked());
    QTest::keyClick(canvas(), Qt::Key_B);
    QVERIFY(m_window->followAction()->isChecked());
    QVERIFY(std::abs(canvas()->scale() / chosen - 1) < 1e-12);
}

void TestFollowZoom::leavingFollowReturnsToTheWholeView() {
    m_window->document()->setSceneNow(longSine());
    canvas()->fitScene();
    const double scale = canvas()->scale();
    const QPointF centre =
        canvas()->toWorld(QPointF(canvas()->width() / 2.0, canvas()->height() / 2.0));
    m_window->followAction()->setChecked(true);
    m_window->playback()->seek(3.0);
    QVERIFY(canvas()->scale() != scale);
    m_window->followAction()->setChecked(false);
    QCOMPARE(canvas()->scale(), scale);
    const QPointF back =
        canvas()->toWorld(QPointF(canvas()->width() / 2.0, canvas()->height() / 2.0));
    QVERIFY(std::abs(back.x() - centre.x()) * scale < 1e-6);
    QVERIFY(std::abs(back.y() - centre.y()) * scale < 1e-6);
    // a view the user zoomed is returned to as well
    canvas()->zoomBy(1.25);
    const double zoomed = canvas()->scale();
    m_window->followAction()->setChecked(true);
    m_window->followAction()->setChecked(false);
    QCOMPARE(canvas()->scale(), zoomed);
}

void TestFollowZoom::fitEndsFollowingAtTheFit() {
    canvas()->fitScene();
    const double fitted = canvas()->scale();
    m_window->followAction()->setChecked(true);
    canvas()->zoomBy(2);
    canvas()->fitScene();
    QVERIFY(!canvas()->followsBody());
    QVERIFY(!m_window->followAction()->isChecked());
    QCOMPARE(canvas()->scale(), fitted);
}

QTEST_MAIN(TestFollowZoom)
#include "test_follow_zoom.moc"
