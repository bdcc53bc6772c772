// Time and view: new scenes start at t = 0, Home/End, one step is one frame at the current
// speed, Fit frames everything that moves, Follow keeps the body centred. Offscreen, real widgets.
#include "canvas/scene_canvas.h"
#include "panels/parameters_panel.h"
#include "panels/path_panel.h"
#include "scene/presets.h"
#include "shell/playback.h"
#include "shell/timeline_bar.h"
#include "widgets/number_field.h"
#include "window_fixture.h"

#include <QComboBox>
#include <QLineEdit>
#include <QMenu>
#include <QRadioButton>
#include <QtTest>

#include <cmath>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestTimeAndView : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_time_and_view_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void newSceneStartsAtZero();
    void homeAndEndKeys();
    void stepIsOneFrameAtCurrentSpeed();
    void everySpeedFromTheMenuAndKeysStepsRight();
    void fitFramesEverythingThatMoves();
    void followKeepsBodyCentred();
};

void TestTimeAndView::newSceneStartsAtZero() {
    Playback* playback = m_window->playback();
    playback->seek(5);
    playback->play();
    choosePreset("circle");
    QCOMPARE(playback->time(), 0.0);
    QVERIFY(!playback->isPlaying());
    // a typed path too (the circle is parametric)
    playback->seek(3);
    PathPanel* panel = m_window->pathPanel();
    QVERIFY(panel->parametricButton()->isChecked());
    panel->xOfUEdit()->setText(QStringLiteral("3*cos(u)"));
    QTest::keyClick(panel->xOfUEdit(), Qt::Key_Return);
    m_window->document()->flush();
    QTRY_COMPARE(QString::fromStdString(m_window->document()->scene().path.xOfU),
                 QStringLiteral("3*cos(u)"));
    QCOMPARE(playback->time(), 0.0);
    // the setting: new scenes start playing
    m_window->playNewScenesAction()->setChecked(true);
    choosePreset("catenary");
    QCOMPARE(playback->time(), 0.0);
    QVERIFY(playback->isPlaying());
    playback->pause();
    // a parameter change keeps the time (the slider is being explored)
    playback->seek(2);
    m_window->parametersPanel()->spinBox(QStringLiteral("m"))->setValue(2.5);
    m_window->document()->flush();
    QCOMPARE(playback->time(), 2.0);
}

void TestTimeAndView::homeAndEndKeys() {
    Playback* playback = m_window->playback();
    playback->seek(1.5);
    QTest::keyClick(m_window.get(), Qt::Key_End);
    QCOMPARE(playback->time(), playback->tEnd());
    QTest::keyClick(m_window.get(), Qt::Key_Home);
    QCOMPARE(playback->time(), 0.0);
}

void TestTimeAndView::stepIsOneFrameAtCurrentSpeed() {
    Playback* playback = m_window->playback();
    TimelineBar* bar = m_window->timeline();
    playback->seek(1);
    bar->speedBox()->setCurrentIndex(bar->speedBox()->findData(1.0));
    QTest::keyClick(m_window.get(), Qt::Key_Period);
    const double frame = playback->time() - 1;
    QVERIFY(frame > 0.01 && frame < 0.05); // one display frame at x1
    // the advance of one frame of play equals one step
    playback->seek(1);
    playback->advance(0.016);
    QVERIFY(std::abs(playback->time() - 1 - frame) < 1e-12);
    bar->speedBox()->setCurrentIndex(bar->speedBox()->findData(4.0));
    playback->seek(1);
    QTest::keyClick(m_window.get(), Qt::Key_Period);
    QVERIFY(std::abs(playback->time() - 1 - 4 * frame) < 1e-12);
    QTest::keyClick(m_window.get(), Qt::Key_Comma);
    QVERIFY(std::abs(playback->time() - 1) < 1e-12);
    // Shift: one second either way, clamped to the motion
    QTest::keyClick(m_window.get(), Qt::Key_Period, Qt::ShiftModifier);
    QVERIFY(std::abs(playback->time() - 2) < 1e-12);
    QTest::keyClick(m_window.get(), Qt::Key_Comma, Qt::ShiftModifier);
    QVERIFY(std::abs(playback->time() - 1) < 1e-12);
    QTest::keyClick(m_window.get(), Qt::Key_Comma, Qt::ShiftModifier);
    QTest::keyClick(m_window.get(), Qt::Key_Comma, Qt::ShiftModifier);
    QCOMPARE(playback->time(), 0.0);
}

