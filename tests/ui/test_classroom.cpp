// GUI tests of the classroom window: presentation mode, layout, time and view, body display,
// state that does not go stale, files, keyboard, help and plots. Offscreen, real widgets.
#include "canvas/canvas_style.h"
#include "canvas/scene_canvas.h"
#include "desktop_entry.h"
#include "document/file_dialogs.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "lab/gallery.h"
#include "panels/accuracy_readout.h"
#include "panels/methods_panel.h"
#include "panels/parameters_panel.h"
#include "panels/path_panel.h"
#include "plots/plot_context_menu.h"
#include "plots/plot_figures.h"
#include "plots/plots_panel.h"
#include "scene/presets.h"
#include "shell/body_display_menu.h"
#include "shell/elided_label.h"
#include "shell/help_window.h"
#include "shell/main_window.h"
#include "shell/playback.h"
#include "shell/presentation_mode.h"
#include "shell/timeline_bar.h"
#include "shell/window_layout.h"
#include "version.h"

#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QImage>
#include <QLineEdit>
#include <QMenu>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSlider>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextBlock>
#include <QTextBrowser>
#include <QToolBar>
#include <QUndoStack>
#include <QtTest>
#include <qcustomplot.h>

#include <cmath>
#include <memory>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

QDockWidget* dock(MainWindow* w, const char* name) {
    return w->findChild<QDockWidget*>(QString::fromLatin1(name));
}

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

// answers every file dialog with a fixed choice and records what was proposed
struct DialogScript {
    QString answer, filter, proposed, caption;
    int calls = 0;
    void install() {
        setDialogHook([this](const QString& c, const QString& p, const QString&) {
            ++calls;
            caption = c;
            proposed = p;
            return DialogChoice{answer, filter};
        });
    }
    ~DialogScript() { setDialogHook({}); }
};

} // namespace

class TestClassroom : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase();
    void init();
    void cleanup();

    // 1. presentation mode
    void presentationEntersAndLeaves();
    void presentationPaletteDistinctInGreyscale();
    void presentationScaleIsASetting();
    void presentationKeyboardControl();
    void presentationScalesPlots();
    void presentationScreenshotOption();
    // 2. layout
    void firstStartSizedToScreen();
    void noDockScrollsAt1280x800();
    void usableCanvasAt1024x768();
    void legendOutsideDrawingArea();
    void statusBarElidedWithTooltip();
    // 3. time and view
    void newSceneStartsAtZero();
    void homeAndEndKeys();
    void stepIsOneFrameAtCurrentSpeed();
    void fitFramesEverythingThatMoves();
    void followKeepsBodyCentred();
    // 4. body display
    void bodyDisplayModesDiffer();
    void bodyDisplaySavedInSettings();
    void bodyDisplayKeptInPresentation();
    // 5. stale state
    void methodsChartClearedOnSceneChange();
    void messagesBelongToTheirScene();
    void invalidSpinBoxIsMarked();
    // 6. files
    void saveProposesNameAndAddsExtension();
    void dialogsRememberLastFolder();
    void filterExtensionAndStems();
    // 7. keyboard and accessibility
    void redoShortcuts();
    void spaceTogglesPlayInSpinBox();
    void tabLeavesTable();
    void tabReachesParameterSpinBoxes();
    void enterInRangeFieldApplies();
    void accessibleNames();
    // 8. help
    void aboutNamesVersionLicenceCreditsPaper();
    void helpRendersDocsFromResources();
    void f1OpensSectionOfFocus();
    // 9. plots
    void flatSeriesGetsSensibleRange();
    void trajectoryPlotHasEqualAspect();
    void plotContextMenuExports();
    void plotTitleDoesNotOverlapTicks();
    void legendsAreCompact();
    void methodsTitlesAboveAndLegendShort();

  private:
    void choosePreset(const char* name);
    std::unique_ptr<MainWindow> m_window;
    QTemporaryDir m_dir;
};

void TestClassroom::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_classroom_tests"));
    QVERIFY(m_dir.isValid());
}

void TestClassroom::init() {
    QSettings().clear();
    m_window = test::showTestWindow();
    QVERIFY(m_window && m_window->document()->solution());
}

void TestClassroom::cleanup() {
    m_window.reset();
    setDialogHook({});
}

void TestClassroom::choosePreset(const char* name) {
    const auto names = presetNames();
    auto it = std::find(names.begin(), names.end(), std::string(name));
    QVERIFY(it != names.end());
    m_window->choosePresetNumber(int(it - names.begin()));
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().preset, std::string(name));
}

// ---- 1. presentation mode ------------------------------------------------------------------

