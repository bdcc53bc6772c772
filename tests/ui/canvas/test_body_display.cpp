// How the bodies are drawn (to scale, outline, marker; trail width, opacity): the modes differ on
// the canvas, they are kept in the settings and in presentation mode. Offscreen, real widgets.
#include "canvas/canvas_style.h"
#include "canvas/scene_canvas.h"
#include "shell/body_display_menu.h"
#include "shell/playback.h"
#include "shell/presentation_mode.h"
#include "window_fixture.h"

#include <QImage>
#include <QtTest>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

// pixels of an image that are clearly coloured (not white, grey or black)
int colouredPixels(const QImage& image, const QRect& area) {
    int n = 0;
    for (int y = area.top(); y <= area.bottom(); ++y)
        for (int x = area.left(); x <= area.right(); ++x) {
            QColor c = image.pixelColor(x, y);
            n += c.saturation() > 60 && c.value() > 40 ? 1 : 0;
        }
    return n;
}

} // namespace

class TestBodyDisplay : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_body_display_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void bodyDisplayModesDiffer();
    void bodyDisplaySavedInSettings();
    void bodyDisplayKeptInPresentation();
};

void TestBodyDisplay::bodyDisplayModesDiffer() {
    // the catenary preset's large sleigh: to scale it covers much of the path, a marker does not
    choosePreset("catenary");
    m_window->playback()->seek(2);
    SceneCanvas* canvas = m_window->canvas();
    QRect area = canvas->drawingArea().toRect();
    auto shot = [&](BodyDisplay d) {
        m_window->bodyDisplayMenu()->displayAction(d)->trigger();
        return canvas->canvasStyle().body == d ? colouredPixels(canvas->grab().toImage(), area)
                                               : -1;
    };
    int toScale = shot(BodyDisplay::ToScale);
    int outline = shot(BodyDisplay::Outline);
    int marker = shot(BodyDisplay::Marker);
    QVERIFY(toScale > 0 && outline >= 0 && marker >= 0);
    QVERIFY2(outline < toScale && marker < toScale,
             qPrintable(QStringLiteral("%1 %2 %3").arg(toScale).arg(outline).arg(marker)));
    QVERIFY(marker < toScale / 2);
}

void TestBodyDisplay::bodyDisplaySavedInSettings() {
    {
        MainWindow window(true);
        window.bodyDisplayMenu()->displayAction(BodyDisplay::Outline)->trigger();
        CanvasStyle s = window.bodyDisplayMenu()->chosenStyle();
        s.trailWidth = 4;
        s.bodyOpacity = 0.3;
        emit window.bodyDisplayMenu()->styleChosen(s);
    }
    QSettings settings;
    QCOMPARE(settings.value(QStringLiteral("canvas/bodyDisplay")).toInt(),
             int(BodyDisplay::Outline));
    MainWindow again(true);
    const CanvasStyle& s = again.canvas()->canvasStyle();
    QCOMPARE(s.body, BodyDisplay::Outline);
    QCOMPARE(s.trailWidth, 4.0);
    QCOMPARE(s.bodyOpacity, 0.3);
    // nonsense in the settings file is clamped, not drawn
    settings.setValue(QStringLiteral("canvas/trailWidth"), 1e9);
    settings.setValue(QStringLiteral("canvas/bodyDisplay"), 17);
    CanvasStyle loaded = CanvasStyle::load(settings);
    QCOMPARE(loaded.trailWidth, 12.0);
    QCOMPARE(loaded.body, BodyDisplay::Automatic);
    // the older key held the to-scale default saved at every start, not a choice: it is not read
    settings.remove(QStringLiteral("canvas/bodyDisplay"));
    settings.setValue(QStringLiteral("canvas/body"), int(BodyDisplay::ToScale));
    QCOMPARE(CanvasStyle::load(settings).body, BodyDisplay::Automatic);
}

void TestBodyDisplay::bodyDisplayKeptInPresentation() {
    m_window->bodyDisplayMenu()->displayAction(BodyDisplay::Marker)->trigger();
    m_window->presentation()->setFullScreen(false);
    m_window->presentation()->setActive(true);
    QCOMPARE(m_window->canvas()->canvasStyle().body, BodyDisplay::Marker);
    QVERIFY(m_window->canvas()->canvasStyle().highContrast);
    m_window->bodyDisplayMenu()->displayAction(BodyDisplay::Outline)->trigger();
    QCOMPARE(m_window->canvas()->canvasStyle().body, BodyDisplay::Outline);
    QVERIFY(m_window->canvas()->canvasStyle().highContrast); // still presenting
}

QTEST_MAIN(TestBodyDisplay)
#include "test_body_display.moc"
