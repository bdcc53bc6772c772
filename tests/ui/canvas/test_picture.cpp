// What the class sees is what is computed: the canvas draws the path from its dense
// representation, so that zoomed in, every exact point of the circle preset lies on the drawn
// band (docs/architecture.md, ui/: the desktop application, Canvas). Offscreen, real widgets.
#include "canvas/canvas_style.h"
#include "canvas/scene_canvas.h"
#include "document/scene_document.h"
#include "shell/playback.h"
#include "window_fixture.h"

#include <QImage>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestPicture : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_picture_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void zoomedCircleOnItsExactPath();
    void gridLinesAreWholePixelsAtTheirMetres();
};

void TestPicture::zoomedCircleOnItsExactPath() {
    choosePreset("circle");
    SceneCanvas* canvas = m_window->canvas();
    CanvasStyle style = canvas->canvasStyle();
    style.body = BodyDisplay::Marker;
    canvas->setCanvasStyle(style);
    m_window->playback()->seek(0);
    // six times closer than Fit everything (centred off the circle's centre, so that an arc
    // stays in view): a heptagon through the 7 panel ends would be 28 px off
    canvas->fitEverything();
    canvas->zoomBy(6);
    QCoreApplication::processEvents();
    const QImage image = canvas->grab().toImage();
    QCOMPARE(image.width(), canvas->width());
    const QTransform map = canvas->worldToPixel();
    const QRectF area = canvas->drawingArea().adjusted(3, 3, -3, -3);
    const QPointF start = map.map(QPointF(2, 0));
    // a pixel of the pale band: light, not white, not the grid's grey
    auto band = [&](int x, int y) {
        if (!image.rect().contains(x, y))
            return false;
        const QColor c = image.pixelColor(x, y);
        const int lo = std::min({c.red(), c.green(), c.blue()});
        const int hi = std::max({c.red(), c.green(), c.blue()});
        return lo >= 130 && hi <= 248 && !(hi - lo < 6 && std::abs(hi - 232) <= 4);
    };
    // a sixth of the view holds an arc of the circle: sampled densely enough for 100 points on it
    int checked = 0;
    for (int k = 0; k < 8000; ++k) {
        const double u = 2 * std::numbers::pi * k / 8000;
        const QPointF q = map.map(QPointF(2 * std::cos(u), 2 * std::sin(u)));
        // the start marker and the bodies at the start cover the band, and so do the edge
        // markers of the bodies out of this view, drawn over the scene at its edge
        const auto& markers = canvas->edgeMarkers();
        if (!area.contains(q) || QLineF(q, start).length() < 24 ||
            std::any_of(markers.begin(), markers.end(), [&](const EdgeMarker& m) {
                return m.box.adjusted(-2, -2, 2, 2).contains(q);
            }))
            continue;
        ++checked;
        bool near = false;
        for (int x = int(std::floor(q.x() - 2)); x <= int(std::ceil(q.x() + 2)) && !near; ++x)
            for (int y = int(std::floor(q.y() - 2)); y <= int(std::ceil(q.y() + 2)) && !near; ++y)
                near = std::hypot(x + 0.5 - q.x(), y + 0.5 - q.y()) <= 1.5 && band(x, y);
        QVERIFY2(near,
                 qPrintable(QStringLiteral("u = %1 at (%2, %3) px: no path pixel within 1.5 px")
                                .arg(u)
                                .arg(q.x())
                                .arg(q.y())));
    }
    QVERIFY2(checked > 100, qPrintable(QString::number(checked)));
}

void TestPicture::gridLinesAreWholePixelsAtTheirMetres() {
    // every 1, 2 or 5 x 10^k m at least 40 px apart: each line the device pixels whose middle is
    // within half the line's width of the metre mark, in the grid's grey (the axes darker), and
    // white on both sides; at presentation's line scale 2 two pixels wide
    choosePreset("circle");
    SceneCanvas* canvas = m_window->canvas();
    for (double lineScale : {1.0, 2.0}) {
        CanvasStyle style = canvas->canvasStyle();
        style.body = BodyDisplay::Marker;
        style.lineScale = lineScale;
        canvas->setCanvasStyle(style);
        canvas->fitEverything();
        canvas->zoomBy(0.37); // grid lines at a fractional pixel, the path small in the middle
        QCoreApplication::processEvents();
        const QImage image = canvas->grab().toImage().convertToFormat(QImage::Format_RGB32);
        QCOMPARE(image.devicePixelRatio(), 1.0);
        const QTransform map = canvas->worldToPixel();
        const double scale = map.m11();
        double step = std::pow(10.0, std::floor(std::log10(40 / scale)));
        for (double f : {1.0, 2.0, 5.0, 10.0})
            if (f * std::pow(10.0, std::floor(std::log10(40 / scale))) * scale >= 40) {
                step = f * std::pow(10.0, std::floor(std::log10(40 / scale)));
                break;
            }
        const int thick = int(lineScale);
        const QRect area = canvas->drawingArea().toAlignedRect().adjusted(4, 4, -4, -4);
        int lines = 0, fractional = 0;
        for (int vertical = 0; vertical < 2; ++vertical)
            for (int k = -200; k <= 200; ++k) {
                const QPointF mark =
                    map.map(vertical ? QPointF(k * step, 0) : QPointF(0, k * step));
                const double at = vertical ? mark.x() : mark.y();
                const int first = int(std::round(at - 0.5 * thick));
                if (first < (vertical ? area.left() : area.top()) + 2 ||
                    first + thick > (vertical ? area.right() : area.bottom()) - 2)
                    continue;
                ++lines;
                fractional += std::abs(at - std::round(at)) > 0.1 ? 1 : 0;
                const QRgb grey = k == 0 ? qRgb(200, 200, 200) : qRgb(232, 232, 232);
                // along the line, where nothing else is drawn: most samples
                int samples = 0, right = 0;
                const int from = vertical ? area.top() : area.left();
                const int to = vertical ? area.bottom() : area.right();
                for (int along = from; along <= to; along += 7) {
                    auto pixel = [&](int across) {
                        return vertical ? image.pixel(across, along) : image.pixel(along, across);
                    };
                    ++samples;
                    bool ok = pixel(first - 1) == qRgb(255, 255, 255) &&
                              pixel(first + thick) == qRgb(255, 255, 255);
                    for (int i = 0; i < thick; ++i)
                        ok = ok && pixel(first + i) == grey;
                    right += ok ? 1 : 0;
                }
                QVERIFY2(right >= samples * 3 / 4,
                         qPrintable(QStringLiteral("line scale %1, %2 line %3 m at %4 px: %5 of "
                                                   "%6 samples are the grid's pixels")
                                        .arg(lineScale)
                                        .arg(vertical ? "vertical" : "horizontal")
                                        .arg(k * step)
                                        .arg(at)
                                        .arg(right)
                                        .arg(samples)));
            }
        QVERIFY2(
            lines >= 8 && fractional >= 4,
            qPrintable(
                QStringLiteral("%1 lines, %2 at a fractional pixel").arg(lines).arg(fractional)));
    }
}

QTEST_MAIN(TestPicture)
#include "test_picture.moc"