void TestClassroom::presentationEntersAndLeaves() {
    PresentationMode* p = m_window->presentation();
    const double font = m_window->font().pointSizeF();
    QVERIFY(dock(m_window.get(), "pathDock")->isVisible());
    QVERIFY(dock(m_window.get(), "accuracyDock")->isVisible());
    // F11 is the action's shortcut; the toolbar has its button
    QCOMPARE(p->toggleAction()->shortcut(), QKeySequence(Qt::Key_F11));
    QVERIFY(m_window->timeline()->actions().contains(p->toggleAction()));
    QTest::keyClick(m_window.get(), Qt::Key_F11);
    QVERIFY(p->isActive());
    QVERIFY(m_window->windowState() & Qt::WindowFullScreen);
    for (const char* name : {"pathDock", "parametersDock", "methodsDock", "accuracyDock"})
        QVERIFY2(!dock(m_window.get(), name)->isVisible(), name);
    QVERIFY(dock(m_window.get(), "plotsDock")->isVisible());
    QVERIFY(m_window->font().pointSizeF() >= 1.6 * font - 1e-9);
    const CanvasStyle& s = m_window->canvas()->canvasStyle();
    QVERIFY(s.lineScale >= 1.6 && s.highContrast && s.largeTime);
    // Esc leaves and restores the window as it was
    QTest::keyClick(m_window.get(), Qt::Key_Escape);
    QVERIFY(!p->isActive());
    QVERIFY(!(m_window->windowState() & Qt::WindowFullScreen));
    QCOMPARE(m_window->font().pointSizeF(), font);
    QVERIFY(dock(m_window.get(), "pathDock")->isVisible() ||
            dock(m_window.get(), "parametersDock")->isVisible());
    QVERIFY(dock(m_window.get(), "accuracyDock")->isVisible());
    QCOMPARE(m_window->canvas()->canvasStyle().lineScale, 1.0);
    QVERIFY(!m_window->canvas()->canvasStyle().highContrast);
}

void TestClassroom::presentationPaletteDistinctInGreyscale() {
    CanvasStyle s = CanvasStyle().presentation(PresentationMode::kDefaultScale);
    const QColor colours[] = {s.controlled(), s.vakonomic(), s.path(), s.free()};
    // four grey levels a washed-out projector or a greyscale print still tells apart
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            QVERIFY2(std::abs(luminance(colours[i]) - luminance(colours[j])) >= 0.09,
                     qPrintable(QStringLiteral("%1 vs %2").arg(i).arg(j)));
    // and each is visible on the white canvas
    for (const QColor& c : colours)
        QVERIFY(luminance(c) < 0.6);
    // luminance itself: black 0, white 1, mid grey 0.2159 (sRGB 0.5)
    QCOMPARE(luminance(Qt::black), 0.0);
    QVERIFY(std::abs(luminance(Qt::white) - 1) < 1e-12);
    QVERIFY(std::abs(luminance(QColor::fromRgbF(0.5, 0.5, 0.5)) - 0.2140) < 2e-3);
    // the canvas drawn in presentation mode uses the palette: the trail's dark blue is there
    m_window->presentation()->setFullScreen(false);
    m_window->presentation()->setActive(true);
    m_window->playback()->seek(m_window->playback()->tEnd() / 2);
    QImage image = m_window->canvas()->grab().toImage();
    int controlled = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            QColor c = image.pixelColor(x, y);
            controlled += c.blue() > 60 && c.red() < 30 && c.green() < 50 ? 1 : 0;
        }
    QVERIFY(controlled > 100);
}

void TestClassroom::presentationScaleIsASetting() {
    QCOMPARE(m_window->presentation()->scale(), PresentationMode::kDefaultScale);
    m_window->presentation()->setScale(2.0);
    QCOMPARE(QSettings().value(QStringLiteral("presentation/scale")).toDouble(), 2.0);
    m_window->presentation()->setFullScreen(false);
    m_window->presentation()->setActive(true);
    QCOMPARE(m_window->canvas()->canvasStyle().lineScale, 2.0);
    // a second window reads the setting; nonsense is clamped
    auto other = std::make_unique<MainWindow>(false);
    QCOMPARE(other->presentation()->scale(), 2.0);
    other->presentation()->setScale(50);
    QCOMPARE(other->presentation()->scale(), 3.0);
    other->presentation()->setScale(NAN);
    QCOMPARE(other->presentation()->scale(), 3.0);
}

void TestClassroom::presentationKeyboardControl() {
    m_window->presentation()->setFullScreen(false);
    m_window->presentation()->setActive(true);
    const auto names = presetNames();
    for (int i = 0; i < 4 && i < int(names.size()); ++i) {
        QTest::keyClick(m_window.get(), Qt::Key(Qt::Key_1 + i));
        m_window->document()->flush();
        QCOMPARE(m_window->document()->scene().preset, names[std::size_t(i)]);
    }
    // Page Down / Page Up walk through the accepted gallery scenes
    QTest::keyClick(m_window.get(), Qt::Key_PageDown);
    m_window->document()->flush();
    Scene first = m_window->document()->scene();
    QTest::keyClick(m_window.get(), Qt::Key_PageDown);
    m_window->document()->flush();
    QVERIFY(!(m_window->document()->scene() == first));
    QTest::keyClick(m_window.get(), Qt::Key_PageUp);
    m_window->document()->flush();
    QVERIFY(m_window->document()->scene() == first);
    bool inGallery = false;
    for (const GalleryEntry& e : galleryEntries())
        inGallery = inGallery || (!e.rejected && e.scene == first);
    QVERIFY(inGallery);
    // play, step and rewind from the keyboard
    QTest::keyClick(m_window.get(), Qt::Key_Space);
    QVERIFY(m_window->playback()->isPlaying());
    QTest::keyClick(m_window.get(), Qt::Key_Period, Qt::ShiftModifier);
    QVERIFY(!m_window->playback()->isPlaying());
    QTest::keyClick(m_window.get(), Qt::Key_Home);
    QCOMPARE(m_window->playback()->time(), 0.0);
    QVERIFY(m_window->presentation()->isActive());
}

