// The rough edges a new user meets: loading a known scene is no modification, the drawn path's
// settings and the typed ranges belong to their own path, the Accuracy dock's t is the canvas's,
// and labels, dots and the explanation are set where they can be read.
#include "canvas/scene_canvas.h"
#include "canvas/vector_layer.h"
#include "document/file_dialogs.h"
#include "document/math_text.h"
#include "document/pin_set.h"
#include "event_counter.h"
#include "panels/accuracy_readout.h"
#include "panels/path_panel.h"
#include "shell/animation_dialog.h"
#include "shell/export_report.h"
#include "shell/help_window.h"
#include "shell/introduction_window.h"
#include "shell/playback.h"
#include "widgets/number_field.h"
#include "window_fixture.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QLineEdit>
#include <QMenuBar>
#include <QMouseEvent>
#include <QPushButton>
#include <QRadioButton>
#include <QSet>
#include <QStatusBar>
#include <QStyle>
#include <QStyleOptionComboBox>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTextDocument>
#include <QToolButton>
#include <QUndoStack>

#include <cmath>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

using test::EventCounter;
using test::menuAction;

} // namespace

class TestRoughEdges : public QObject, public test::WindowFixture {
    Q_OBJECT
  private slots:
    void initTestCase() { startSuite("ui_rough_edges_tests"); }
    void init() { openWindowWithOwnSettings("ui_rough_edges_tests"); }
    void cleanup() {
        ExportReport::setOpenUrlHook({});
        closeWindow();
    }

    void presetAndGalleryAreNoModification();
    void presetKeepsUnsavedWorkModifiedAndUndoGivesTheFileBack();
    void newDrawingStartsWithTheDefaultsAfterAGalleryScene();
    void userCornerChoiceCarriesToTheNextDrawing();
    void graphAndParametricKeepTheirOwnRanges();
    void cornerChoicesReadWholeAt1024();
    void accuracyTimeIsTheCanvasTimeEveryFrame();
    void galleryNoteDotsSetInAFaceThatPlacesThem();
    void helpDotsSetInAFaceThatPlacesThem();
    void vectorLabelsApartOnTheSmallCarriage();
    void scaleBarTextsGetTheirWidth();
    void vectorNamesAndScaleBarsGrowWithTheLineScale();
    void helpMenuOpensTheExplanationWithItsDrawing();
    void explanationAtStartUntilDismissed();

  private:
    void drawStroke();
};

void TestRoughEdges::drawStroke() {
    SceneCanvas* canvas = m_window->canvas();
    if (!m_window->pathPanel()->drawButton()->isChecked())
        m_window->pathPanel()->drawButton()->click();
    QVERIFY(canvas->drawMode());
    test::dragStroke(canvas, QPoint(100, 300),
                     {QPoint(200, 300), QPoint(300, 200), QPoint(400, 200)}, QPoint(500, 300));
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().path.kind, PathKind::Polyline);
}

void TestRoughEdges::presetAndGalleryAreNoModification() {
    SceneDocument* doc = m_window->document();
    QVERIFY(!doc->isModified());
    choosePreset("circle");
    QVERIFY(!doc->isModified());
    QVERIFY(!m_window->windowTitle().contains(QLatin1Char('*')));
    QVERIFY(m_window->loadGalleryEntry(QStringLiteral("cusp")));
    doc->flush();
    QCOMPARE(doc->scene().path.xOfU, std::string("u^2"));
    QVERIFY(!doc->isModified());
    QVERIFY(!m_window->windowTitle().contains(QLatin1Char('*')));
    // each is still a step that can be undone
    QCOMPARE(m_window->undoStack()->count(), 2);
    m_window->undoStack()->undo();
    doc->flush();
    QCOMPARE(doc->scene().preset, std::string("circle"));
    // a real change is one
    Scene s = doc->scene();
    s.speed *= 2;
    m_window->editScene(s, QStringLiteral("speed"));
    QVERIFY(doc->isModified());
    QVERIFY(m_window->windowTitle().contains(QLatin1Char('*')));
}

