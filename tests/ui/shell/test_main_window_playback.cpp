// GUI tests of the main window's time and view, driving the real widgets under the offscreen
// platform: the bodies drawn at their poses, panning and following, play, pause and seek, a click
// on a plot that seeks, Space typed into a text field.
#include "canvas/scene_canvas.h"
#include "document/scene_document.h"
#include "panels/path_panel.h"
#include "plots/plots_panel.h"
#include "shell/main_window.h"
#include "shell/playback.h"
#include "shell/timeline_bar.h"
#include "window_fixture.h"

#include <QAction>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QSlider>
#include <QtTest>
#include <qcustomplot.h>

#include <cmath>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestMainWindowPlayback : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_main_window_playback_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void canvasDrawsBodiesAtTheirPoses();
    void playPauseSeek();
    void clickingPlotSeeks();
    void spaceTypesInTextFields();
};

void TestMainWindowPlayback::canvasDrawsBodiesAtTheirPoses() {
    SceneCanvas* canvas = m_window->canvas();
    canvas->fitEverything(); // the free ghost runs far from the path
    m_window->playback()->seek(6.0);
    MotionSample m = m_window->document()->solution()->at(6.0);
    QImage image = canvas->grab().toImage();
    double dpr = image.devicePixelRatio();
    auto colourAt = [&](double x, double y) {
        QPointF p = canvas->toPixel(QPointF(x, y)) * dpr;
        return image.pixelColor(p.toPoint());
    };
    // inside the controlled board, between the knife and the centre of mass (a = 0.5 ahead of P):
    // blue; inside the free ghost: pale red; far from both: white
    double ahead = 0.25;
    QColor body = colourAt(m.x + ahead * std::cos(m.phi) + 0.3 * -std::sin(m.phi),
                           m.y + ahead * std::sin(m.phi) + 0.3 * std::cos(m.phi));
    QVERIFY2(body.blue() > body.red() + 60, qPrintable(body.name()));
    QColor ghost = colourAt(m.free.x + ahead * std::cos(m.free.phi) + 0.3 * -std::sin(m.free.phi),
                            m.free.y + ahead * std::sin(m.free.phi) + 0.3 * std::cos(m.free.phi));
    QVERIFY2(ghost.red() > ghost.blue() + 20, qPrintable(ghost.name()));
    QCOMPARE(canvas->toWorld(canvas->toPixel(QPointF(1.25, -0.5))), QPointF(1.25, -0.5));
    // the arrow keys pan by a tenth of the view
    QPointF before = canvas->toPixel(QPointF(1.0, 1.0));
    QTest::keyClick(canvas, Qt::Key_Right);
    QPointF after = canvas->toPixel(QPointF(1.0, 1.0));
    QVERIFY(std::abs(before.x() - after.x() - 0.1 * canvas->width()) < 1e-6);
    QVERIFY(std::abs(before.y() - after.y()) < 1e-9);
    // following the body puts it in the middle of the canvas
    m_window->followAction()->trigger();
    QVERIFY(canvas->followsBody());
    QPointF centre = canvas->toPixel(QPointF(m.x, m.y));
    QVERIFY(std::abs(centre.x() - canvas->width() / 2.0) < 1);
    QVERIFY(std::abs(centre.y() - canvas->height() / 2.0) < 1);
}

void TestMainWindowPlayback::playPauseSeek() {
    Playback* playback = m_window->playback();
    playback->seek(2.0);
    QCOMPARE(m_window->canvas()->time(), 2.0);
    QCOMPARE(m_window->plotsPanel()->cursorTime(), 2.0);
    QVERIFY(m_window->timeline()->timeLabel()->text().contains(QStringLiteral("2.00")));
    QCustomPlot* psi = m_window->plotsPanel()->plot(0);
    psi->replot();
    double x2 = psi->axisRect()->axis(QCPAxis::atBottom)->coordToPixel(2.0);
    QVERIFY(std::abs(m_window->plotsPanel()->cursor(0)->geometry().center().x() - x2) <= 1.5);
    QVERIFY(m_window->plotsPanel()->cursor(0)->isVisible());
    int sliderAt2 = m_window->timeline()->slider()->value();
    QVERIFY(sliderAt2 > 0);
    QTest::keyClick(m_window.get(), Qt::Key_Space);
    QVERIFY(playback->isPlaying());
    QTRY_VERIFY_WITH_TIMEOUT(playback->time() > 2.1, 3000);
    QTest::keyClick(m_window.get(), Qt::Key_Space);
    QVERIFY(!playback->isPlaying());
    double paused = playback->time();
    QTest::qWait(100);
    QCOMPARE(playback->time(), paused);
    m_window->timeline()->stepForwardAction()->trigger();
    QVERIFY(std::abs(playback->time() - (paused + playback->stepSize())) < 1e-12);
    // scrubbing the slider seeks
    m_window->timeline()->slider()->setValue(1000);
    QVERIFY(std::abs(playback->time() - playback->tEnd() / 2) < 1e-9);
    // the end stops unless looping
    playback->seek(playback->tEnd() - 0.01);
    playback->play();
    QTRY_VERIFY_WITH_TIMEOUT(!playback->isPlaying(), 3000);
    QCOMPARE(playback->time(), playback->tEnd());
}

void TestMainWindowPlayback::clickingPlotSeeks() {
    QCustomPlot* plot = m_window->plotsPanel()->plot(3);
    plot->replot();
    QCPAxis* t = plot->axisRect()->axis(QCPAxis::atBottom);
    int x = int(std::lround(t->coordToPixel(5.0)));
    int y = plot->axisRect()->center().y();
    QTest::mouseClick(plot, Qt::LeftButton, {}, QPoint(x, y));
    // once the double-click interval has passed: a double click does not seek
    QTRY_VERIFY2(std::abs(m_window->playback()->time() - 5.0) < 0.1,
                 qPrintable(QString::number(m_window->playback()->time())));
    QVERIFY(std::abs(m_window->canvas()->time() - m_window->playback()->time()) < 1e-12);
    // dragging with the button down scrubs
    QPoint to(int(std::lround(t->coordToPixel(8.0))), y);
    QTest::mousePress(plot, Qt::LeftButton, {}, QPoint(x, y));
    QMouseEvent drag(QEvent::MouseMove, to, plot->mapToGlobal(to), Qt::NoButton, Qt::LeftButton,
                     {});
    QApplication::sendEvent(plot, &drag);
    QVERIFY(std::abs(m_window->playback()->time() - 8.0) < 0.1);
    QTest::mouseRelease(plot, Qt::LeftButton, {}, to);
}

void TestMainWindowPlayback::spaceTypesInTextFields() {
    QLineEdit* edit = m_window->pathPanel()->graphEdit();
    edit->setFocus();
    QTRY_VERIFY(edit->hasFocus());
    edit->end(false);
    QTest::keyClick(edit, Qt::Key_Space);
    QVERIFY(!m_window->playback()->isPlaying());
    QCOMPARE(edit->text(), QStringLiteral("-sin(x) "));
    // elsewhere Space plays and pauses
    m_window->canvas()->setFocus();
    QTest::keyClick(m_window->canvas(), Qt::Key_Space);
    QVERIFY(m_window->playback()->isPlaying());
    QTest::keyClick(m_window->canvas(), Qt::Key_Space);
    QVERIFY(!m_window->playback()->isPlaying());
}

QTEST_MAIN(TestMainWindowPlayback)
#include "test_main_window_playback.moc"