void TestClassroom::presentationScalesPlots() {
    QCustomPlot* plot = m_window->plotsPanel()->plot(0);
    const double pen = plot->graph(0)->pen().widthF();
    const double tick = plot->xAxis->tickLabelFont().pointSizeF();
    m_window->presentation()->setFullScreen(false);
    m_window->presentation()->setActive(true);
    plot = m_window->plotsPanel()->plot(0);
    QVERIFY(plot->graph(0)->pen().widthF() >= 1.6 * pen - 1e-9);
    QVERIFY(plot->xAxis->tickLabelFont().pointSizeF() >= 1.6 * tick - 1e-6);
    QCOMPARE(plot->graph(0)->pen().color(), CanvasStyle().presentation(1.6).controlled());
    m_window->presentation()->setActive(false);
    plot = m_window->plotsPanel()->plot(0);
    QCOMPARE(plot->graph(0)->pen().widthF(), pen);
    QCOMPARE(plot->xAxis->tickLabelFont().pointSizeF(), tick);
}

void TestClassroom::presentationScreenshotOption() {
    QString normal = m_dir.filePath(QStringLiteral("normal.png"));
    QString shown = m_dir.filePath(QStringLiteral("presentation.png"));
    QByteArray n = normal.toUtf8(), s = shown.toUtf8();
    const char* a[] = {"chaplygin-lab", "--screenshot", n.constData(), "--preset",
                       "catenary",      "--size",       "1280x720"};
    const char* b[] = {"chaplygin-lab", "--screenshot", s.constData(), "--preset",
                       "catenary",      "--size",       "1280x720",    "--presentation"};
    QCOMPARE(runScreenshot(7, const_cast<char**>(a)), 0);
    QCOMPARE(runScreenshot(8, const_cast<char**>(b)), 0);
    QImage plain(normal), presenting(shown);
    QCOMPARE(presenting.size(), QSize(1280, 720));
    // no docks on the left in presentation mode: the canvas (white) reaches the window's left
    // edge below the toolbar, where the normal window shows the path dock (grey)
    QColor leftNormal = plain.pixelColor(20, 300), leftPresenting = presenting.pixelColor(20, 300);
    QVERIFY(leftNormal != leftPresenting);
    QVERIFY(leftPresenting.lightness() > 240);
}

// ---- 2. layout -----------------------------------------------------------------------------

void TestClassroom::firstStartSizedToScreen() {
    FirstStart big = firstStartGeometry(QRect(0, 0, 1920, 1080));
    QCOMPARE(big.geometry.size(), QSize(1632, 918));
    QCOMPARE(big.geometry.center(), QRect(0, 0, 1920, 1080).center());
    QVERIFY(!big.maximised);
    FirstStart small = firstStartGeometry(QRect(0, 0, 1280, 800));
    QVERIFY(small.maximised);
    QCOMPARE(small.geometry, QRect(0, 0, 1280, 800));
    // a window with (empty) settings starts sized to its screen, not at a fixed 1280 x 800
    QSettings().clear();
    MainWindow window(true);
    FirstStart expected = firstStartGeometry(window.screen()->availableGeometry());
    if (expected.maximised)
        QVERIFY(window.windowState() & Qt::WindowMaximized);
    else
        QCOMPARE(window.size(), expected.geometry.size());
}

void TestClassroom::noDockScrollsAt1280x800() {
    m_window->resize(1280, 800);
    m_window->balanceDocks();
    QApplication::processEvents();
    for (const char* name : {"pathDock", "parametersDock"}) {
        QDockWidget* d = dock(m_window.get(), name);
        d->raise();
        QApplication::processEvents();
        auto* scroll = qobject_cast<QScrollArea*>(d->widget());
        QVERIFY(scroll);
        QVERIFY2(scroll->verticalScrollBar()->maximum() == 0,
                 qPrintable(QStringLiteral("%1 scrolls by %2 px")
                                .arg(QLatin1String(name))
                                .arg(scroll->verticalScrollBar()->maximum())));
    }
}

void TestClassroom::usableCanvasAt1024x768() {
    m_window->resize(1024, 768);
    m_window->balanceDocks();
    QApplication::processEvents();
    SceneCanvas* canvas = m_window->canvas();
    QVERIFY2(canvas->width() >= 480, qPrintable(QString::number(canvas->width())));
    QVERIFY2(canvas->drawingArea().height() >= 220,
             qPrintable(QString::number(canvas->drawingArea().height())));
}

void TestClassroom::legendOutsideDrawingArea() {
    SceneCanvas* canvas = m_window->canvas();
    canvas->fitScene();
    QRectF area = canvas->drawingArea();
    QVERIFY(area.bottom() < canvas->height() - 40); // the legend has its own strip
    // everything Fit frames lies inside the drawing area, none of it under the legend
    QRectF bounds = canvas->sceneBounds();
    QRectF pixels = QRectF(canvas->toPixel(bounds.topLeft()), canvas->toPixel(bounds.bottomRight()))
                        .normalized();
    QVERIFY(area.adjusted(-1, -1, 1, 1).contains(pixels));
    // L collapses the legend: the drawing area grows to the bottom edge
    canvas->setFocus();
    QTest::keyClick(canvas, Qt::Key_L);
    QVERIFY(!canvas->legendVisible());
    QCOMPARE(canvas->drawingArea().bottom(), double(canvas->height()));
    QTest::keyClick(canvas, Qt::Key_L);
    QVERIFY(canvas->legendVisible());
}

