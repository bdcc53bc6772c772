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
        // the start marker and the bodies at the start cover the band
        if (!area.contains(q) || QLineF(q, start).length() < 24)
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

QTEST_MAIN(TestPicture)
#include "test_picture.moc"