void TestRoughEdges::presetKeepsUnsavedWorkModifiedAndUndoGivesTheFileBack() {
    SceneDocument* doc = m_window->document();
    // a saved file, then a preset: the preset is untitled (Save asks for a name) and clean
    const QString file = m_dir.filePath(QStringLiteral("mine.json"));
    QVERIFY(m_window->saveFile(file));
    QCOMPARE(doc->fileName(), file);
    choosePreset("line");
    QVERIFY(!doc->isModified());
    QVERIFY(doc->fileName().isEmpty());
    m_window->undoStack()->undo();
    doc->flush();
    QCOMPARE(doc->fileName(), file); // the file's scene comes back with its name
    // unsaved work before a preset stays modified: Quit still asks, and undo reaches it
    Scene s = doc->scene();
    s.speed *= 2;
    m_window->editScene(s, QStringLiteral("speed"));
    choosePreset("catenary");
    QVERIFY(doc->isModified());
    m_window->undoStack()->undo();
    doc->flush();
    QCOMPARE(doc->scene().speed, s.speed);
}

void TestRoughEdges::newDrawingStartsWithTheDefaultsAfterAGalleryScene() {
    PathPanel* panel = m_window->pathPanel();
    QVERIFY(m_window->loadGalleryEntry(QStringLiteral("corner-pivot")));
    m_window->document()->flush();
    const PathSource& gallery = m_window->document()->scene().path;
    QCOMPARE(gallery.corners, CornerMode::Pivot);
    QCOMPARE(gallery.smoothing, 10.0);
    // the panel shows the gallery path's own settings...
    QCOMPARE(panel->cornersBox()->currentData().toInt(), int(CornerMode::Pivot));
    QCOMPARE(panel->smoothingSpin()->value(), 10.0);
    // ...and a new drawing starts with the defaults, shown as soon as drawing starts
    panel->drawButton()->click();
    QCOMPARE(panel->cornersBox()->currentData().toInt(), int(CornerMode::Smooth));
    QCOMPARE(panel->smoothingSpin()->value(), 3.0);
    drawStroke();
    const PathSource& drawn = m_window->document()->scene().path;
    QCOMPARE(drawn.corners, CornerMode::Smooth);
    QCOMPARE(drawn.smoothing, 3.0);
    QCOMPARE(drawn.points.size(), std::size_t(5));
}

void TestRoughEdges::userCornerChoiceCarriesToTheNextDrawing() {
    PathPanel* panel = m_window->pathPanel();
    panel->drawButton()->click();
    // chosen while drawing: the next drawing's, not a change of the shown path
    const Scene before = m_window->document()->scene();
    panel->cornersBox()->setCurrentIndex(panel->cornersBox()->findData(int(CornerMode::Pivot)));
    m_window->document()->flush();
    QVERIFY(m_window->document()->scene() == before);
    drawStroke();
    QCOMPARE(m_window->document()->scene().path.corners, CornerMode::Pivot);
    // a gallery scene in between does not change the user's choice
    QVERIFY(m_window->loadGalleryEntry(QStringLiteral("cusp")));
    drawStroke();
    QCOMPARE(m_window->document()->scene().path.corners, CornerMode::Pivot);
    // changed on a drawn path outside draw mode: that path changes, and so does the next one
    panel->drawButton()->click();
    QVERIFY(!m_window->canvas()->drawMode());
    panel->smoothingSpin()->setValue(5.0);
    panel->cornersBox()->setCurrentIndex(panel->cornersBox()->findData(int(CornerMode::Smooth)));
    QTRY_COMPARE(m_window->document()->scene().path.corners, CornerMode::Smooth);
    QCOMPARE(m_window->document()->scene().path.smoothing, 5.0);
    drawStroke();
    QCOMPARE(m_window->document()->scene().path.corners, CornerMode::Smooth);
    QCOMPARE(m_window->document()->scene().path.smoothing, 5.0);
}