void TestClassroom::statusBarElidedWithTooltip() {
    ElidedLabel* label = m_window->statusLabel();
    QVERIFY(!label->fullText().isEmpty());
    QCOMPARE(label->toolTip(), label->fullText());
    const QString longText = QString(QStringLiteral("model ")).repeated(200);
    label->setFullText(longText);
    QApplication::processEvents();
    QVERIFY(label->text().endsWith(QChar(0x2026)));
    QVERIFY(label->fontMetrics().horizontalAdvance(label->text()) <= label->width());
    QCOMPARE(label->toolTip(), longText);
    // the status bar does not grow with the text
    QVERIFY(m_window->statusBar()->width() <= m_window->width());
}

// ---- 3. time and view ----------------------------------------------------------------------

void TestClassroom::newSceneStartsAtZero() {
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

void TestClassroom::homeAndEndKeys() {
    Playback* playback = m_window->playback();
    playback->seek(1.5);
    QTest::keyClick(m_window.get(), Qt::Key_End);
    QCOMPARE(playback->time(), playback->tEnd());
    QTest::keyClick(m_window.get(), Qt::Key_Home);
    QCOMPARE(playback->time(), 0.0);
}

void TestClassroom::stepIsOneFrameAtCurrentSpeed() {
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

void TestClassroom::fitFramesEverythingThatMoves() {
    // the sinusoid's free ghost runs far from the path: it stays in view over the whole horizon
    SceneCanvas* canvas = m_window->canvas();
    canvas->fitScene();
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

void TestClassroom::followKeepsBodyCentred() {
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

// ---- 4. body display -----------------------------------------------------------------------

void TestClassroom::bodyDisplayModesDiffer() {
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

void TestClassroom::bodyDisplaySavedInSettings() {
    {
        MainWindow window(true);
        window.bodyDisplayMenu()->displayAction(BodyDisplay::Outline)->trigger();
        CanvasStyle s = window.bodyDisplayMenu()->chosenStyle();
        s.trailWidth = 4;
        s.bodyOpacity = 0.3;
        emit window.bodyDisplayMenu()->styleChosen(s);
    }
    QSettings settings;
    QCOMPARE(settings.value(QStringLiteral("canvas/body")).toInt(), int(BodyDisplay::Outline));
    MainWindow again(true);
    const CanvasStyle& s = again.canvas()->canvasStyle();
    QCOMPARE(s.body, BodyDisplay::Outline);
    QCOMPARE(s.trailWidth, 4.0);
    QCOMPARE(s.bodyOpacity, 0.3);
    // nonsense in the settings file is clamped, not drawn
    settings.setValue(QStringLiteral("canvas/trailWidth"), 1e9);
    settings.setValue(QStringLiteral("canvas/body"), 17);
    CanvasStyle loaded = CanvasStyle::load(settings);
    QCOMPARE(loaded.trailWidth, 12.0);
    QCOMPARE(loaded.body, BodyDisplay::ToScale);
}

void TestClassroom::bodyDisplayKeptInPresentation() {
    m_window->bodyDisplayMenu()->displayAction(BodyDisplay::Marker)->trigger();
    m_window->presentation()->setFullScreen(false);
    m_window->presentation()->setActive(true);
    QCOMPARE(m_window->canvas()->canvasStyle().body, BodyDisplay::Marker);
    QVERIFY(m_window->canvas()->canvasStyle().highContrast);
    m_window->bodyDisplayMenu()->displayAction(BodyDisplay::Outline)->trigger();
    QCOMPARE(m_window->canvas()->canvasStyle().body, BodyDisplay::Outline);
    QVERIFY(m_window->canvas()->canvasStyle().highContrast); // still presenting
}

// ---- 5. stale state ------------------------------------------------------------------------

void TestClassroom::methodsChartClearedOnSceneChange() {
    choosePreset("line");
    MethodsPanel* panel = m_window->methodsPanel();
    panel->start();
    panel->waitForFinished();
    QVERIFY(panel->report());
    QVERIFY(panel->plot()->plottableCount() > 0);
    QVERIFY(panel->chosenTable()->rowCount() > 0);
    choosePreset("circle");
    QVERIFY(!panel->report());
    QCOMPARE(panel->plot()->plottableCount(), 0);
    QCOMPARE(panel->chosenTable()->rowCount(), 0);
    QVERIFY(panel->statusText().contains(QStringLiteral("scene changed")));
}

void TestClassroom::messagesBelongToTheirScene() {
    QString refused;
    for (const GalleryEntry& e : galleryEntries())
        if (e.rejected)
            refused = QString::fromStdString(e.name);
    QVERIFY(!refused.isEmpty());
    QVERIFY(!m_window->loadGalleryEntry(refused));
    QVERIFY(!m_window->statusBar()->currentMessage().isEmpty());
    QVERIFY(m_window->accuracyReadout()->noteText().contains(QStringLiteral("Refused")));
    choosePreset("circle");
    QVERIFY(m_window->statusBar()->currentMessage().isEmpty());
    QVERIFY(!m_window->accuracyReadout()->noteText().contains(QStringLiteral("Refused")));
    // a refused parameter's message goes with the next scene too
    QDoubleSpinBox* m = m_window->parametersPanel()->spinBox(QStringLiteral("m"));
    m->setValue(0);
    QVERIFY(!m_window->parametersPanel()->errorText().isEmpty());
    choosePreset("catenary");
    QVERIFY(m_window->parametersPanel()->errorText().isEmpty());
}

void TestClassroom::invalidSpinBoxIsMarked() {
    ParametersPanel* panel = m_window->parametersPanel();
    QDoubleSpinBox* m = panel->spinBox(QStringLiteral("m"));
    QVERIFY(m);
    const double used = m_window->document()->scene().system.params.at("m");
    m->setValue(0); // a massless body is refused
    m_window->document()->flush();
    QVERIFY(!panel->errorText().isEmpty());
    QVERIFY(panel->isMarkedInvalid(QStringLiteral("m")));
    QVERIFY(!m->styleSheet().isEmpty());
    QCOMPARE(m_window->document()->scene().system.params.at("m"), used);
    // a valid value is used and the mark goes
    m->setValue(used + 1);
    m_window->document()->flush();
    QVERIFY(!panel->isMarkedInvalid(QStringLiteral("m")));
    QVERIFY(m->styleSheet().isEmpty());
    QCOMPARE(m_window->document()->scene().system.params.at("m"), used + 1);
}

// ---- 6. files ------------------------------------------------------------------------------

void TestClassroom::saveProposesNameAndAddsExtension() {
    choosePreset("catenary");
    DialogScript dialog;
    dialog.install();
    dialog.answer = m_dir.filePath(QStringLiteral("lecture"));
    dialog.filter = QStringLiteral("Scenes (*.json)");
    QAction* saveAs = nullptr;
    for (QAction* a : m_window->findChildren<QAction*>())
        if (a->text().startsWith(QStringLiteral("Save &As")))
            saveAs = a;
    QVERIFY(saveAs);
    saveAs->trigger();
    QCOMPARE(dialog.calls, 1);
    QVERIFY2(dialog.proposed.endsWith(QStringLiteral("/catenary.json")),
             qPrintable(dialog.proposed));
    QVERIFY(QFile::exists(m_dir.filePath(QStringLiteral("lecture.json"))));
    QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("lecture"))));
    QCOMPARE(m_window->document()->fileName(), m_dir.filePath(QStringLiteral("lecture.json")));
    // the CSV export proposes the scene's (now the file's) name with .csv
    dialog.answer = m_dir.filePath(QStringLiteral("table"));
    dialog.filter = QStringLiteral("CSV (*.csv)");
    QTest::keyClick(m_window.get(), Qt::Key_E, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY2(dialog.proposed.endsWith(QStringLiteral("/lecture.csv")), qPrintable(dialog.proposed));
    QFile csv(m_dir.filePath(QStringLiteral("table.csv")));
    QVERIFY(csv.open(QIODevice::ReadOnly));
    QVERIFY(csv.readLine().startsWith("# Chaplygin Lab"));
}

void TestClassroom::dialogsRememberLastFolder() {
    QTemporaryDir other;
    DialogScript dialog;
    dialog.install();
    dialog.answer = QDir(other.path()).filePath(QStringLiteral("a.json"));
    dialog.filter = QStringLiteral("Scenes (*.json)");
    QString saved = chooseSaveFile(nullptr, QStringLiteral("Save"), QStringLiteral("scene"),
                                   QStringLiteral("x"), QStringLiteral("Scenes (*.json)"));
    QCOMPARE(saved, dialog.answer);
    QCOMPARE(lastFolder(QStringLiteral("scene")), QFileInfo(other.path()).absoluteFilePath());
    // the next save and the open dialog start there; another purpose does not
    chooseSaveFile(nullptr, QStringLiteral("Save"), QStringLiteral("scene"), QStringLiteral("y"),
                   QStringLiteral("Scenes (*.json)"));
    QCOMPARE(dialog.proposed, QDir(QFileInfo(other.path()).absoluteFilePath()).filePath("y.json"));
    chooseOpenFile(nullptr, QStringLiteral("Open"), QStringLiteral("scene"),
                   QStringLiteral("Scenes (*.json)"));
    QCOMPARE(dialog.proposed, QFileInfo(other.path()).absoluteFilePath());
    QVERIFY(lastFolder(QStringLiteral("csv")) != QFileInfo(other.path()).absoluteFilePath());
    // a cancelled dialog changes nothing
    dialog.answer.clear();
    QVERIFY(chooseSaveFile(nullptr, QStringLiteral("Save"), QStringLiteral("csv"),
                           QStringLiteral("z"), QStringLiteral("CSV (*.csv)"))
                .isEmpty());
    QVERIFY(lastFolder(QStringLiteral("csv")) != QFileInfo(other.path()).absoluteFilePath());
}

void TestClassroom::filterExtensionAndStems() {
    const QString scenes = QStringLiteral("Scenes (*.json)");
    QCOMPARE(withFilterExtension(QStringLiteral("/t/lecture"), scenes),
             QStringLiteral("/t/lecture.json"));
    QCOMPARE(withFilterExtension(QStringLiteral("/t/lecture.JSON"), scenes),
             QStringLiteral("/t/lecture.JSON"));
    QCOMPARE(withFilterExtension(QStringLiteral("/t/v1.2"), scenes),
             QStringLiteral("/t/v1.2.json"));
    QCOMPARE(withFilterExtension(QStringLiteral("/t/notes"), QStringLiteral("All files (*)")),
             QStringLiteral("/t/notes"));
    QCOMPARE(
        withFilterExtension(QStringLiteral("/t/p.svg"), QStringLiteral("Images (*.png *.svg)")),
        QStringLiteral("/t/p.svg"));
    QCOMPARE(withFilterExtension(QString(), scenes), QString());
    Scene s = presetScene("sinusoid");
    QCOMPARE(sceneFileStem(s), QStringLiteral("sinusoid"));
    QCOMPARE(sceneFileStem(s, QStringLiteral("/x/my lecture.json")), QStringLiteral("my-lecture"));
    s.preset.clear();
    s.path.kind = PathKind::Graph;
    s.path.y = "-sin(x)/2";
    QCOMPARE(sceneFileStem(s), QStringLiteral("graph-sin-x-2"));
    s.path.kind = PathKind::Polyline;
    QCOMPARE(sceneFileStem(s), QStringLiteral("drawn"));
}

// ---- 7. keyboard and accessibility ---------------------------------------------------------

void TestClassroom::redoShortcuts() {
    QDoubleSpinBox* m = m_window->parametersPanel()->spinBox(QStringLiteral("m"));
    const double before = m->value();
    for (QKeySequence redo :
         {QKeySequence(Qt::CTRL | Qt::Key_Y), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)}) {
        QVERIFY(m_window->redoAction()->shortcuts().contains(redo));
        m->setValue(before + 1);
        m_window->document()->flush();
        QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
        m_window->document()->flush();
        QCOMPARE(m_window->document()->scene().system.params.at("m"), before);
        QTest::keySequence(m_window.get(), redo);
        m_window->document()->flush();
        QCOMPARE(m_window->document()->scene().system.params.at("m"), before + 1);
        QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
        m_window->document()->flush();
    }
}

void TestClassroom::spaceTogglesPlayInSpinBox() {
    m_window->showParametersDock();
    QDoubleSpinBox* m = m_window->parametersPanel()->spinBox(QStringLiteral("m"));
    m->setFocus();
    QApplication::processEvents();
    const QString text = m->text();
    QTest::keyClick(m, Qt::Key_Space);
    QVERIFY(m_window->playback()->isPlaying());
    QCOMPARE(m->text(), text);
    QTest::keyClick(m, Qt::Key_Space);
    QVERIFY(!m_window->playback()->isPlaying());
    // a slider and the speed box too; a text field types the space
    QTest::keyClick(m_window->timeline()->slider(), Qt::Key_Space);
    QVERIFY(m_window->playback()->isPlaying());
    m_window->playback()->pause();
    QLineEdit* edit = m_window->pathPanel()->graphEdit();
    m_window->findChild<QDockWidget*>(QStringLiteral("pathDock"))->raise();
    edit->setFocus();
    edit->setText(QStringLiteral("x"));
    QTest::keyClick(edit, Qt::Key_Space);
    QCOMPARE(edit->text(), QStringLiteral("x "));
    QVERIFY(!m_window->playback()->isPlaying());
}

void TestClassroom::tabLeavesTable() {
    m_window->showMethodsDock();
    QTableWidget* table = m_window->methodsPanel()->chosenTable();
    table->setRowCount(3);
    table->setFocus();
    QApplication::processEvents();
    QVERIFY(table->hasFocus());
    QTest::keyClick(table, Qt::Key_Tab);
    QVERIFY(!table->hasFocus());
    table->setFocus();
    QTest::keyClick(table, Qt::Key_Backtab, Qt::ShiftModifier);
    QVERIFY(!table->hasFocus());
}

void TestClassroom::tabReachesParameterSpinBoxes() {
    m_window->showParametersDock();
    QApplication::processEvents();
    m_window->canvas()->setFocus();
    QSet<QWidget*> reached;
    for (int i = 0; i < 200; ++i) {
        QWidget* f = QApplication::focusWidget();
        QVERIFY(f);
        reached.insert(f);
        QTest::keyClick(f, Qt::Key_Tab);
    }
    for (const QString& name :
         {QStringLiteral("m"), QStringLiteral("a"), QStringLiteral("speed")}) {
        QDoubleSpinBox* spin = m_window->parametersPanel()->spinBox(name);
        QVERIFY(spin);
        QVERIFY2(reached.contains(spin), qPrintable(name));
    }
    QVERIFY(reached.contains(m_window->canvas()));
    QVERIFY(reached.contains(m_window->timeline()->slider()));
}

void TestClassroom::enterInRangeFieldApplies() {
    PathPanel* panel = m_window->pathPanel();
    m_window->findChild<QDockWidget*>(QStringLiteral("pathDock"))->raise();
    panel->graphEdit()->setText(QStringLiteral("0.5*x"));
    QDoubleSpinBox* to = panel->toSpin();
    to->setFocus();
    to->selectAll();
    QTest::keyClicks(to, QStringLiteral("2.5"));
    QTest::keyClick(to, Qt::Key_Return);
    m_window->document()->flush();
    QTRY_COMPARE(m_window->document()->scene().path.to, 2.5);
    QCOMPARE(QString::fromStdString(m_window->document()->scene().path.y), QStringLiteral("0.5*x"));
    QDoubleSpinBox* from = panel->fromSpin();
    from->setFocus();
    from->selectAll();
    QTest::keyClicks(from, QStringLiteral("0.5"));
    QTest::keyClick(from, Qt::Key_Enter);
    m_window->document()->flush();
    QTRY_COMPARE(m_window->document()->scene().path.from, 0.5);
}

void TestClassroom::accessibleNames() {
    QVERIFY(!m_window->canvas()->accessibleName().isEmpty());
    QVERIFY(!m_window->canvas()->accessibleDescription().isEmpty());
    QVERIFY(!m_window->timeline()->accessibleName().isEmpty());
    QVERIFY(!m_window->timeline()->slider()->accessibleName().isEmpty());
    QVERIFY(!m_window->timeline()->timeLabel()->accessibleName().isEmpty());
    // the canvas and the slider are reachable by keyboard
    QVERIFY(m_window->canvas()->focusPolicy() & Qt::TabFocus);
    QVERIFY(m_window->timeline()->slider()->focusPolicy() & Qt::TabFocus);
}

// ---- 8. help -------------------------------------------------------------------------------

void TestClassroom::aboutNamesVersionLicenceCreditsPaper() {
    const QString about = MainWindow::aboutText();
    QVERIFY(about.contains(QStringLiteral(CHAPLYGIN_LAB_VERSION)));
    QVERIFY(QStringLiteral(CHAPLYGIN_LAB_VERSION).contains(QLatin1Char('.')));
    QVERIFY(about.contains(QStringLiteral("Licence")));
    QVERIFY(about.contains(QStringLiteral("Credits")));
    QVERIFY(about.contains(QStringLiteral("Antunes")));
    QVERIFY(about.contains(QStringLiteral("Controlling nonholonomic Chaplygin systems")));
    QVERIFY(about.contains(QString::fromLatin1(qVersion())));
}

void TestClassroom::helpRendersDocsFromResources() {
    HelpWindow* help = m_window->showHelp(QStringLiteral("physics.md"));
    QVERIFY(help->isVisible());
    // the compiled-in document is the repository's docs/physics.md, byte for byte
    QFile compiled(QStringLiteral(":/help/physics.md"));
    QFile source(QStringLiteral(CHAPLYGIN_SOURCE_DIR "/docs/physics.md"));
    QVERIFY(compiled.open(QIODevice::ReadOnly) && source.open(QIODevice::ReadOnly));
    QCOMPARE(compiled.readAll(), source.readAll());
    for (const QString& doc : HelpWindow::documents())
        QVERIFY2(QFile::exists(QStringLiteral(":/help/") + doc), qPrintable(doc));
    // rendered as Markdown: the first line is a level-1 heading without its '#'
    QTextBlock first = help->browser()->document()->begin();
    while (first.isValid() && first.text().isEmpty())
        first = first.next();
    QCOMPARE(first.blockFormat().headingLevel(), 1);
    QVERIFY(!first.text().startsWith(QLatin1Char('#')));
    QVERIFY(help->browser()->toPlainText().contains(QStringLiteral("Antunes")));
    // the pictures are there too: an image of the user guide loads from the resources
    QVERIFY(help->showTopic(QStringLiteral("user-guide.md")));
    QVERIFY(!QImage(QStringLiteral(":/help/images/main-window-sinusoid.png")).isNull());
    QVERIFY(!help->showTopic(QStringLiteral("no-such.md")));
}

void TestClassroom::f1OpensSectionOfFocus() {
    m_window->showParametersDock();
    QDoubleSpinBox* m = m_window->parametersPanel()->spinBox(QStringLiteral("m"));
    m->setFocus();
    QApplication::processEvents();
    QTest::keyClick(m, Qt::Key_F1);
    HelpWindow* help = m_window->findChild<HelpWindow*>();
    QVERIFY(help && help->isVisible());
    QCOMPARE(help->currentDocument(), QStringLiteral("user-guide.md"));
    QTextBlock block = help->browser()->textCursor().block();
    QVERIFY(block.blockFormat().headingLevel() > 0);
    QVERIFY2(block.text().contains(QStringLiteral("parameters")), qPrintable(block.text()));
    // from the canvas: the animation section
    m_window->activateWindow();
    m_window->canvas()->setFocus();
    m_window->showContextHelp();
    QVERIFY(help->browser()->textCursor().block().text().contains(QStringLiteral("Animation")));
}

// ---- 9. plots ------------------------------------------------------------------------------

void TestClassroom::flatSeriesGetsSensibleRange() {
    // a constant 2.5 J with rounding noise: a +-10 % band, not a magnified 1e-10 wiggle
    QCPRange r = paddedRange(2.5, 2.5 + 1e-10);
    QVERIFY(std::abs(r.lower - 2.25) < 1e-9 && std::abs(r.upper - 2.75) < 1e-9);
    QCPRange zero = paddedRange(0, 0);
    QVERIFY(zero.lower < 0 && zero.upper > 0 && zero.size() < 0.01);
    QCPRange normal = paddedRange(0, 10);
    QCOMPARE(normal.lower, -0.5);
    QCOMPARE(normal.upper, 10.5);
    QCPRange bad = paddedRange(NAN, 1);
    QVERIFY(std::isfinite(bad.lower) && std::isfinite(bad.upper));
    // the energy plot of the energy mode: T is constant; the axis hugs it
    QCustomPlot* energy = m_window->plotsPanel()->plot(3);
    const double T = m_window->document()->series().energy.front();
    QCPRange y = energy->graph(0)->valueAxis()->range();
    QVERIFY(y.contains(T));
    QVERIFY(y.lower > 0);
    QVERIFY(y.size() <= 0.5 * T);
}

void TestClassroom::trajectoryPlotHasEqualAspect() {
    QCustomPlot plot;
    drawPlot(plot, PlotKind::Trajectory, m_window->document()->series());
    for (QSize size : {QSize(900, 600), QSize(500, 700)}) {
        plot.resize(size);
        plot.replot();
        QCPAxisRect* rect = plot.axisRect();
        double mx = rect->axis(QCPAxis::atBottom)->range().size() / rect->width();
        double my = rect->axis(QCPAxis::atLeft)->range().size() / rect->height();
        QVERIFY2(std::abs(mx / my - 1) < 1e-9, qPrintable(QString::number(mx / my)));
        // the whole path stays in view
        const PlotSeries& s = m_window->document()->series();
        for (int i = 0; i < s.pathX.size(); ++i) {
            QVERIFY(rect->axis(QCPAxis::atBottom)->range().contains(s.pathX[i]));
            QVERIFY(rect->axis(QCPAxis::atLeft)->range().contains(s.pathY[i]));
        }
    }
}

void TestClassroom::plotContextMenuExports() {
    QCustomPlot* plot = m_window->plotsPanel()->plot(2);
    const QSize shown = plot->size();
    QCOMPARE(plot->contextMenuPolicy(), Qt::CustomContextMenu);
    QMenu* menu = plotExportMenu(plot);
    QVERIFY(menu && !menu->actions().isEmpty());
    DialogScript dialog;
    dialog.install();
    dialog.answer = m_dir.filePath(QStringLiteral("lambda-plot"));
    dialog.filter = QStringLiteral("SVG (*.svg)");
    menu->actions().first()->trigger();
    QVERIFY2(dialog.proposed.endsWith(QStringLiteral("/lambda.png")), qPrintable(dialog.proposed));
    QFile svg(m_dir.filePath(QStringLiteral("lambda-plot.svg")));
    QVERIFY(svg.open(QIODevice::ReadOnly));
    QVERIFY(svg.readAll().contains("<svg"));
    // the plot in the dock keeps its size
    QCOMPARE(plot->size(), shown);
    // a wrong extension is refused with a message naming the file
    try {
        exportPlotFile(*plot, m_dir.filePath(QStringLiteral("x.txt")));
        QFAIL("a .txt plot was written");
    } catch (const std::exception& e) {
        QVERIFY(QString::fromUtf8(e.what()).contains(QStringLiteral("x.txt")));
    }
    QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("x.txt"))));
    // the Methods diagram has the same menu
    QVERIFY(plotExportMenu(m_window->methodsPanel()->plot()));
}

