// GUI tests of the animation frame's economies: what a frame repaints and lays out, and that
// the cached layers draw what direct drawing draws. Offscreen, through the real window.
#include "canvas/body_sprites.h"
#include "canvas/scene_canvas.h"
#include "canvas/vector_painter.h"
#include "document/scene_document.h"
#include "event_counter.h"
#include "gui_test_support.h"
#include "pixel_difference.h"
#include "plots/flat_plot.h"
#include "plots/plots_panel.h"
#include "scene/presets.h"
#include "scene/solution.h"
#include "shell/main_window.h"
#include "shell/playback.h"
#include "shell/timeline_bar.h"

#include <QElapsedTimer>
#include <QLabel>
#include <QPaintEvent>
#include <QPainter>
#include <QScreen>
#include <QtTest>

#include <cmath>
#include <memory>
#include <vector>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

using test::EventCounter;

// the union of the regions of the paint events a widget receives
class PaintRegions : public QObject {
  public:
    QRegion region;
    int count = 0;
    bool eventFilter(QObject*, QEvent* e) override {
        if (e->type() == QEvent::Paint) {
            region += static_cast<QPaintEvent*>(e)->region();
            ++count;
        }
        return false;
    }
};

// what the window shows of the canvas (the offscreen screen grabs the backing store) against
// what a full repaint of the canvas draws now, its cached layers dropped: the same pixels, but for
// the resampling of a turned body image, whose fixed-point steps start where a repainted span
// starts (a level or two on a few pixels; a stale body or a missed trail end differs by far more)
bool showsAFullRepaint(MainWindow& window) {
    SceneCanvas* canvas = window.canvas();
    QPoint at = canvas->mapTo(&window, QPoint(0, 0));
    QImage shown =
        window.screen()
            ->grabWindow(window.winId(), at.x(), at.y(), canvas->width(), canvas->height())
            .toImage()
            .convertToFormat(QImage::Format_RGB32);
    canvas->dropLayers(); // the reference draws the static layer and the whole trails anew
    QImage full = canvas->grab().toImage().convertToFormat(QImage::Format_RGB32);
    if (shown.isNull() || shown.size() != full.size())
        return false;
    int differing = 0;
    for (int y = 0; y < full.height(); ++y)
        for (int x = 0; x < full.width(); ++x) {
            QRgb a = shown.pixel(x, y), b = full.pixel(x, y);
            int d = test::channelDifference(a, b);
            if (d > 4)
                return false;
            differing += d > 0 ? 1 : 0;
        }
    return differing <= full.width() * full.height() / 1000;
}

int area(const QRegion& r) {
    int a = 0;
    for (const QRect& rect : r)
        a += rect.width() * rect.height();
    return a;
}

// the canvas-sized image of bodies drawn either directly or through the sprite cache
QImage drawBody(BodySprites* sprites, const SystemSpec& spec, const BodyPose& pose,
                const BodyLook& look, double scale, bool ghost) {
    QImage image(320, 240, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing, true);
    QTransform world;
    world.translate(160, 120);
    world.scale(scale, -scale);
    DerivedSystem derived = deriveSystem(spec);
    if (sprites) {
        sprites->paint(p, world, scale, spec, derived, pose, QColor(40, 90, 230), ghost, look);
    } else {
        p.setTransform(world);
        paintBody(p, spec, derived, pose, QColor(40, 90, 230), ghost, look);
    }
    return image;
}

// the ink (765 - r - g - b) of each pixel, averaged over its 3 x 3 neighbourhood: what the eye
// sees, blind to the sub-pixel shifts of resampling
std::vector<double> blurredInk(const QImage& image) {
    const int w = image.width(), h = image.height();
    std::vector<double> ink(std::size_t(w * h), 0.0), out(ink.size(), 0.0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            QRgb p = image.pixel(x, y);
            ink[std::size_t(y * w + x)] = 765 - qRed(p) - qGreen(p) - qBlue(p);
        }
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            double sum = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    sum += ink[std::size_t((y + dy) * w + x + dx)];
            out[std::size_t(y * w + x)] = sum / 9;
        }
    return out;
}