void TestRoughEdges::graphAndParametricKeepTheirOwnRanges() {
    PathPanel* panel = m_window->pathPanel();
    QVERIFY(panel->graphButton()->isChecked()); // the sinusoid, x from 0 to 4 pi
    const double graphFrom = panel->fromSpin()->value(), graphTo = panel->toSpin()->value();
    QVERIFY(std::abs(graphTo - 4 * M_PI) < 1e-4);
    QVERIFY(m_window->loadGalleryEntry(QStringLiteral("cusp")));
    m_window->document()->flush();
    QVERIFY(panel->parametricButton()->isChecked());
    QCOMPARE(panel->fromSpin()->value(), -1.0);
    QCOMPARE(panel->toSpin()->value(), 1.0);
    // switching to graph shows the graph's own range, not u's
    panel->graphButton()->click();
    QCOMPARE(panel->fromSpin()->value(), graphFrom);
    QCOMPARE(panel->toSpin()->value(), graphTo);
    panel->toSpin()->setValue(5.0); // typed for the graph
    panel->parametricButton()->click();
    QCOMPARE(panel->fromSpin()->value(), -1.0);
    QCOMPARE(panel->toSpin()->value(), 1.0);
    panel->graphButton()->click();
    QCOMPARE(panel->toSpin()->value(), 5.0);
    // and a graph applied from there uses it
    panel->graphEdit()->setText(QStringLiteral("x^2/4"));
    panel->applyButton()->click();
    m_window->document()->flush();
    QTRY_COMPARE(m_window->document()->scene().path.kind, PathKind::Graph);
    QCOMPARE(m_window->document()->scene().path.to, 5.0);
    QCOMPARE(m_window->document()->scene().path.from, graphFrom);
}

void TestRoughEdges::cornerChoicesReadWholeAt1024() {
    m_window->resize(1024, 768);
    m_window->balanceDocks();
    m_window->pathPanel()->window()->show();
    QTest::qWait(100);
    QComboBox* corners = m_window->pathPanel()->cornersBox();
    QStyleOptionComboBox option;
    option.initFrom(corners);
    option.editable = false;
    const QRect field = corners->style()->subControlRect(QStyle::CC_ComboBox, &option,
                                                         QStyle::SC_ComboBoxEditField, corners);
    for (int i = 0; i < corners->count(); ++i) {
        QVERIFY2(
            corners->fontMetrics().horizontalAdvance(corners->itemText(i)) <= field.width(),
            qPrintable(QStringLiteral("%1 in %2 px").arg(corners->itemText(i)).arg(field.width())));
        // the whole explanation is the item's tooltip
        QVERIFY(corners->itemData(i, Qt::ToolTipRole).toString().size() >
                corners->itemText(i).size());
    }
}

