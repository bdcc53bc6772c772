// Nothing of the lesson is clipped: bodies, trails and ghosts drawn up to the canvas's top, Fit
// that frames the bodies at the shown time, an edge marker for a body out of view that a click
// frames, the controlled body above the others, a path band without seams and the arrows'
// labels clear of their heads. Offscreen, real widgets; the expected pixels from the colours'
// source-over composition and the exact curves.
#include "canvas/body_painter.h"
#include "canvas/scene_canvas.h"
#include "canvas/vector_painter.h"
#include "document/scene_document.h"
#include "shell/playback.h"
#include "systems/system_parameters.h"
#include "window_fixture.h"

#include <QImage>
#include <QPainter>
#include <QRegularExpression>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

// a world point of a body's own frame (P at the origin, s-hat along x) at pose (x, y, phi)
QPointF onBody(QPointF local, double x, double y, double phi) {
    return {x + std::cos(phi) * local.x() - std::sin(phi) * local.y(),
            y + std::sin(phi) * local.x() + std::cos(phi) * local.y()};
}

// whether a pixel within radius of at is within tolerance of expected on every channel
bool colourNear(const QImage& image, QPointF at, QRgb expected, int radius, int tolerance) {
    for (int x = int(at.x()) - radius; x <= int(at.x()) + radius; ++x)
        for (int y = int(at.y()) - radius; y <= int(at.y()) + radius; ++y) {
            if (!image.rect().contains(x, y))
                continue;
            const QRgb c = image.pixel(x, y);
            if (std::abs(qRed(c) - qRed(expected)) <= tolerance &&
                std::abs(qGreen(c) - qGreen(expected)) <= tolerance &&
                std::abs(qBlue(c) - qBlue(expected)) <= tolerance)
                return true;
        }
    return false;
}

// a colour of alpha a laid over white
QRgb overWhite(const QColor& c, double a) {
    auto mix = [&](int v) { return int(std::lround(a * v + (1 - a) * 255)); };
    return qRgb(mix(c.red()), mix(c.green()), mix(c.blue()));
}

struct DrawnPose {
    double x, y, phi;
    QColor colour;
    const char* name;
};

} // namespace

class TestLessonInView : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_lesson_in_view_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void bodiesTrailsAndGhostsReachTheCanvasTop();
    void fitFramesTheBodiesAtTheShownTime();
    void bodyOutOfViewHasAnEdgeMarkerThatFramesIt();
    void controlledBodyIsDrawnAboveTheOthers();
    void pathBandHasNoSeams();
    void arrowLabelsClearTheArrowheads();

  private:
    void seek(double t) {
        m_window->playback()->seek(t);
        QCoreApplication::processEvents();
    }
    std::vector<DrawnPose> poses() const {
        const MotionSample m = m_window->document()->solution()->at(m_window->playback()->time());
        const CanvasStyle& style = m_window->canvas()->canvasStyle();
        return {{m.x, m.y, m.phi, style.controlled(), "controlled"},
                {m.free.x, m.free.y, m.free.phi, style.free(), "free"},
                {m.vak.x, m.vak.y, m.vak.phi, style.vakonomic(), "vakonomic"}};
    }
    // the view panned by a drag from an empty corner, so that world lands on pixel
    void panTo(QPointF world, QPointF pixel) {
        SceneCanvas* canvas = m_window->canvas();
        const QRectF area = canvas->drawingArea();
        const QPointF body = canvas->toPixel(QPointF(poses()[0].x, poses()[0].y));
        QPointF from;
        double best = -1;
        for (QPointF corner :
             {area.topLeft() + QPointF(8, 8), area.topRight() + QPointF(-8, 8),
              area.bottomLeft() + QPointF(8, -8), area.bottomRight() + QPointF(-8, -8)})
            if (QLineF(corner, body).length() > best) {
                best = QLineF(corner, body).length();
                from = corner;
            }
        const QPointF shift = pixel - canvas->toPixel(world);
        test::dragStroke(canvas, from.toPoint(),
                         {(from + 0.5 * shift).toPoint(), (from + shift).toPoint()},
                         (from + shift).toPoint());
        QCoreApplication::processEvents();
    }
};