struct Difference {
    double total[2] = {0, 0}; // the ink of each image
    double largest = 0;       // the largest difference of blurred ink [of 765]
};

Difference compare(const QImage& a, const QImage& b) {
    std::vector<double> p = blurredInk(a), q = blurredInk(b);
    Difference d;
    for (std::size_t i = 0; i < p.size(); ++i) {
        d.total[0] += p[i];
        d.total[1] += q[i];
        d.largest = std::max(d.largest, std::abs(p[i] - q[i]));
    }
    return d;
}

// the current scene again with every on-canvas vector shown; its canvas
SceneCanvas* showEveryVector(MainWindow& window) {
    Scene s = window.document()->scene();
    for (int i = 0; i < kVectorKinds; ++i)
        (s.vectors.*vectorToggle(VectorKind(i))).shown = true;
    window.loadScene(s);
    window.document()->flush();
    window.canvas()->fitEverything(); // the view these frames were measured at
    return window.canvas();
}

} // namespace

class TestFrame : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase();
    void init();
    void cleanup();

    void timeReadoutFitsWithoutLayingOutTheWindow();
    void bodySpritesDrawWhatDirectDrawingDraws();
    void turnedSpritesReachEveryPixelDirectDrawingInks();
    void framesRepaintWhatMovesAsAFullRepaintWould();
    void followingShiftsTheStaticLayerAsRedrawingWould();
    void fastFramesAfterZoomAndPanRepaintAsAFullRepaintWould();
    void trailLayerKeepsStepAcrossLoopsJumpsAndFollowing();
    void flatPlotsShowWhatQCustomPlotPaints();

  private:
    std::unique_ptr<MainWindow> m_window;
};

void TestFrame::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_frame_tests"));
}

void TestFrame::init() {
    m_window = test::showTestWindow();
    QVERIFY(m_window && m_window->document()->solution());
    // the view these frames were measured at: every body small beside the canvas
    m_window->canvas()->fitEverything();
}

void TestFrame::cleanup() {
    m_window.reset();
}

void TestFrame::timeReadoutFitsWithoutLayingOutTheWindow() {
    QLabel* label = m_window->timeline()->timeLabel();
    Playback* playback = m_window->playback();
    EventCounter layouts(QEvent::LayoutRequest);
    m_window->installEventFilter(&layouts);
    // the window's first layout settles: 200 ms without a layout request (a slow build, such as
    // the sanitizers', takes longer than any one fixed wait)
    QElapsedTimer settling;
    settling.start();
    do {
        layouts.count = 0;
        QTest::qWait(200);
    } while (layouts.count > 0 && settling.elapsed() < 10000);
    QCOMPARE(layouts.count, 0);
    // every time up to the end fits the label, and a new time lays out no part of the window
    for (double t : {0.0, 1.0, 9.99, playback->tEnd()}) {
        playback->seek(t);
        QCoreApplication::processEvents();
        QVERIFY(label->text().contains(QString::number(t, 'f', 2)));
        QVERIFY2(label->fontMetrics().horizontalAdvance(label->text()) <=
                     label->contentsRect().width(),
                 qPrintable(label->text()));
    }
    QCOMPARE(layouts.count, 0);
    // a longer horizon makes room for its longer times
    Scene s = m_window->document()->scene();
    s.speed = 0.1; // ten times slower: the end is past 100 s
    try {
        m_window->loadScene(s);
    } catch (const std::exception& e) {
        QFAIL(e.what());
    }
    m_window->document()->flush();
    playback->seek(111.11);
    QCoreApplication::processEvents();
    QVERIFY(label->text().contains(QStringLiteral("111.11")));
    QVERIFY(label->fontMetrics().horizontalAdvance(label->text()) <= label->contentsRect().width());
}