void TestRoughEdges::accuracyTimeIsTheCanvasTimeEveryFrame() {
    choosePreset("circle");
    AccuracyReadout* readout = m_window->accuracyReadout();
    Playback* playback = m_window->playback();
    QTest::qWait(100); // the first layout settles
    EventCounter layouts(QEvent::LayoutRequest);
    readout->installEventFilter(&layouts);
    for (int frame = 0; frame < 40; ++frame) {
        playback->advance(0.016);
        // the same frame's time, without waiting for the event loop
        const QString expected = QStringLiteral("%1 s").arg(m_window->canvas()->time(), 0, 'f', 3);
        QCOMPARE(readout->timeText(), expected);
        // the layout requests a frame posts (and no timer: the numbers wait for the meter)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    }
    QVERIFY(m_window->canvas()->time() > 0.6);
    QCOMPARE(layouts.count, 0); // a new time lays out nothing
}

void TestRoughEdges::vectorLabelsApartOnTheSmallCarriage() {
    // the carriage on the catenary with every arrow: at t = 2 s the heads of v_P and v_C, N and
    // the couple's arc end meet within a label's size
    Scene scene = presetScene("catenary");
    scene.preset.clear();
    scene.system = {
        SystemKind::Carriage,
        {{"R", 0.3}, {"a", 0.4}, {"m", 0.5}, {"I1", 0.02}, {"I2", 0.01}, {"M", 3.0}, {"I", 0.2}}};
    for (int i = 0; i < kVectorKinds; ++i)
        (scene.vectors.*vectorToggle(VectorKind(i))).shown = true;
    m_window->loadScene(scene);
    m_window->playback()->seek(2);
    m_window->canvas()->repaint();
    const std::vector<QRectF>& labels = m_window->canvas()->vectorLayer().labelBoxes();
    QVERIFY2(labels.size() >= 4, qPrintable(QString::number(labels.size()))); // f_s may be short
    for (std::size_t i = 0; i < labels.size(); ++i)
        for (std::size_t j = i + 1; j < labels.size(); ++j)
            QVERIFY2(!labels[i].intersects(labels[j]),
                     qPrintable(QStringLiteral("labels %1 and %2 overlap").arg(i).arg(j)));
}

void TestRoughEdges::scaleBarTextsGetTheirWidth() {
    // the couple's "τ: 0.1 N m = 103°" is wider than the old fixed 104 px column in a
    // presentation's font: the column is as wide as its widest text
    VectorOverlay overlay;
    for (int i = 0; i < kVectorKinds; ++i)
        (overlay.*vectorToggle(VectorKind(i))).shown = true;
    VectorScales scales;
    scales.fill(1.0);
    QFont big;
    big.setPointSizeF(17);
    const int width = scaleBarsTextWidth(big, overlay, scales, 50);
    const QFontMetrics metrics(big);
    const double value = roundValue((M_PI / 2) / 1.0);
    const QString tau = vectorSymbol(VectorKind::ControlCouple) +
                        QStringLiteral(": %1 %2 = %3\u00b0")
                            .arg(value)
                            .arg(vectorUnit(VectorKind::ControlCouple))
                            .arg(std::min(value * 180 / M_PI, 340.0), 0, 'f', 0);
    QVERIFY2(width >= metrics.horizontalAdvance(tau), qPrintable(tau));
    QVERIFY(width > 104);
}

void TestRoughEdges::vectorNamesAndScaleBarsGrowWithTheLineScale() {
    // presentation mode's line scale reaches the arrows' names and the scale bars: at twice the
    // scale their boxes are about twice as tall, and the names still do not overlap
    Scene scene = presetScene("catenary");
    for (int i = 0; i < kVectorKinds; ++i)
        (scene.vectors.*vectorToggle(VectorKind(i))).shown = true;
    m_window->loadScene(scene);
    m_window->resize(1920, 1080);
    QCoreApplication::processEvents();
    m_window->playback()->seek(2);
    SceneCanvas* canvas = m_window->canvas();
    auto measure = [&](double lineScale) {
        CanvasStyle style = canvas->canvasStyle();
        style.lineScale = lineScale;
        canvas->setCanvasStyle(style);
        canvas->repaint();
        const std::vector<QRectF>& labels = canvas->vectorLayer().labelBoxes();
        double tallest = 0;
        for (std::size_t i = 0; i < labels.size(); ++i) {
            tallest = std::max(tallest, labels[i].height());
            for (std::size_t j = i + 1; j < labels.size(); ++j)
                if (labels[i].intersects(labels[j]))
                    return std::pair(-1.0, 0.0);
        }
        // the scale bars stand in the drawing area's corner, never over the legend under it
        const QRectF area = canvas->drawingArea();
        const QRect bars = canvas->vectorLayer().scaleBarsBounds(scene.vectors, area);
        if (!area.contains(bars)) {
            qWarning() << "scale" << lineScale << "area" << area << "bars" << bars;
            return std::pair(0.0, -1.0);
        }
        return std::pair(tallest, double(bars.height()));
    };
    const auto [label1, bars1] = measure(1);
    const auto [label2, bars2] = measure(2);
    QVERIFY2(label1 >= 0 && label2 >= 0, "labels overlap");
    QVERIFY2(bars1 >= 0 && bars2 >= 0, "scale bars outside the drawing area");
    QVERIFY2(label2 > 1.7 * label1, qPrintable(QStringLiteral("%1 -> %2").arg(label1).arg(label2)));
    QVERIFY2(bars2 > 1.8 * bars1, qPrintable(QStringLiteral("%1 -> %2").arg(bars1).arg(bars2)));
    QCOMPARE(canvas->vectorLayer().lineScale(), 2.0);
}

void TestRoughEdges::galleryNoteDotsSetInAFaceThatPlacesThem() {
    // the cusp's note says φ̇ and ṡ, never "phidot" (docs.real_notation checks every note); the
    // dotted Greek letters are set in a face whose dot sits on the letter
    QVERIFY(m_window->loadGalleryEntry(QStringLiteral("cusp")));
    const QString note = m_window->accuracyReadout()->noteText();
    QVERIFY(note.contains(QStringLiteral("\u03c6\u0307")));
    QVERIFY(!note.contains(QStringLiteral("phidot")));
    QVERIFY2(note.contains(QStringLiteral("'DejaVu Serif', serif\">\u03c6\u0307</span>")),
             qPrintable(note));
    QVERIFY(withDottedSymbolFont(QStringLiteral("a \u03c7\u0307 b")) ==
            QStringLiteral(
                "a <span style=\"font-family: 'DejaVu Serif', serif\">\u03c7\u0307</span> b"));
}

void TestRoughEdges::helpDotsSetInAFaceThatPlacesThem() {
    HelpWindow* help = m_window->showHelp(QStringLiteral("physics.md"));
    QTextDocument* doc = help->findChild<QTextBrowser*>()->document();
    QTextCursor found = doc->find(QStringLiteral("\u03c6\u0307"));
    QVERIFY(!found.isNull());
    QVERIFY2(
        found.charFormat().fontFamilies().toStringList().contains(QStringLiteral("DejaVu Serif")),
        qPrintable(found.charFormat().fontFamilies().toStringList().join(u',')));
    // a letter without a dot keeps the document's face
    QTextCursor plain = doc->find(QStringLiteral("Kinetic energy"));
    QVERIFY(!plain.isNull());
    QVERIFY(
        !plain.charFormat().fontFamilies().toStringList().contains(QStringLiteral("DejaVu Serif")));
}

void TestRoughEdges::helpMenuOpensTheExplanationWithItsDrawing() {
    QVERIFY(!m_window->introduction());
    QAction* action = menuAction(m_window->menuBar(), QStringLiteral("What am I looking at?"));
    QVERIFY(action);
    action->trigger();
    IntroductionWindow* intro = m_window->introduction();
    QVERIFY(intro);
    QVERIFY(QTest::qWaitForWindowExposed(intro));
    const QString text = intro->text();
    for (const QString& word :
         {QStringLiteral("\u03a8"), QStringLiteral("\u03c7"), QStringLiteral("\u03bb"),
          QStringLiteral("ghost"), QStringLiteral("vakonomic"), QStringLiteral("leaves the path")})
        QVERIFY2(text.contains(word), qPrintable(word));
    // the screen first, in plain words (the four plots, the path's colours, the green line,
    // how to play), then the physics
    const qsizetype physics = text.indexOf(QStringLiteral("knife"));
    QVERIFY(physics > 0);
    for (const QString& word :
         {QStringLiteral("canvas"), QStringLiteral("four plots"),
          QStringLiteral("red where it "
                         "turns right"),
          QStringLiteral("blue where it turns left"), QStringLiteral("green line"),
          QStringLiteral("Space"), QStringLiteral("To play")}) {
        const qsizetype at = text.indexOf(word);
        QVERIFY2(at >= 0 && at < physics, qPrintable(word));
    }
    // the drawing is painted: a good part of it is ink of several colours
    auto* diagram = intro->findChild<BodyDiagram*>();
    QVERIFY(diagram && diagram->isVisible());
    QVERIFY(diagram->width() >= 320 && diagram->height() >= 170);
    const QImage image = diagram->grab().toImage();
    const QRgb background = image.pixel(1, 1);
    int ink = 0;
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (image.pixel(x, y) != background) {
                ++ink;
                colours.insert(image.pixel(x, y) & 0xf0f0f0);
            }
    QVERIFY2(ink > image.width() * image.height() / 20, qPrintable(QString::number(ink)));
    QVERIFY(colours.size() > 20);
    // the same window comes forward again; a window without user settings never offers it
    action->trigger();
    QCOMPARE(m_window->introduction(), intro);
    QVERIFY(!intro->dismissBox()->isEnabled());
    intro->close();
    QVERIFY(!m_window->offerIntroduction());
    QVERIFY(m_window->introduction() == nullptr || !m_window->introduction()->isVisible());
}

void TestRoughEdges::explanationAtStartUntilDismissed() {
    m_window.reset();
    QSettings().clear(); // a first start
    QVERIFY(IntroductionWindow::dueAtStart(QSettings()));
    {
        MainWindow window(true);
        window.show();
        QVERIFY(window.offerIntroduction());
        QVERIFY(window.introduction() && window.introduction()->isVisible());
        QVERIFY(!window.introduction()->dismissBox()->isChecked());
        window.introduction()->dismissBox()->click(); // "Don't show this at start"
        QVERIFY(!IntroductionWindow::dueAtStart(QSettings()));
    }
    {
        MainWindow window(true);
        window.show();
        QVERIFY(!window.offerIntroduction());
        QVERIFY(!window.introduction());
        // Help still opens it, with the box ticked; unticking brings it back at the next start
        IntroductionWindow* intro = window.showIntroduction();
        QVERIFY(intro->dismissBox()->isChecked());
        intro->dismissBox()->click();
        QVERIFY(IntroductionWindow::dueAtStart(QSettings()));
    }
    QSettings().clear();
}

QTEST_MAIN(TestRoughEdges)
#include "test_rough_edges.moc"