void TestLessonInView::bodiesTrailsAndGhostsReachTheCanvasTop() {
    // the time line's band above the drawing area shows the grid: the bodies, their trails and
    // the ghosts are drawn there too, under the read-out, at every line scale
    choosePreset("circle");
    SceneCanvas* canvas = m_window->canvas();
    for (double lineScale : {1.0, 2.0}) {
        CanvasStyle style = canvas->canvasStyle();
        style.body = BodyDisplay::Outline;
        style.lineScale = lineScale;
        canvas->setCanvasStyle(style);
        canvas->fitScene();
        seek(2);
        const double top = canvas->drawingArea().top();
        QVERIFY(top >= 20);
        const Solution& solution = *m_window->document()->solution();
        const QRectF board = bodyShape(solution.scene().system, solution.system()).boundingRect();
        // a place in the band clear of the read-out's text and the scale bar: no dark pixel
        // around it
        const QImage empty = canvas->grab().toImage().convertToFormat(QImage::Format_RGB32);
        double clearX = -1;
        for (double f : {0.5, 0.6, 0.7, 0.4, 0.8}) {
            bool clear = true;
            for (int x = int(f * canvas->width()) - 30; x <= int(f * canvas->width()) + 30; ++x)
                for (int y = 0; y < int(top); ++y) {
                    const QRgb c = empty.pixel(x, y);
                    clear = clear && std::min({qRed(c), qGreen(c), qBlue(c)}) > 150;
                }
            if (clear) {
                clearX = f * canvas->width();
                break;
            }
        }
        QVERIFY(clearX > 0);
        // the board's outline on its right side, far from the path, and its ink
        for (const DrawnPose& pose : poses()) {
            if (std::string(pose.name) == "vakonomic")
                continue; // the same drawing as the free ghost's
            const bool ghost = std::string(pose.name) != "controlled";
            const QPointF rim =
                onBody(QPointF(board.center().x(), board.top()), pose.x, pose.y, pose.phi);
            const QPointF target(clearX, 0.5 * top);
            panTo(rim, target);
            QVERIFY2(QLineF(canvas->toPixel(rim), target).length() < 1.5, pose.name);
            const QImage image = canvas->grab().toImage().convertToFormat(QImage::Format_RGB32);
            const QColor ink = pose.colour.darker(140);
            const QRgb expected =
                ghost ? overWhite(ink, (lineScale > 1 ? 220 : 130) / 255.0) : ink.rgb();
            QVERIFY2(colourNear(image, canvas->toPixel(rim), expected, 2, 40),
                     qPrintable(QStringLiteral("%1 body's outline at line scale %2 not drawn "
                                               "in the time line's band")
                                    .arg(QLatin1String(pose.name))
                                    .arg(lineScale)));
        }
        // the controlled trail, half a second behind the body, in the band
        const MotionSample before = solution.at(1.5);
        const QPointF trail(before.x, before.y);
        panTo(trail, QPointF(clearX, 0.5 * top));
        const QImage image = canvas->grab().toImage().convertToFormat(QImage::Format_RGB32);
        QVERIFY2(
            colourNear(image, canvas->toPixel(trail),
                       canvas->canvasStyle().controlled().darker(150).rgb(), 1, 40),
            qPrintable(
                QStringLiteral("the trail at line scale %1 not drawn in the band").arg(lineScale)));
    }
}

void TestLessonInView::fitFramesTheBodiesAtTheShownTime() {
    SceneCanvas* canvas = m_window->canvas();
    // every body's outline [px] inside the drawing area
    auto check = [&](const QString& what) {
        const Solution& solution = *m_window->document()->solution();
        const QPainterPath shape = bodyShape(solution.scene().system, solution.system());
        for (const DrawnPose& pose : poses()) {
            QTransform place;
            place.translate(pose.x, pose.y);
            place.rotate(pose.phi * 180 / std::numbers::pi);
            const QRectF pixels = (place * canvas->worldToPixel()).map(shape).boundingRect();
            QVERIFY2(canvas->drawingArea().contains(pixels),
                     qPrintable(QStringLiteral("%1: the %2 body at (%3, %4, %5, %6) px, the "
                                               "drawing area (%7, %8, %9, %10)")
                                    .arg(what, QLatin1String(pose.name))
                                    .arg(pixels.left())
                                    .arg(pixels.top())
                                    .arg(pixels.right())
                                    .arg(pixels.bottom())
                                    .arg(canvas->drawingArea().left())
                                    .arg(canvas->drawingArea().top())
                                    .arg(canvas->drawingArea().right())
                                    .arg(canvas->drawingArea().bottom())));
        }
    };
    for (QSize size : {QSize(1280, 800), QSize(1024, 768)}) {
        m_window->resize(size);
        QCoreApplication::processEvents();
        // the line preset's sleigh at the start
        choosePreset("line");
        seek(0);
        canvas->setFocus();
        QTest::keyClick(canvas, Qt::Key_F);
        check(QStringLiteral("line, sleigh, t = 0"));
        // and the disk on it
        Scene disk = m_window->document()->scene();
        disk.system = SystemSpec{SystemKind::Disk, defaultSystemParams(SystemKind::Disk)};
        m_window->loadScene(disk);
        m_window->document()->flush();
        seek(0);
        QTest::keyClick(canvas, Qt::Key_F);
        check(QStringLiteral("line, disk, t = 0"));
        // the sinusoid's ghosts far from the path at t = 6 s
        choosePreset("sinusoid");
        seek(6);
        QTest::keyClick(canvas, Qt::Key_F);
        check(QStringLiteral("sinusoid, t = 6"));
    }
}

