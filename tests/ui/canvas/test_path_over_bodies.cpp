// The path laid over the bodies drawn to scale (SceneCanvas::paintPathOverBodies): the band and
// the controlled trail kept within each body's area, from the path's layer or, at a view's first
// paint, drawn within each body's box; the same picture either way.
#include "canvas/canvas_style.h"
#include "canvas/scene_canvas.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "pixel_difference.h"
#include "scene/presets.h"
#include "shell/main_window.h"
#include "shell/playback.h"

#include <QtTest>

#include <algorithm>
#include <memory>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestPathOverBodies : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase();
    void init();
    void cleanup();

    void pathOverBodiesAtAViewsFirstPaintIsWhatItsLayerDraws();

  private:
    std::unique_ptr<MainWindow> m_window;
};

void TestPathOverBodies::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_path_over_bodies_tests"));
}

void TestPathOverBodies::init() {
    m_window = test::showTestWindow();
    QVERIFY(m_window && m_window->document()->solution());
    // the view these frames were measured at: every body small beside the canvas
    m_window->canvas()->fitEverything();
}

void TestPathOverBodies::cleanup() {
    m_window.reset();
}

void TestPathOverBodies::pathOverBodiesAtAViewsFirstPaintIsWhatItsLayerDraws() {
    // the catenary's large sleighs drawn to scale cover the path: at a view's first paint (a zoom
    // step) the band is drawn within each body's box, at the next from the layer made for the
    // view; the same picture, zoomed out, zoomed in and while following
    m_window->loadScene(presetScene("catenary"));
    m_window->document()->flush();
    SceneCanvas* canvas = m_window->canvas();
    canvas->fitScene();
    CanvasStyle style = canvas->canvasStyle();
    style.body = BodyDisplay::ToScale;
    canvas->setCanvasStyle(style);
    m_window->playback()->seek(2);
    QCoreApplication::processEvents();
    auto twice = [&](const char* where) {
        const QImage first = canvas->grab().toImage().convertToFormat(QImage::Format_RGB32);
        QVERIFY2(!canvas->pathOverBodiesFromLayer(), where);
        const QImage second = canvas->grab().toImage().convertToFormat(QImage::Format_RGB32);
        QVERIFY2(canvas->pathOverBodiesFromLayer(), where);
        QCOMPARE(first.size(), second.size());
        int differing = 0, largest = 0;
        for (int y = 0; y < first.height(); ++y)
            for (int x = 0; x < first.width(); ++x) {
                const QRgb a = first.pixel(x, y), b = second.pixel(x, y);
                const int d = test::channelDifference(a, b);
                largest = std::max(largest, d);
                differing += d > 0 ? 1 : 0;
            }
        QVERIFY2(largest <= 2 && differing <= 20,
                 qPrintable(QStringLiteral("%1: %2 pixels differ, by up to %3")
                                .arg(where)
                                .arg(differing)
                                .arg(largest)));
    };
    canvas->zoomBy(1 / 1.1); // each view is new: the window has not painted it
    twice("zoomed out by 1.1");
    canvas->zoomBy(3.3);
    twice("zoomed in by 3");
    canvas->setFollowBody(true);
    QCoreApplication::processEvents();
    canvas->zoomBy(1.1);
    twice("following, zoomed in by 3.3");
}

QTEST_MAIN(TestPathOverBodies)
#include "test_path_over_bodies.moc"