void TestTimeAndView::everySpeedFromTheMenuAndKeysStepsRight() {
    // a long path, so that even x64's steps stay inside the motion
    Scene longSinusoid = presetScene("sinusoid");
    longSinusoid.preset.clear();
    longSinusoid.path.to = 60; // some 80 s along y = -sin x
    m_window->loadScene(longSinusoid);
    Playback* playback = m_window->playback();
    TimelineBar* bar = m_window->timeline();
    const double t0 = 3;
    QVERIFY(playback->tEnd() > t0 + 2 * 64 * 0.5);
    // the frame at x1, measured once: one step forward from t0
    bar->normalSpeedAction()->trigger();
    playback->seek(t0);
    QTest::keyClick(m_window.get(), Qt::Key_Period);
    const double frame = playback->time() - t0;
    QVERIFY(frame > 0.01 && frame < 0.05);
    auto* menu = m_window->findChild<QMenu*>(QStringLiteral("speedMenu"));
    QVERIFY(menu);
    QStringList labels;
    int chosen = 0;
    for (QAction* entry : menu->actions()) {
        if (!entry->isCheckable())
            continue;
        entry->trigger();
        QVERIFY(entry->isChecked());
        labels << entry->text();
        const double factor = std::ldexp(1.0, chosen - 4); // 1/16, 1/8, ..., 64
        ++chosen;
        QCOMPARE(playback->speedFactor(), factor);
        QCOMPARE(bar->speedBox()->currentText(), entry->text());
        // a step forward and back is one frame at this speed
        playback->seek(t0);
        QTest::keyClick(m_window.get(), Qt::Key_Period);
        QVERIFY2(std::abs(playback->time() - t0 - factor * frame) < 1e-12 * factor,
                 qPrintable(entry->text()));
        QTest::keyClick(m_window.get(), Qt::Key_Comma);
        QVERIFY(std::abs(playback->time() - t0) < 1e-12);
        // half a second of play moves by half a second times the speed
        playback->seek(t0);
        playback->advance(0.5);
        QVERIFY2(std::abs(playback->time() - t0 - 0.5 * factor) < 1e-12 * factor,
                 qPrintable(entry->text()));
    }
    QCOMPARE(labels, QStringList({QStringLiteral("\u00d71/16"), QStringLiteral("\u00d71/8"),
                                  QStringLiteral("\u00d71/4"), QStringLiteral("\u00d71/2"),
                                  QStringLiteral("\u00d71"), QStringLiteral("\u00d72"),
                                  QStringLiteral("\u00d74"), QStringLiteral("\u00d78"),
                                  QStringLiteral("\u00d716"), QStringLiteral("\u00d732"),
                                  QStringLiteral("\u00d764")}));
    // the keys: Backspace is x1, ] goes up to x64 and stops there, [ down to x1/16
    QTest::keyClick(m_window.get(), Qt::Key_Backspace);
    QCOMPARE(playback->speedFactor(), 1.0);
    for (int i = 0; i < 8; ++i)
        QTest::keyClick(m_window.get(), Qt::Key_BracketRight);
    QCOMPARE(playback->speedFactor(), 64.0);
    QVERIFY(!bar->fasterAction()->isEnabled());
    for (int i = 0; i < 12; ++i)
        QTest::keyClick(m_window.get(), Qt::Key_BracketLeft);
    QCOMPARE(playback->speedFactor(), 1.0 / 16);
    QVERIFY(!bar->slowerAction()->isEnabled());
    QTest::keyClick(m_window.get(), Qt::Key_BracketRight);
    QCOMPARE(playback->speedFactor(), 1.0 / 8);
    QVERIFY(bar->slowerAction()->isEnabled());
}

void TestTimeAndView::fitFramesEverythingThatMoves() {
    // the sinusoid's free ghost runs far from the path: it stays in view over the whole horizon
    SceneCanvas* canvas = m_window->canvas();
    canvas->fitEverything();
    const Solution& solution = *m_window->document()->solution();
    QRectF area = canvas->drawingArea().adjusted(-1, -1, 1, 1);
    int outside = 0;
    for (int i = 0; i <= 400; ++i) {
        double t = solution.tEnd() * i / 400;
        MotionSample m = solution.at(t);
        outside += area.contains(canvas->toPixel({m.x, m.y})) ? 0 : 1;
        outside += area.contains(canvas->toPixel({m.free.x, m.free.y})) ? 0 : 1;
    }
    QCOMPARE(outside, 0);
    // and the view is not needlessly small: the scene fills one of the two directions
    QRectF b = canvas->sceneBounds();
    double used = std::max(b.width() * canvas->scale() / area.width(),
                           b.height() * canvas->scale() / area.height());
    QVERIFY(used > 0.9);
}

void TestTimeAndView::followKeepsBodyCentred() {
    SceneCanvas* canvas = m_window->canvas();
    m_window->followAction()->setChecked(true);
    QVERIFY(canvas->followsBody());
    for (double t : {0.5, 2.0, 4.0}) {
        m_window->playback()->seek(t);
        MotionSample m = m_window->document()->solution()->at(t);
        QPointF p = canvas->toPixel({m.x, m.y});
        QVERIFY(std::abs(p.x() - canvas->width() / 2.0) < 1);
        QVERIFY(std::abs(p.y() - canvas->height() / 2.0) < 1);
    }
    // a new scene's fit ends following, a new follow starts it again
    canvas->fitScene();
    QVERIFY(!m_window->followAction()->isChecked());
}

QTEST_MAIN(TestTimeAndView)
#include "test_time_and_view.moc"