void TestLessonInView::bodyOutOfViewHasAnEdgeMarkerThatFramesIt() {
    choosePreset("sinusoid");
    SceneCanvas* canvas = m_window->canvas();
    QTest::qWait(100); // the window's layout settled: no resize refits the view from here on
    canvas->fitScene();
    const Solution& solution = *m_window->document()->solution();
    const double reach = bodyExtent(solution.scene().system, solution.system()) * canvas->scale();
    const QRectF area = canvas->drawingArea();
    // the first time from 2 s on with a body wholly out of view
    auto outOfView = [&](const DrawnPose& pose) {
        return !area.adjusted(-reach - 10, -reach - 10, reach + 10, reach + 10)
                    .contains(canvas->toPixel(QPointF(pose.x, pose.y)));
    };
    double t = 2;
    for (; t < solution.tEnd(); t += 0.25) {
        seek(t);
        const std::vector<DrawnPose> now = poses();
        if (std::any_of(now.begin(), now.end(), outOfView))
            break;
    }
    QVERIFY2(t < solution.tEnd(), "no body leaves the view");
    seek(t);
    int out = 0;
    const QImage image = canvas->grab().toImage().convertToFormat(QImage::Format_RGB32);
    const std::vector<EdgeMarker> markers = canvas->edgeMarkers();
    const QTransform toWorld = canvas->worldToPixel().inverted();
    for (const DrawnPose& pose : poses()) {
        const QPointF at = canvas->toPixel(QPointF(pose.x, pose.y));
        const auto marker = std::find_if(markers.begin(), markers.end(), [&](const EdgeMarker& m) {
            return m.colour == pose.colour;
        });
        if (area.contains(at)) {
            QVERIFY2(marker == markers.end(), pose.name); // in view: no marker
            continue;
        }
        if (!outOfView(pose))
            continue; // at the edge: partly in view
        ++out;
        QVERIFY2(marker != markers.end(), pose.name);
        // on the line from the area's centre toward the body, at the area's edge
        const QPointF d = at - area.center();
        const QPointF u = d / std::hypot(d.x(), d.y());
        QVERIFY2(u.x() * marker->toward.x() + u.y() * marker->toward.y() >
                     std::cos(0.5 * std::numbers::pi / 180),
                 pose.name);
        QVERIFY(area.contains(marker->tip));
        const double edge =
            std::min({marker->tip.x() - area.left(), area.right() - marker->tip.x(),
                      marker->tip.y() - area.top(), area.bottom() - marker->tip.y()});
        QVERIFY2(edge <= 8, qPrintable(QString::number(edge)));
        // its distance: from the tip to P [m], as its text reads it
        const QPointF tip = toWorld.map(marker->tip);
        const double metres = std::hypot(pose.x - tip.x(), pose.y - tip.y());
        const QRegularExpressionMatch number =
            QRegularExpression(QStringLiteral("[0-9]+(\\.[0-9]+)?")).match(marker->text);
        QVERIFY2(number.hasMatch(), qPrintable(marker->text));
        QVERIFY2(std::abs(number.captured(0).toDouble() - metres) <= (metres < 100 ? 0.051 : 0.51),
                 qPrintable(QStringLiteral("%1 for %2 m").arg(marker->text).arg(metres)));
        // drawn in the body's colour
        int inColour = 0;
        const QRect box = marker->box.toAlignedRect() & image.rect();
        for (int x = box.left(); x <= box.right(); ++x)
            for (int y = box.top(); y <= box.bottom(); ++y)
                inColour += colourNear(image, QPointF(x, y), pose.colour.rgb(), 0, 30) ? 1 : 0;
        QVERIFY2(inColour >= 20, qPrintable(QStringLiteral("%1: %2 pixels of its colour")
                                                .arg(QLatin1String(pose.name))
                                                .arg(inColour)));
    }
    QVERIFY(out >= 1);
    // a click on the free body's marker frames it, and the controlled body stays in view
    const auto free = std::find_if(markers.begin(), markers.end(), [&](const EdgeMarker& m) {
        return m.colour == canvas->canvasStyle().free();
    });
    QVERIFY(free != markers.end());
    QTest::mouseClick(canvas, Qt::LeftButton, {}, free->box.center().toPoint());
    QCoreApplication::processEvents();
    const QPainterPath shape = bodyShape(solution.scene().system, solution.system());
    for (const DrawnPose& pose : {poses()[0], poses()[1]}) {
        QTransform place;
        place.translate(pose.x, pose.y);
        place.rotate(pose.phi * 180 / std::numbers::pi);
        QVERIFY2(canvas->drawingArea().contains(
                     (place * canvas->worldToPixel()).map(shape).boundingRect()),
                 pose.name);
    }
    canvas->grab();
    for (const EdgeMarker& m : canvas->edgeMarkers())
        QVERIFY(m.colour != canvas->canvasStyle().free());
}

