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
    void thePartsInkCanReachDrawWhatTheWholeBoxDraws();

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
        const auto [differing, largest] = test::pictureDifference(first, second);
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

void TestPathOverBodies::thePartsInkCanReachDrawWhatTheWholeBoxDraws() {
    // The path over a body is laid only over the parts of its box that the band, the path's
    // marks and the controlled trail can ink (canvas/ink_rows). The reference lays it over the
    // whole box: the same pixels, at a view's first paint (the band drawn within the box) and
    // from the path's layer, for large and small bodies, a pivot's mark, zoomed in, following
    SceneCanvas* canvas = m_window->canvas();
    int compared = 0;
    auto compare = [&](const QString& where) {
        for (bool fromLayer : {false, true}) {
            QImage image[2];
            for (bool whole : {true, false}) {
                canvas->setPathOverBodiesWhole(whole);
                canvas->dropLayers(); // a view's first paint, then its layer made
                if (fromLayer)
                    canvas->grab();
                image[whole ? 0 : 1] =
                    canvas->grab().toImage().convertToFormat(QImage::Format_RGB32);
            }
            canvas->setPathOverBodiesWhole(false);
            const auto [differing, largest] = test::pictureDifference(image[0], image[1]);
            const QString what = QStringLiteral("%1, %2: %3 pixels differ, by up to %4")
                                     .arg(where)
                                     .arg(fromLayer ? "from the layer" : "first")
                                     .arg(differing)
                                     .arg(largest);
            // a part's image has another origin than the box's: an edge (the band's, the trail's,
            // the body's in the mask) that falls exactly between two of the rasteriser's
            // fixed-point steps may round the other way, a level or two on a row or column of it
            // (as between a first paint and the layer); ink left out would differ by far more
            QVERIFY2(largest <= 2 && differing <= 200, qPrintable(what));
            ++compared;
        }
    };
    auto toScale = [&] {
        CanvasStyle style = canvas->canvasStyle();
        style.body = BodyDisplay::ToScale;
        canvas->setCanvasStyle(style);
    };
    m_window->loadScene(presetScene("catenary"));
    m_window->document()->flush();
    canvas->fitScene();
    toScale();
    for (double t : {0.0, 2.0, 5.5}) {
        m_window->playback()->seek(t);
        QCoreApplication::processEvents();
        compare(QStringLiteral("catenary at %1 s").arg(t));
    }
    canvas->zoomBy(3.3);
    compare(QStringLiteral("catenary zoomed in"));
    canvas->setFollowBody(true);
    QCoreApplication::processEvents();
    compare(QStringLiteral("catenary following"));
    canvas->setFollowBody(false);
    QVERIFY(m_window->loadGalleryEntry(QStringLiteral("corner-pivot")));
    m_window->document()->flush();
    canvas->fitScene();
    toScale();
    for (double t : {0.3, 1.0}) {
        m_window->playback()->seek(t);
        QCoreApplication::processEvents();
        compare(QStringLiteral("the corner's pivot at %1 s").arg(t));
    }
    QCOMPARE(compared, 14);
}

QTEST_MAIN(TestPathOverBodies)
#include "test_path_over_bodies.moc"