void TestClassroom::plotTitleDoesNotOverlapTicks() {
    // an exported plot: title row above the axis rect, never on its tick labels
    QCustomPlot plot;
    drawPlot(plot, PlotKind::Psi, m_window->document()->series());
    addCaption(plot, QStringLiteral("caption"));
    plot.resize(900, 600);
    plot.replot();
    QCPAxisRect* rect = plot.axisRect();
    auto* caption = qobject_cast<QCPTextElement*>(plot.plotLayout()->element(0, 0));
    QVERIFY(caption);
    // the tick labels of the left axis reach at most the top of the axis rect's outer margin
    QVERIFY(caption->outerRect().bottom() <= rect->outerRect().top() + 1);
    QVERIFY(rect->rect().top() - rect->outerRect().top() >= 0);
}

void TestClassroom::legendsAreCompact() {
    m_window->resize(1280, 800);
    QApplication::processEvents();
    for (int i = 0; i < 4; ++i) {
        QCustomPlot* plot = m_window->plotsPanel()->plot(i);
        plot->replot();
        QCPLegend* legend = nullptr;
        for (QCPLayoutElement* e : plot->plotLayout()->elements(true))
            if (auto* l = qobject_cast<QCPLegend*>(e))
                legend = l;
        QVERIFY(legend);
        QVERIFY(legend->itemCount() <= 3);
        // one short row under the plot: its entries fit the width, it takes little height
        QVERIFY2(legend->minimumOuterSizeHint().width() <= plot->width(),
                 qPrintable(QStringLiteral("%1: %2 of %3")
                                .arg(i)
                                .arg(legend->minimumOuterSizeHint().width())
                                .arg(plot->width())));
        QVERIFY(legend->outerRect().height() < 0.2 * plot->height());
        QVERIFY(!legend->outerRect().intersects(plot->axisRect()->rect()));
        QVERIFY(legend->font().pointSizeF() <= plot->font().pointSizeF());
    }
}