void TestFrame::bodySpritesDrawWhatDirectDrawingDraws() {
    // every system and display, turned and off the pixel grid: the sprite is the direct drawing
    // resampled, so the two carry the same ink (within 1.5 %) and, seen through a 3 x 3 blur,
    // differ nowhere by more than a fifth of black (a missing knife or a pixel's shift would)
    SystemSpec carriage{SystemKind::Carriage, defaultSystemParams(SystemKind::Carriage)};
    SystemSpec disk{SystemKind::Disk, defaultSystemParams(SystemKind::Disk)};
    SystemSpec sleigh; // a = 0.5, b = 1
    BodySprites sprites;
    int cases = 0;
    for (const SystemSpec& spec : {sleigh, disk, carriage})
        for (BodyDisplay display :
             {BodyDisplay::ToScale, BodyDisplay::Outline, BodyDisplay::Marker})
            for (bool ghost : {false, true})
                for (double phi : {0.0, 0.7, 2.9, -1.2}) {
                    BodyPose pose{0.137, -0.071, phi};
                    BodyLook look{display, 0.8, 1.0};
                    QImage direct = drawBody(nullptr, spec, pose, look, 60, ghost);
                    QImage cached = drawBody(&sprites, spec, pose, look, 60, ghost);
                    Difference d = compare(direct, cached);
                    QVERIFY(d.total[0] > 765 * 50);
                    QVERIFY2(
                        std::abs(d.total[0] - d.total[1]) <= 0.015 * d.total[0],
                        qPrintable(QStringLiteral("ink %1 vs %2").arg(d.total[0]).arg(d.total[1])));
                    QVERIFY2(d.largest <= 0.2 * 765, qPrintable(QString::number(d.largest)));
                    ++cases;
                }
    QCOMPARE(cases, 72);
    // zoomed far in, a body larger than any sprite is drawn directly: the very same pixels
    BodyPose pose{0.01, 0.02, 0.3};
    QImage direct = drawBody(nullptr, sleigh, pose, {}, 2000, false);
    QImage cached = drawBody(&sprites, sleigh, pose, {}, 2000, false);
    QCOMPARE(cached, direct);
}

namespace {

// the box of the pixels with ink over 8 of 765 (white is none)
QRect inkedBox(const QImage& image) {
    QRect box;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QRgb p = image.pixel(x, y);
            if (765 - qRed(p) - qGreen(p) - qBlue(p) > 8)
                box = box.united(QRect(x, y, 1, 1));
        }
    return box;
}

QImage drawBodyAt(BodySprites* sprites, const SystemSpec& spec, const BodyPose& pose,
                  const BodyLook& look, double dpr) {
    QImage image(int(400 * dpr), int(300 * dpr), QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(dpr);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing, true);
    QTransform world;
    world.translate(200, 150);
    world.scale(70, -70);
    const DerivedSystem derived = deriveSystem(spec);
    if (sprites) {
        sprites->paint(p, world, 70, spec, derived, pose, QColor(40, 90, 230), false, look);
    } else {
        p.setTransform(world);
        paintBody(p, spec, derived, pose, QColor(40, 90, 230), false, look);
    }
    return image;
}

} // namespace

void TestFrame::turnedSpritesReachEveryPixelDirectDrawingInks() {
    // a turned sprite resamples only the columns its body's box crosses: at every heading, with
    // wide pens and at device pixel ratio 2, its ink reaches as far as direct drawing's on each
    // side (within the pixel the smooth turn may spread or lose)
    SystemSpec carriage{SystemKind::Carriage, defaultSystemParams(SystemKind::Carriage)};
    SystemSpec disk{SystemKind::Disk, defaultSystemParams(SystemKind::Disk)};
    SystemSpec sleigh;
    SystemSpec backwards; // the centre of mass behind the knife
    backwards.params["a"] = -0.8;
    BodySprites sprites;
    int cases = 0;
    for (const SystemSpec& spec : {sleigh, backwards, disk, carriage})
        for (BodyDisplay display : {BodyDisplay::ToScale, BodyDisplay::Outline})
            for (double lineScale : {1.0, 2.5})
                for (double dpr : {1.0, 2.0})
                    for (int step = 0; step < 24; ++step) {
                        const BodyPose pose{0.0123, -0.0456, -M_PI + step * M_PI / 12 + 0.01};
                        const BodyLook look{display, 0.8, lineScale};
                        const QRect direct = inkedBox(drawBodyAt(nullptr, spec, pose, look, dpr));
                        const QRect turned = inkedBox(drawBodyAt(&sprites, spec, pose, look, dpr));
                        QVERIFY(std::max(direct.width(), direct.height()) > 20 * dpr);
                        const QMargins apart(
                            direct.left() - turned.left(), direct.top() - turned.top(),
                            turned.right() - direct.right(), turned.bottom() - direct.bottom());
                        QVERIFY2(apart.left() >= -1 && apart.top() >= -1 && apart.right() >= -1 &&
                                     apart.bottom() >= -1 && apart.left() <= 1 &&
                                     apart.top() <= 1 && apart.right() <= 1 && apart.bottom() <= 1,
                                 qPrintable(QStringLiteral("system %1 heading %2 dpr %3: "
                                                           "direct %4,%5 %6x%7, turned %8,%9 "
                                                           "%10x%11")
                                                .arg(int(spec.kind))
                                                .arg(pose.phi)
                                                .arg(dpr)
                                                .arg(direct.x())
                                                .arg(direct.y())
                                                .arg(direct.width())
                                                .arg(direct.height())
                                                .arg(turned.x())
                                                .arg(turned.y())
                                                .arg(turned.width())
                                                .arg(turned.height())));
                        ++cases;
                    }
    QCOMPARE(cases, 768);
}

