// GUI tests of the animation frame's economies: what a frame repaints and lays out, and that
// the cached layers draw what direct drawing draws. Offscreen, through the real window.
#include "canvas/body_sprites.h"
#include "canvas/masked_layer.h"
#include "canvas/scene_canvas.h"
#include "canvas/trail_stroke.h"
#include "canvas/vector_painter.h"
#include "document/scene_document.h"
#include "event_counter.h"
#include "gui_test_support.h"
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
            int d = std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                              std::abs(qBlue(a) - qBlue(b))});
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

// a trail-like polyline in pixels: loops that cross themselves, a stop (one point repeated, as
// while the body pivots), a long straight run and steps far below a pixel
QPolygonF loopingLine() {
    QPolygonF line;
    for (int i = 0; i <= 1500; ++i) {
        double u = 0.01 * i;
        line << QPointF(150 + 18 * u + 60 * std::cos(3 * u), 120 + 70 * std::sin(2.2 * u));
        if (i == 700)
            for (int k = 0; k < 5; ++k)
                line << line.last();
    }
    line << QPointF(20, 230);
    for (int i = 1; i <= 50; ++i)
        line << QPointF(20 + 0.002 * i, 230 - 0.003 * i);
    return line;
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
    void framesRepaintWhatMovesAsAFullRepaintWould();
    void followingShiftsTheStaticLayerAsRedrawingWould();
    void trailStrokesWithinAnAreaDrawWhatDrawPolylineDraws();
    void maskedLayerDrawsWhatClipPathsDraw();
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
            int d = std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                              std::abs(qBlue(a) - qBlue(b))});
            differing += d > 0 ? 1 : 0;
            most = std::max(most, d);
        }
    QVERIFY2(most <= 12, qPrintable(QString::number(most)));
    QVERIFY2(differing <= drawn.width() * drawn.height() / 1000,
             qPrintable(QString::number(differing)));
}

void TestFrame::trailStrokesWithinAnAreaDrawWhatDrawPolylineDraws() {
    // Qt's own stroke of the whole polyline is the reference: inside the area the culled,
    // self-dashed stroke inks the same pixels (translucent ink shows a crossing inked twice).
    // The line stays on the image: where it leaves the device Qt's dasher skips ahead by whole
    // patterns only roughly, and its dashes after the return start elsewhere
    const QPolygonF line = loopingLine();
    struct Case {
        Qt::PenStyle style;
        double width;
        bool cosmetic;
        double offset;
    };
    const Case cases[] = {{Qt::SolidLine, 2, true, 0},     {Qt::DashLine, 1.5, true, 0},
                          {Qt::DashDotLine, 1.5, true, 0}, {Qt::DashLine, 3, true, 0},
                          {Qt::DashLine, 2.5, false, 1.7}, {Qt::SolidLine, 4, false, 0}};
    const QRegion areas[] = {
        QRegion(0, 0, 520, 260),                            // everything
        QRegion(300, 40, 40, 50),                           // near the loops' end
        QRegion(120, 60, 30, 120),                          // across the crossings
        QRegion(0, 0, 400, 22) + QRegion(180, 100, 60, 60), // two boxes, as a frame's
        QRegion(10, 200, 30, 40),                           // the stop and the tiny steps
    };
    int compared = 0;
    for (double zoom : {1.0, 2.0}) // 2: a display of device pixel ratio 2
        for (const Case& c : cases)
            for (const QRegion& area : areas) {
                QPen pen(QColor(30, 90, 200, 150), c.width, c.style);
                pen.setCosmetic(c.cosmetic);
                pen.setCapStyle(c.cosmetic ? Qt::RoundCap : Qt::SquareCap);
                pen.setJoinStyle(c.cosmetic ? Qt::RoundJoin : Qt::MiterJoin);
                pen.setDashOffset(c.offset);
                QImage reference(QSize(520, 260) * zoom, QImage::Format_ARGB32_Premultiplied);
                reference.fill(Qt::white);
                QImage culled = reference;
                for (QImage* image : {&reference, &culled}) {
                    QPainter p(image);
                    p.setRenderHint(QPainter::Antialiasing, true);
                    p.scale(zoom, zoom);
                    p.setClipRegion(area);
                    if (image == &reference) {
                        p.setPen(pen);
                        p.drawPolyline(line);
                    } else {
                        strokePolylineWithin(p, line, pen, area);
                    }
                }
                int inked = 0, differing = 0, most = 0;
                for (int y = 0; y < reference.height(); ++y)
                    for (int x = 0; x < reference.width(); ++x) {
                        QRgb a = reference.pixel(x, y), b = culled.pixel(x, y);
                        int d =
                            std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                                      std::abs(qBlue(a) - qBlue(b))});
                        inked += a != qRgb(255, 255, 255) ? 1 : 0;
                        differing += d > 0 ? 1 : 0;
                        most = std::max(most, d);
                    }
                const QString what = QStringLiteral("zoom %1 style %2 width %3 area %4: %5 px "
                                                    "differ, by up to %6, of %7 inked")
                                         .arg(zoom)
                                         .arg(int(c.style))
                                         .arg(c.width)
                                         .arg(area.boundingRect().x())
                                         .arg(differing)
                                         .arg(most)
                                         .arg(inked);
                QVERIFY2(inked > 40, qPrintable(what));
                // the same pixels but for the rasteriser's rounding of a dash end computed
                // in another order (a level on a few pixels)
                QVERIFY2(most <= 2 && differing <= std::max(3, inked / 200), qPrintable(what));
                ++compared;
            }
    QCOMPARE(compared, 60);
}