void TestClassroom::methodsTitlesAboveAndLegendShort() {
    choosePreset("line");
    MethodsPanel* panel = m_window->methodsPanel();
    m_window->showMethodsDock();
    panel->start();
    panel->waitForFinished();
    QCustomPlot* plot = panel->plot();
    plot->replot();
    QCOMPARE(plot->axisRectCount(), 2);
    for (QCPAxisRect* rect : plot->axisRects()) {
        // the title is the top axis's label, outside the frame; nothing is inset over the data
        QCPAxis* top = rect->axis(QCPAxis::atTop);
        QVERIFY(top->visible() && !top->label().isEmpty());
        QVERIFY(!top->tickLabels());
        for (int i = 0; i < rect->insetLayout()->elementCount(); ++i)
            QVERIFY(!qobject_cast<QCPTextElement*>(rect->insetLayout()->elementAt(i)));
        // one entry per method and a single one for every chosen star
        int methods = 0;
        for (QCPAbstractPlottable* p : rect->plottables())
            methods += p->name().startsWith(QLatin1String("chosen: ")) ? 0 : 1;
        QCPLegend* legend = nullptr;
        for (QCPLayoutElement* e : plot->plotLayout()->elements(true))
            if (auto* l = qobject_cast<QCPLegend*>(e)) {
                bool mine = false;
                for (int i = 0; i < l->itemCount(); ++i)
                    if (auto* item = qobject_cast<QCPPlottableLegendItem*>(l->item(i)))
                        mine = mine || item->plottable()->keyAxis()->axisRect() == rect;
                if (mine)
                    legend = l;
            }
        QVERIFY(legend);
        QVERIFY2(
            legend->itemCount() <= methods + 1,
            qPrintable(
                QStringLiteral("%1 entries for %2 methods").arg(legend->itemCount()).arg(methods)));
    }
}

QTEST_MAIN(TestClassroom)
#include "test_classroom.moc"