void TestFrame::framesRepaintWhatMovesAsAFullRepaintWould() {
    Scene s = m_window->document()->scene();
    s.vectors.knifeVelocity.shown = s.vectors.lateralReaction.shown = true;
    s.vectors.controlCouple.shown = true;
    m_window->loadScene(s);
    SceneCanvas* canvas = m_window->canvas();
    canvas->fitEverything();
    Playback* playback = m_window->playback();
    playback->seek(1.0);
    QCoreApplication::processEvents();
    QVERIFY(showsAFullRepaint(*m_window));
    PaintRegions painted;
    canvas->installEventFilter(&painted);
    // playing: each frame repaints the bodies, their arrows, the trails' new ends and the time
    // read-out, and the window then shows what a full repaint draws
    const int whole = canvas->width() * canvas->height();
    for (int frame = 0; frame < 40; ++frame) {
        painted.region = {};
        playback->advance(1.0 / 60);
        QCoreApplication::processEvents();
        QCOMPARE(painted.region.boundingRect().intersected(canvas->rect()).isEmpty(), false);
        QVERIFY2(area(painted.region) < whole / 3,
                 qPrintable(QStringLiteral("frame %1: %2 of %3 px")
                                .arg(frame)
                                .arg(area(painted.region))
                                .arg(whole)));
    }
    QVERIFY(painted.count >= 40);
    QVERIFY(showsAFullRepaint(*m_window));
    // a jump forward along a straight line: the bodies leave their old places, which are
    // repainted too
    m_window->loadScene(presetScene("line"));
    m_window->canvas()->fitEverything();
    playback->seek(0.5);
    QCoreApplication::processEvents();
    QVERIFY(showsAFullRepaint(*m_window));
    painted.region = {};
    playback->seek(2.0);
    QCoreApplication::processEvents();
    QVERIFY(area(painted.region) < whole / 3);
    QVERIFY(showsAFullRepaint(*m_window));
    // back in time the trails shrink: the whole canvas
    painted.region = {};
    playback->seek(0.5);
    QCoreApplication::processEvents();
    QCOMPARE(painted.region.boundingRect(), canvas->rect());
    QVERIFY(showsAFullRepaint(*m_window));
    // following the body moves the view by whole pixels: Qt scrolls the drawing area, and a
    // frame repaints what that uncovers and what moves
    canvas->setFollowBody(true);
    QCoreApplication::processEvents();
    for (int frame = 0; frame < 20; ++frame) {
        painted.region = {};
        playback->advance(1.0 / 60);
        QCoreApplication::processEvents();
        QVERIFY(area(painted.region) < whole / 3);
    }
    QVERIFY(showsAFullRepaint(*m_window));
}

