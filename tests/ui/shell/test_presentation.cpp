// Presentation mode (F11): the docks it hides, the scale and high-contrast palette, keyboard
// control of a demo, the plots and the --presentation screenshot. Offscreen, real widgets.
#include "canvas/canvas_style.h"
#include "canvas/scene_canvas.h"
#include "desktop_entry.h"
#include "lab/gallery.h"
#include "panels/notes_panel.h"
#include "plots/plots_panel.h"
#include "scene/presets.h"
#include "shell/playback.h"
#include "shell/presentation_mode.h"
#include "shell/timeline_bar.h"
#include "window_fixture.h"

#include <QImage>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextLayout>
#include <QToolButton>
#include <QtTest>
#include <qcustomplot.h>

#include <cmath>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestPresentation : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_presentation_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void presentationEntersAndLeaves();
    void presentationPaletteDistinctInGreyscale();
    void presentationScaleIsASetting();
    void presentationKeyboardControl();
    void presentationScalesPlots();
    void presentationScreenshotOption();
    void presentationLegendsWholeAt1024x768();
    void presentationNotesReadableUnscrolled();
};

void TestPresentation::presentationEntersAndLeaves() {
    PresentationMode* p = m_window->presentation();
    const double font = m_window->font().pointSizeF();
    QVERIFY(dock("pathDock")->isVisible());
    QVERIFY(dock("accuracyDock")->isVisible());
    // F11 is the action's shortcut; the toolbar has its button
    QCOMPARE(p->toggleAction()->shortcut(), QKeySequence(Qt::Key_F11));
    QVERIFY(m_window->timeline()->actions().contains(p->toggleAction()));
    QTest::keyClick(m_window.get(), Qt::Key_F11);
    QVERIFY(p->isActive());
    QVERIFY(m_window->windowState() & Qt::WindowFullScreen);
    for (const char* name :
         {"pathDock", "parametersDock", "methodsDock", "sweepDock", "accuracyDock"})
        QVERIFY2(!dock(name)->isVisible(), name);
    QVERIFY(dock("plotsDock")->isVisible());
    QVERIFY(m_window->font().pointSizeF() >= 1.6 * font - 1e-9);
    const CanvasStyle& s = m_window->canvas()->canvasStyle();
    QVERIFY(s.lineScale >= 1.6 && s.highContrast && s.largeTime);
    // Esc leaves and restores the window as it was
    QTest::keyClick(m_window.get(), Qt::Key_Escape);
    QVERIFY(!p->isActive());
    QVERIFY(!(m_window->windowState() & Qt::WindowFullScreen));
    QCOMPARE(m_window->font().pointSizeF(), font);
    QVERIFY(dock("pathDock")->isVisible() || dock("parametersDock")->isVisible());
    QVERIFY(dock("accuracyDock")->isVisible());
    QCOMPARE(m_window->canvas()->canvasStyle().lineScale, 1.0);
    QVERIFY(!m_window->canvas()->canvasStyle().highContrast);
}