void TestFrame::maskedLayerDrawsWhatClipPathsDraw() {
    // the path over a body: a layer's pixels and a stroke on them, kept within a turned ellipse
    // and the ring of its outline's pen, against drawing both under a clip path of the areas'
    // union. Away from the areas' edges (1.5 px) the pixels are the same; on the edges the
    // mask's coverage and the clip's antialiasing may differ
    for (double zoom : {1.0, 2.0}) {
        QImage layer(QSize(320, 220) * zoom, QImage::Format_ARGB32_Premultiplied);
        layer.setDevicePixelRatio(zoom);
        layer.fill(Qt::transparent);
        QPolygonF band;
        for (int i = 0; i <= 200; ++i)
            band << QPointF(10 + 1.5 * i, 110 + 60 * std::sin(0.03 * i));
        {
            QPainter l(&layer);
            l.setRenderHint(QPainter::Antialiasing, true);
            QPen pen(QColor(200, 170, 160), 6);
            pen.setCosmetic(true);
            l.setPen(pen);
            l.drawPolyline(band);
            l.setBrush(QColor(40, 40, 40));
            l.drawEllipse(QPointF(160, 100), 4, 4);
        }
        QTransform pose;
        pose.translate(170, 105);
        pose.rotate(27);
        QPainterPath body;
        body.addEllipse(QPointF(0, 0), 60, 35);
        body.moveTo(0, 0);
        body.arcTo(QRectF(-30, -30, 60, 60), 10, 120);
        body = pose.map(body);
        const QPainterPath& shape = body;
        QPainterPathStroker stroker;
        stroker.setWidth(5);
        const QPainterPath ring = stroker.createStroke(body);
        QPolygonF trail;
        for (int i = 0; i <= 120; ++i)
            trail << QPointF(60 + 2 * i, 112 + 55 * std::sin(0.05 * i + 0.3));
        QPen trailPen(QColor(20, 60, 140), 2.5);
        trailPen.setCosmetic(true);
        auto over = [&](QPainter& c) {
            c.setPen(trailPen);
            c.drawPolyline(trail);
        };
        const QRect box = body.boundingRect().united(ring.boundingRect()).toAlignedRect();
        QImage reference(QSize(320, 220) * zoom, QImage::Format_RGB32);
        reference.setDevicePixelRatio(zoom);
        reference.fill(QColor(120, 200, 230)); // the body's fill under the path
        QImage masked = reference;
        {
            QPainter p(&reference);
            p.setRenderHint(QPainter::Antialiasing, true);
            // one clip, the areas' union: under a clip per area the edges of what is drawn
            // where the areas overlap would be inked twice
            p.setClipPath(shape.united(ring));
            p.drawImage(QPointF(0, 0), layer);
            over(p);
        }
        {
            QPainter p(&masked);
            p.setRenderHint(QPainter::Antialiasing, true);
            drawMaskedLayer(p, layer, QPoint(0, 0), box, {&body, &ring}, over);
        }
        // a pixel (in the painter's coordinates) away from every edge: the 8 points 1.5 px
        // around its middle lie on the same side of both areas as the middle
        auto awayFromEdges = [&](QPointF c) {
            for (const QPainterPath* area : {&shape, &ring}) {
                const bool in = area->contains(c);
                for (int k = 0; k < 8; ++k)
                    if (area->contains(c + 1.5 * QPointF(std::cos(k * M_PI / 4),
                                                         std::sin(k * M_PI / 4))) != in)
                        return false;
            }
            return true;
        };
        int inside = 0, edge = 0, edgeDiffering = 0, most = 0;
        for (int y = 0; y < reference.height(); ++y)
            for (int x = 0; x < reference.width(); ++x) {
                const QRgb a = reference.pixel(x, y), b = masked.pixel(x, y);
                const int d =
                    std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                              std::abs(qBlue(a) - qBlue(b))});
                const QPointF c = QPointF(x + 0.5, y + 0.5) / zoom;
                if (awayFromEdges(c)) {
                    QVERIFY2(d <= 2, qPrintable(QStringLiteral("zoom %1: pixel (%2, %3) away from "
                                                               "the edges differs by %4")
                                                    .arg(zoom)
                                                    .arg(x)
                                                    .arg(y)
                                                    .arg(d)));
                    inside += body.contains(c) || ring.contains(c) ? 1 : 0;
                } else {
                    ++edge;
                    edgeDiffering += d > 24 ? 1 : 0;
                    most = std::max(most, d);
                }
            }
        const QString what = QStringLiteral("zoom %1: %2 px inside, %3 on the edges, %4 of them "
                                            "differ by more than 24 levels, at most %5")
                                 .arg(zoom)
                                 .arg(inside)
                                 .arg(edge)
                                 .arg(edgeDiffering)
                                 .arg(most);
        qInfo().noquote() << what;
        QVERIFY2(inside > 2000 * zoom * zoom, qPrintable(what));
        QVERIFY2(edge > 1000 * zoom && edgeDiffering == 0, qPrintable(what));
    }
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