void TestFrame::followingShiftsTheStaticLayerAsRedrawingWould() {
    SceneCanvas* canvas = m_window->canvas();
    Playback* playback = m_window->playback();
    playback->seek(2.0);
    canvas->setFollowBody(true);
    QCoreApplication::processEvents();
    PaintRegions painted;
    canvas->installEventFilter(&painted);
    int scrolled = 0; // frames that repainted only part of the canvas
    for (int frame = 0; frame < 90; ++frame) {
        painted.region = {};
        playback->advance(1.0 / 30); // three seconds: the view moves by many pixels
        QCoreApplication::processEvents();
        scrolled += area(painted.region) < canvas->width() * canvas->height() / 2 ? 1 : 0;
        // the body stays in the middle (to the pixel grid)
        MotionSample m = m_window->document()->solution()->at(playback->time());
        QPointF p = canvas->toPixel({m.x, m.y});
        QVERIFY(std::abs(p.x() - canvas->width() / 2.0) <= 0.5 + 1e-9);
        QVERIFY(std::abs(p.y() - canvas->height() / 2.0) <= 0.5 + 1e-9);
    }
    // the world layer is drawn again only when the view has moved past its margin
    QVERIFY2(scrolled >= 80, qPrintable(QString::number(scrolled)));
    QVERIFY(showsAFullRepaint(*m_window));
    // the shifted layer is what drawing the grid, the path and the legend at this view draws
    QImage following = canvas->grab().toImage();
    canvas->setFollowBody(false); // the view stays
    QImage drawn = canvas->grab().toImage();
    // the same pixels, but for the rounding of the legend's antialiased line ends, which the
    // cached legend composites from a translucent image (a few levels on a few pixels)
    QCOMPARE(following.size(), drawn.size());
    int differing = 0, most = 0;
    for (int y = 0; y < drawn.height(); ++y)
        for (int x = 0; x < drawn.width(); ++x) {
            QRgb a = following.pixel(x, y), b = drawn.pixel(x, y);
            int d = test::channelDifference(a, b);
            differing += d > 0 ? 1 : 0;
            most = std::max(most, d);
        }
    QVERIFY2(most <= 12, qPrintable(QString::number(most)));
    QVERIFY2(differing <= drawn.width() * drawn.height() / 1000,
             qPrintable(QString::number(differing)));
}

void TestFrame::fastFramesAfterZoomAndPanRepaintAsAFullRepaintWould() {
    // the third body and every arrow (their scale bars stay put in a corner), at four times the
    // speed: the trails' new ends are stroked where each frame repaints, and the window shows
    // what a full repaint draws, also after a zoom, a pan and a jump back
    SceneCanvas* canvas = showEveryVector(*m_window);
    canvas->setShowVakonomic(true);
    Playback* playback = m_window->playback();
    playback->setSpeedFactor(4);
    playback->seek(0.5);
    QCoreApplication::processEvents();
    PaintRegions painted;
    canvas->installEventFilter(&painted);
    const int whole = canvas->width() * canvas->height();
    auto play = [&](int frames) {
        for (int frame = 0; frame < frames; ++frame) {
            painted.region = {};
            playback->advance(1.0 / 60);
            QCoreApplication::processEvents();
            QVERIFY(area(painted.region) < whole / 2);
        }
        QVERIFY(showsAFullRepaint(*m_window));
    };
    play(60);
    canvas->zoomBy(1.6);
    QCoreApplication::processEvents();
    play(30);
    const QPointF before = canvas->toPixel({0, 0});
    const QPoint from = canvas->drawingArea().center().toPoint();
    QTest::mousePress(canvas, Qt::LeftButton, {}, from);
    QTest::mouseMove(canvas, from + QPoint(-37, 23));
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, from + QPoint(-37, 23));
    QCoreApplication::processEvents();
    QVERIFY(canvas->toPixel({0, 0}) != before); // the view moved
    play(30);
    playback->seek(1.0);
    QCoreApplication::processEvents();
    play(45);
    QVERIFY(painted.count > 0);
}