void TestPresentation::presentationPaletteDistinctInGreyscale() {
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

void TestPresentation::presentationScaleIsASetting() {
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

void TestPresentation::presentationKeyboardControl() {
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
    // a scene chosen from the Gallery menu: Page Down goes on to the next accepted one after it
    const auto& entries = galleryEntries();
    std::size_t chosen = entries.size() / 2;
    while (entries[chosen].rejected)
        ++chosen;
    QVERIFY(m_window->loadGalleryEntry(QString::fromStdString(entries[chosen].name)));
    std::size_t next = (chosen + 1) % entries.size();
    while (entries[next].rejected)
        next = (next + 1) % entries.size();
    QTest::keyClick(m_window.get(), Qt::Key_PageDown);
    m_window->document()->flush();
    QVERIFY2(m_window->document()->scene() == entries[next].scene, entries[next].name.c_str());
    // play, step and rewind from the keyboard
    QTest::keyClick(m_window.get(), Qt::Key_Space);
    QVERIFY(m_window->playback()->isPlaying());
    QTest::keyClick(m_window.get(), Qt::Key_Period, Qt::ShiftModifier);
    QVERIFY(!m_window->playback()->isPlaying());
    QTest::keyClick(m_window.get(), Qt::Key_Home);
    QCOMPARE(m_window->playback()->time(), 0.0);
    QVERIFY(m_window->presentation()->isActive());
}

void TestPresentation::presentationScalesPlots() {
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

void TestPresentation::presentationScreenshotOption() {
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

void TestPresentation::presentationLegendsWholeAt1024x768() {
    // every plot legend entry's name fits beside its line, with a pinned run and with the
    // perturbed bodies (more entries) as without
    m_window->presentation()->setFullScreen(false);
    m_window->resize(1024, 768);
    Scene plain = presetScene("sinusoid"), pinned = plain, pushed = plain;
    PinnedRun pin{plain.path, plain.system, plain.mode, plain.speed, plain.tEnd};
    pin.system.params["b"] = 2.2;
    pinned.pins.push_back(pin);
    pushed.perturbation = Perturbation{};
    pushed.perturbation->dpsi = 0.2;
    int checked = 0;
    for (const Scene& scene : {plain, pinned, pushed}) {
        // a scene loaded before presentation mode is entered, as in a lecture
        m_window->presentation()->setActive(false);
        m_window->loadScene(scene);
        m_window->document()->flush();
        m_window->presentation()->setActive(true);
        m_window->resize(1024, 768);
        QTest::qWait(50);
        for (QCustomPlot* plot : m_window->plotsPanel()->findChildren<QCustomPlot*>()) {
            if (!plot->isVisible())
                continue;
            plot->replot(QCustomPlot::rpImmediateRefresh);
            for (QCPLegend* legend : plot->findChildren<QCPLegend*>()) {
                for (int i = 0; i < legend->itemCount(); ++i) {
                    auto* item = qobject_cast<QCPPlottableLegendItem*>(legend->item(i));
                    if (!item || !item->visible())
                        continue;
                    const QString name = item->plottable()->name();
                    const double need = QFontMetricsF(item->font()).horizontalAdvance(name);
                    const double room = item->rect().width() - legend->iconSize().width() -
                                        legend->iconTextPadding();
                    QVERIFY2(need <= room + 0.5,
                             qPrintable(QStringLiteral("\"%1\" needs %2 px, has %3 px (legend "
                                                       "%4 px of %5 px, %6 columns, plot %7 px)")
                                            .arg(name)
                                            .arg(need)
                                            .arg(room)
                                            .arg(legend->outerRect().width())
                                            .arg(legend->minimumOuterSizeHint().width())
                                            .arg(legend->columnCount())
                                            .arg(plot->width())));
                    ++checked;
                }
            }
        }
    }
    QVERIFY2(checked >= 20, qPrintable(QString::number(checked)));
}

// every gallery note at 1920x1080 in presentation: shown whole without scrolling, at least 60
// characters a line (the last line of a paragraph aside), no Edit button
void TestPresentation::presentationNotesReadableUnscrolled() {
    m_window->presentation()->setFullScreen(false);
    m_window->resize(1920, 1080);
    m_window->presentation()->setActive(true);
    m_window->resize(1920, 1080);
    int notes = 0;
    for (const GalleryEntry& entry : galleryEntries()) {
        if (entry.rejected || entry.scene.note.empty())
            continue;
        QVERIFY(m_window->loadGalleryEntry(QString::fromStdString(entry.name)));
        m_window->document()->flush();
        QTest::qWait(30);
        QDockWidget* notesDock = dock("notesDock");
        QVERIFY2(notesDock->isVisible(), entry.name.c_str());
        auto* panel = notesDock->findChild<NotesPanel*>();
        QVERIFY(panel);
        auto* edit = panel->findChild<QToolButton*>(QStringLiteral("editNote"));
        QVERIFY(edit);
        QVERIFY2(!edit->isVisible(), "the Edit button is shown while presenting");
        QTextBrowser* view = panel->view();
        QTRY_VERIFY2(view->verticalScrollBar()->maximum() == 0,
                     qPrintable(QStringLiteral("%1 scrolls by %2 px in a %3x%4 view")
                                    .arg(QString::fromStdString(entry.name))
                                    .arg(view->verticalScrollBar()->maximum())
                                    .arg(view->viewport()->width())
                                    .arg(view->viewport()->height())));
        int shortest = 1 << 20;
        for (QTextBlock b = view->document()->begin(); b.isValid(); b = b.next()) {
            QTextLayout* layout = b.layout();
            for (int i = 0; layout && i + 1 < layout->lineCount(); ++i) // not a paragraph's last
                shortest = std::min(shortest, layout->lineAt(i).textLength());
        }
        QVERIFY2(shortest >= 60, qPrintable(QStringLiteral("%1: a line of %2 characters")
                                                .arg(QString::fromStdString(entry.name))
                                                .arg(shortest)));
        ++notes;
    }
    QVERIFY(notes >= 10);
    // leaving presentation mode gives the Edit button back
    m_window->presentation()->setActive(false);
    auto* edit = dock("notesDock")->findChild<QToolButton*>(QStringLiteral("editNote"));
    dock("notesDock")->show();
    dock("notesDock")->raise();
    QTRY_VERIFY(edit->isVisible());
}

QTEST_MAIN(TestPresentation)
#include "test_presentation.moc"