void TestLessonInView::controlledBodyIsDrawnAboveTheOthers() {
    // at t = 0 the three bodies coincide: inside the board, away from the path, the knife and
    // the centre of mass, the controlled body's fill F of opacity a lies over whatever is under
    // it, so each channel is a F + (1 - a) x for some x in 0 ... 255
    SceneCanvas* canvas = m_window->canvas();
    choosePreset("sinusoid");
    CanvasStyle style = canvas->canvasStyle();
    style.body = BodyDisplay::ToScale;
    canvas->setCanvasStyle(style);
    canvas->fitScene();
    seek(0);
    const QImage image = canvas->grab().toImage().convertToFormat(QImage::Format_RGB32);
    const Solution& solution = *m_window->document()->solution();
    const QRectF board = bodyShape(solution.scene().system, solution.system()).boundingRect();
    const double big = 0.5 * board.width();
    QVERIFY(0.3 * big * canvas->scale() > 12); // the samples well clear of the band and knife
    const QColor fill = style.controlled().lighter(150);
    const double a = style.bodyOpacity;
    const DrawnPose body = poses()[0];
    int checked = 0;
    for (double along : {-0.4, -0.2, 0.2, 0.4})
        for (double across : {-0.3, 0.3}) {
            const QPointF p = canvas->toPixel(onBody(
                QPointF(board.center().x() + along * big, across * big), body.x, body.y, body.phi));
            const QRgb c = image.pixel(p.toPoint());
            for (auto [channel, level] :
                 {std::pair{qRed(c), fill.red()}, std::pair{qGreen(c), fill.green()},
                  std::pair{qBlue(c), fill.blue()}}) {
                QVERIFY2(channel >= a * level - 3 && channel <= a * level + (1 - a) * 255 + 3,
                         qPrintable(QStringLiteral("at (%1, %2) px: %3 not within %4 ... %5")
                                        .arg(p.x())
                                        .arg(p.y())
                                        .arg(channel)
                                        .arg(a * level)
                                        .arg(a * level + (1 - a) * 255)));
            }
            ++checked;
        }
    QCOMPARE(checked, 8);
}