void TestFrame::trailLayerKeepsStepAcrossLoopsJumpsAndFollowing() {
    // the trails live on a layer that a frame restrokes only where their ends moved; through
    // the end of a loop (the trails start again), jumps, the third body switched off and on
    // and following the body on and off, the window shows what drawing everything anew draws
    SceneCanvas* canvas = showEveryVector(*m_window);
    Playback* playback = m_window->playback();
    playback->setLoop(true);
    playback->setSpeedFactor(4);
    PaintRegions painted;
    canvas->installEventFilter(&painted);
    const int whole = canvas->width() * canvas->height();
    int partial = 0, frames = 0;
    auto play = [&](int count) {
        for (int frame = 0; frame < count; ++frame) {
            painted.region = {};
            playback->advance(1.0 / 60);
            QCoreApplication::processEvents();
            partial += area(painted.region) < whole / 2 ? 1 : 0;
            ++frames;
        }
    };
    playback->seek(playback->tEnd() - 0.5);
    QCoreApplication::processEvents();
    play(20); // past the end: the loop starts again, the trails are short
    QVERIFY(playback->time() < 1.0);
    QVERIFY(showsAFullRepaint(*m_window));
    play(30);
    QVERIFY(showsAFullRepaint(*m_window));
    playback->seek(playback->time() + 1.3); // a jump: the new ends span many vertices
    QCoreApplication::processEvents();
    QVERIFY(showsAFullRepaint(*m_window));
    canvas->setShowVakonomic(false);
    QCoreApplication::processEvents();
    play(10);
    QVERIFY(showsAFullRepaint(*m_window));
    canvas->setShowVakonomic(true);
    QCoreApplication::processEvents();
    play(10);
    QVERIFY(showsAFullRepaint(*m_window));
    canvas->setFollowBody(true);
    QCoreApplication::processEvents();
    play(60);
    QVERIFY(showsAFullRepaint(*m_window));
    canvas->setFollowBody(false);
    QCoreApplication::processEvents();
    play(10);
    QVERIFY(showsAFullRepaint(*m_window));
    // most frames repainted what moves, not the canvas
    QVERIFY2(partial >= frames * 3 / 4,
             qPrintable(QStringLiteral("%1 of %2").arg(partial).arg(frames)));
}

void TestFrame::flatPlotsShowWhatQCustomPlotPaints() {
    // each plot repaints from one image of its buffers composited after a replot: the window
    // shows what QCustomPlot's own paint draws, after the cursor moved over many frames and
    // after a parameter change redrew the curves
    Playback* playback = m_window->playback();
    PlotsPanel* plots = m_window->plotsPanel();
    auto showsQCustomPlotsPaint = [&](int i) {
        auto* plot = dynamic_cast<FlatPlot*>(plots->plot(i));
        if (!plot)
            return false;
        QPoint at = plot->mapTo(m_window.get(), QPoint(0, 0));
        QImage shown =
            m_window->screen()
                ->grabWindow(m_window->winId(), at.x(), at.y(), plot->width(), plot->height())
                .toImage()
                .convertToFormat(QImage::Format_RGB32);
        plot->setFlattened(false);
        QImage own = plot->grab().toImage().convertToFormat(QImage::Format_RGB32);
        plot->setFlattened(true);
        QCoreApplication::processEvents();
        return !own.isNull() && shown == own;
    };
    playback->seek(1.0);
    plots->replotNow();
    QCoreApplication::processEvents();
    for (int i = 0; i < 4; ++i)
        QVERIFY2(showsQCustomPlotsPaint(i), qPrintable(QString::number(i)));
    playback->setSpeedFactor(4);
    for (int frame = 0; frame < 45; ++frame) {
        playback->advance(1.0 / 60);
        QCoreApplication::processEvents();
    }
    for (int i = 0; i < 4; ++i)
        QVERIFY2(showsQCustomPlotsPaint(i), qPrintable(QString::number(i)));
    // new parameters: new curves, replotted from the event loop (queued replots, then the
    // repaint they ask for: on a loaded machine that can take more than one fixed wait)
    QImage before = plots->plot(0)->grab().toImage();
    Scene s = m_window->document()->scene();
    s.system.params["b"] = 1.7 * s.system.params["b"];
    m_window->loadScene(s);
    m_window->document()->flush();
    QTRY_VERIFY_WITH_TIMEOUT(plots->plot(0)->grab().toImage() != before, 5000);
    for (int i = 0; i < 4; ++i)
        QTRY_VERIFY2_WITH_TIMEOUT(showsQCustomPlotsPaint(i), qPrintable(QString::number(i)), 5000);
}

QTEST_MAIN(TestFrame)
#include "test_frame.moc"