void TestLessonInView::pathBandHasNoSeams() {
    // along the band's centre line (the exact sinusoid y = -sin x) the colour follows the
    // curvature, a level or two from pixel to pixel; a seam where two runs of colour meet is a
    // pixel lighter than both its neighbours three pixels away
    SceneCanvas* canvas = m_window->canvas();
    choosePreset("sinusoid");
    CanvasStyle style = canvas->canvasStyle();
    style.body = BodyDisplay::Marker;
    canvas->setCanvasStyle(style);
    for (double zoom : {1.0, 3.0}) {
        canvas->fitScene();
        canvas->zoomBy(zoom);
        seek(0);
        const QImage image = canvas->grab().toImage().convertToFormat(QImage::Format_RGB32);
        const QRectF area = canvas->drawingArea().adjusted(10, 10, -10, -10);
        const QPointF start = canvas->toPixel(QPointF(0, 0));
        const QPointF end = canvas->toPixel(QPointF(4 * std::numbers::pi, 0));
        std::vector<int> light;
        std::vector<QPoint> at;
        QPoint last(-1, -1);
        for (int k = 0; k <= 200000; ++k) {
            const double x = 4 * std::numbers::pi * k / 200000;
            const QPointF q = canvas->toPixel(QPointF(x, -std::sin(x)));
            const QPoint pixel(int(std::floor(q.x())), int(std::floor(q.y())));
            if (pixel == last)
                continue;
            last = pixel;
            if (!area.contains(q) || QLineF(q, start).length() < 30 ||
                QLineF(q, end).length() < 30) {
                light.push_back(-1);
                at.push_back(pixel);
                continue;
            }
            const QRgb c = image.pixel(pixel);
            light.push_back(qRed(c) + qGreen(c) + qBlue(c));
            at.push_back(pixel);
        }
        int checked = 0, worst = 0;
        QPoint worstAt;
        for (std::size_t i = 3; i + 3 < light.size(); ++i) {
            if (light[i] < 0 || light[i - 3] < 0 || light[i + 3] < 0)
                continue;
            ++checked;
            const int bump = light[i] - std::max(light[i - 3], light[i + 3]);
            if (bump > worst) {
                worst = bump;
                worstAt = at[i];
            }
        }
        QVERIFY2(checked > 300, qPrintable(QString::number(checked)));
        QVERIFY2(worst <= 6, qPrintable(QStringLiteral("zoom %1: a seam %2 levels lighter at "
                                                       "(%3, %4) px")
                                            .arg(zoom)
                                            .arg(worst)
                                            .arg(worstAt.x())
                                            .arg(worstAt.y())));
    }
}

void TestLessonInView::arrowLabelsClearTheArrowheads() {
    // arrows in sixteen directions, alone and from one tail (their labels crowd): no label's box
    // covers any arrowhead, the triangle of length 9 px and half width 0.45 of it at each head
    for (double lineScale : {1.0, 2.0}) {
        for (bool crowded : {false, true}) {
            VectorShapes shapes;
            for (int k = 0; k < 16; ++k) {
                const double angle = 2 * std::numbers::pi * k / 16 + 0.1;
                const QPointF tail =
                    crowded ? QPointF(400, 400) : QPointF(150 + 200 * (k % 4), 150 + 200 * (k / 4));
                const QPointF head = tail + 70 * QPointF(std::cos(angle), std::sin(angle));
                const VectorKind kinds[] = {VectorKind::KnifeVelocity, VectorKind::AxialForce,
                                            VectorKind::LateralReaction, VectorKind::CmVelocity};
                shapes.arrows.push_back({kinds[k % 4], tail, head, 1.0, false});
            }
            QImage image(900, 900, QImage::Format_ARGB32_Premultiplied);
            image.fill(Qt::white);
            std::vector<QRectF> placed;
            {
                QPainter p(&image);
                paintVectorShapes(p, shapes, true, &placed, lineScale);
            }
            QCOMPARE(placed.size(), shapes.arrows.size());
            const double length = 9 * lineScale;
            for (const ArrowShape& a : shapes.arrows) {
                const QPointF d = a.head - a.tail;
                const QPointF u = d / std::hypot(d.x(), d.y()), n(-u.y(), u.x());
                const QPolygonF head{a.head, a.head - length * u + 0.45 * length * n,
                                     a.head - length * u - 0.45 * length * n};
                for (const QRectF& label : placed)
                    QVERIFY2(!QPolygonF(label).intersects(head),
                             qPrintable(QStringLiteral("line scale %1%2: a label at (%3, %4) on "
                                                       "the head at (%5, %6)")
                                            .arg(lineScale)
                                            .arg(crowded ? ", crowded" : "")
                                            .arg(label.x())
                                            .arg(label.y())
                                            .arg(a.head.x())
                                            .arg(a.head.y())));
            }
        }
    }
}

QTEST_MAIN(TestLessonInView)
#include "test_lesson_in_view.moc"
