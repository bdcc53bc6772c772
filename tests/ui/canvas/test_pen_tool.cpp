// The pen on the canvas, driven by synthetic mouse events: reached from the menu, the toolbar
// and keys; a stroke is drawn where the mouse went (its pixels in the pen's colour); the marks
// are held in metres and move with the view's own map on a zoom and a pan; Ctrl+Z with the pen on
// removes the last mark and never a scene edit; E and Delete clear them all; the four colours and
// the arrows; presentation mode; the scene, its solution, summary and link untouched; File > Save
// writes the marks only when asked, and they come back from the file.
#include "canvas/pen_tool.h"
#include "canvas/scene_canvas.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "pen_strokes.h"
#include "scene/scene_json.h"
#include "scene/scene_link.h"
#include "scene/summary_json.h"
#include "shell/main_window.h"
#include "shell/playback.h"
#include "shell/presentation_mode.h"
#include "shell/timeline_bar.h"

#include <QAction>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMenuBar>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <cmath>
#include <memory>

using namespace chaplygin;
using namespace chaplygin::ui;
using test::drag;
using test::near;
using test::sendMove;
using test::straightScene;

namespace {

// the pixels of a horizontal stroke's colour in the column through `centre`, within 12 px of it
int thickness(const QImage& image, QPointF centre, QColor colour) {
    int count = 0;
    for (int dy = -12; dy <= 12; ++dy)
        count += near(image.pixelColor(centre.toPoint() + QPoint(0, dy)), colour, 60);
    return count;
}

} // namespace

class TestPenTool : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase();
    void init();
    void cleanup();

    void reachedFromMenuToolbarAndKeys();
    void aStrokeAppearsWhereItIsDrawn();
    void theMarksFollowZoomAndPan();
    void ctrlZUndoesTheLastMarkAndNoSceneEdit();
    void eAndDeleteClearEveryMark();
    void fourColoursAndArrows();
    void aLongStrokeIsSimplified();
    void drawsInPresentationMode();
    void theSceneAndItsResultAreUnchanged();
    void savedOnlyWhenAskedAndReadBack();
    void marksToBeSavedAreUnsavedChangesUntilSaved();

  private:
    PenTool* startPen();
    // the canvas as painted now
    QImage picture() const { return m_canvas->grab().toImage(); }
    QColor at(const QImage& image, QPointF pixel) const {
        return image.pixelColor(pixel.toPoint());
    }
    // a horizontal stroke at height y [m] from x0 to x1 [m]
    void strokeAt(double y, double x0 = 1.0, double x1 = 3.0);
    std::unique_ptr<MainWindow> m_window;
    SceneCanvas* m_canvas = nullptr;
};

void TestPenTool::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_pen_tests"));
}

void TestPenTool::init() {
    m_window = test::showTestWindow();
    QVERIFY(m_window);
    m_window->document()->loadNow(straightScene());
    m_window->playback()->pause();
    m_window->playback()->seek(0);
    m_canvas = m_window->canvas();
    m_canvas->fitScene();
}

void TestPenTool::cleanup() {
    m_window.reset();
}

PenTool* TestPenTool::startPen() {
    m_canvas->setPenMode(true);
    return m_canvas->penTool();
}

void TestPenTool::strokeAt(double y, double x0, double x1) {
    drag(m_canvas, m_canvas->toPixel({x0, y}).toPoint(), m_canvas->toPixel({x1, y}).toPoint());
}

void TestPenTool::reachedFromMenuToolbarAndKeys() {
    auto* pen = m_window->findChild<QAction*>(QStringLiteral("penAction"));
    QVERIFY(pen && pen->isCheckable());
    QVERIFY(m_window->timeline()->actions().contains(pen));
    QVERIFY(test::inMenuBar(m_window->menuBar(), pen));
    QVERIFY(!m_canvas->penMode());
    QTest::keySequence(m_window.get(), pen->shortcut());
    QVERIFY(m_canvas->penMode());
    QVERIFY(pen->isChecked());
    m_canvas->setFocus();
    QTest::keyClick(m_canvas, Qt::Key_P);
    QVERIFY(!m_canvas->penMode());
    QVERIFY(!pen->isChecked());
    QTest::keyClick(m_canvas, Qt::Key_P);
    QVERIFY(m_canvas->penMode());
    // the other tools end it, and it ends them
    m_canvas->setMeasureMode(true);
    QVERIFY(!m_canvas->penMode());
    pen->trigger();
    QVERIFY(m_canvas->penMode());
    QVERIFY(!m_canvas->measureMode());
    m_canvas->setPlanMode(true);
    QVERIFY(!m_canvas->penMode());
    pen->trigger();
    QVERIFY(!m_canvas->planMode());
    m_canvas->setDrawMode(true);
    QVERIFY(!m_canvas->penMode());
    m_canvas->setDrawMode(false);
    // the pen's menu: arrows, four colours, undo and clear
    for (const char* name : {"penArrowsAction", "penColour0", "penColour1", "penColour2",
                             "penColour3", "penUndoAction", "penClearAction"})
        QVERIFY2(m_window->findChild<QAction*>(QString::fromLatin1(name)), name);
}

void TestPenTool::aStrokeAppearsWhereItIsDrawn() {
    PenTool* pen = startPen();
    const QPointF middle = m_canvas->toPixel({2, 0.8});
    QVERIFY(m_canvas->drawingArea().contains(middle));
    const QColor red = PenTool::colourOf(0);
    QVERIFY(!near(at(picture(), middle), red, 60));
    strokeAt(0.8);
    QCOMPARE(pen->marks().size(), std::size_t(1));
    const AnnotationMark& mark = pen->marks()[0];
    QCOMPARE(mark.kind, MarkKind::Freehand);
    QCOMPARE(mark.colour, 0);
    // held in metres: its ends are the drag's ends through the view's map
    const QPointF first(mark.points.front().first, mark.points.front().second);
    const QPointF last(mark.points.back().first, mark.points.back().second);
    QVERIFY(QLineF(m_canvas->toPixel(first), m_canvas->toPixel({1, 0.8}).toPoint()).length() <
            1e-9);
    QVERIFY(QLineF(m_canvas->toPixel(last), m_canvas->toPixel({3, 0.8}).toPoint()).length() < 1e-9);
    const QImage image = picture();
    QVERIFY2(near(at(image, middle), red), qPrintable(at(image, middle).name()));
    // the stroke is about 4 px wide: 12 px above and below it nothing is red
    for (double dy : {-12.0, 12.0})
        QVERIFY(!near(at(image, middle + QPointF(0, dy)), red, 60));
    // and the scene's pixels are the same away from the stroke
    QVERIFY(!near(at(image, m_canvas->toPixel({2, -0.8})), red, 60));
}

void TestPenTool::theMarksFollowZoomAndPan() {
    PenTool* pen = startPen();
    strokeAt(0.6);
    const auto marks = pen->marks();
    const QTransform before = m_canvas->worldToPixel();
    const QPointF drawnAt = m_canvas->toPixel({2, 0.6});
    const QColor red = PenTool::colourOf(0);
    // zoom in about the centre, then pan with the arrows
    m_canvas->zoomBy(1.25);
    m_canvas->setFocus();
    QTest::keyClick(m_canvas, Qt::Key_Left);
    const QTransform after = m_canvas->worldToPixel();
    QVERIFY(before != after);
    QCOMPARE(pen->marks(), marks); // the metres are kept
    // where the view's map now puts the drawn pixel
    const QPointF moved = after.map(before.inverted().map(drawnAt));
    QVERIFY(QLineF(moved, drawnAt).length() > 20);
    const QImage image = picture();
    QVERIFY2(near(at(image, moved), red), qPrintable(at(image, moved).name()));
    QVERIFY(!near(at(image, drawnAt), red, 60));
    // a pan by the mouse's right button with the pen on moves the marks with the world
    const QTransform beforeDrag = m_canvas->worldToPixel();
    QTest::mousePress(m_canvas, Qt::RightButton, {}, QPoint(200, 300));
    sendMove(m_canvas, QPointF(260, 330), Qt::RightButton, {});
    QTest::mouseRelease(m_canvas, Qt::RightButton, {}, QPoint(260, 330));
    QCOMPARE(pen->marks(), marks);
    const QPointF dragged = m_canvas->worldToPixel().map(beforeDrag.inverted().map(moved));
    QVERIFY(QLineF(dragged, moved + QPointF(60, 30)).length() < 1e-6);
    QVERIFY(near(at(picture(), dragged), red));
}

void TestPenTool::ctrlZUndoesTheLastMarkAndNoSceneEdit() {
    // a scene edit first: the speed
    Scene faster = m_window->document()->scene();
    faster.speed = 1.5;
    m_window->document()->edit(faster, QStringLiteral("speed"));
    m_window->document()->flush();
    QUndoStack* stack = m_window->document()->undoStack();
    const int steps = stack->index();
    PenTool* pen = startPen();
    strokeAt(0.4);
    strokeAt(0.7);
    strokeAt(1.0);
    QCOMPARE(pen->marks().size(), std::size_t(3));
    const auto firstTwo = std::vector(pen->marks().begin(), pen->marks().begin() + 2);
    QTest::keySequence(m_window.get(), QKeySequence::Undo);
    QCOMPARE(pen->marks(), firstTwo);
    QCOMPARE(stack->index(), steps);
    QCOMPARE(m_window->document()->scene().speed, 1.5);
    const QImage image = picture();
    QVERIFY(!near(at(image, m_canvas->toPixel({2, 1.0})), PenTool::colourOf(0), 60));
    QVERIFY(near(at(image, m_canvas->toPixel({2, 0.7})), PenTool::colourOf(0)));
    // the menu's item too
    m_window->findChild<QAction*>(QStringLiteral("penUndoAction"))->trigger();
    QCOMPARE(pen->marks().size(), std::size_t(1));
    QTest::keySequence(m_window.get(), QKeySequence::Undo);
    QTest::keySequence(m_window.get(), QKeySequence::Undo);
    QVERIFY(pen->marks().empty());
    QCOMPARE(m_window->document()->scene().speed, 1.5);
    // with the pen off, Ctrl+Z is the scene's again
    m_canvas->setPenMode(false);
    QTest::keySequence(m_window.get(), QKeySequence::Undo);
    QCOMPARE(stack->index(), steps - 1);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().speed, straightScene().speed);
}

void TestPenTool::eAndDeleteClearEveryMark() {
    PenTool* pen = startPen();
    for (const Qt::Key key : {Qt::Key_E, Qt::Key_Delete}) {
        strokeAt(0.4);
        strokeAt(0.8);
        QCOMPARE(pen->marks().size(), std::size_t(2));
        m_canvas->setFocus();
        QTest::keyClick(m_canvas, key);
        QVERIFY(pen->marks().empty());
        const QImage image = picture();
        for (double y : {0.4, 0.8})
            QVERIFY(!near(at(image, m_canvas->toPixel({2, y})), PenTool::colourOf(0), 60));
    }
    // the menu's item
    strokeAt(1.0);
    m_window->findChild<QAction*>(QStringLiteral("penClearAction"))->trigger();
    QVERIFY(pen->marks().empty());
}

void TestPenTool::fourColoursAndArrows() {
    PenTool* pen = startPen();
    m_canvas->setFocus();
    const double heights[] = {-0.9, -0.45, 0.45, 0.9};
    for (int c = 0; c < kMarkColours; ++c) {
        QCOMPARE(pen->colour(), c);
        QVERIFY(m_window->findChild<QAction*>(QStringLiteral("penColour%1").arg(c))->isChecked());
        strokeAt(heights[c]);
        QTest::keyClick(m_canvas, Qt::Key_C); // the next colour
    }
    QCOMPARE(pen->colour(), 0); // after the last, the first
    const QImage image = picture();
    for (int c = 0; c < kMarkColours; ++c) {
        QCOMPARE(pen->marks()[std::size_t(c)].colour, c);
        const QColor seen = at(image, m_canvas->toPixel({2, heights[c]}));
        QVERIFY2(near(seen, PenTool::colourOf(c)), qPrintable(seen.name()));
    }
    // the four colours are far apart
    for (int a = 0; a < kMarkColours; ++a)
        for (int b = a + 1; b < kMarkColours; ++b)
            QVERIFY(!near(PenTool::colourOf(a), PenTool::colourOf(b), 60));
    // a chosen colour from the menu
    m_window->findChild<QAction*>(QStringLiteral("penColour2"))->trigger();
    QCOMPARE(pen->colour(), 2);
    // arrows: A, then a drag from its tail to its head
    pen->clear();
    QTest::keyClick(m_canvas, Qt::Key_A);
    QCOMPARE(pen->kind(), MarkKind::Arrow);
    QVERIFY(m_window->findChild<QAction*>(QStringLiteral("penArrowsAction"))->isChecked());
    const QPoint tail = m_canvas->toPixel({0.5, 1.1}).toPoint();
    const QPoint head = m_canvas->toPixel({3.0, 0.3}).toPoint();
    drag(m_canvas, tail, head);
    QCOMPARE(pen->marks().size(), std::size_t(1));
    const AnnotationMark& arrow = pen->marks()[0];
    QCOMPARE(arrow.kind, MarkKind::Arrow);
    QCOMPARE(arrow.points.size(), std::size_t(2));
    QVERIFY(
        QLineF(m_canvas->toPixel({arrow.points[1].first, arrow.points[1].second}), head).length() <
        1e-9);
    // the head is filled: the pixel just behind its tip along the shaft is the arrow's colour
    const QPointF along = QPointF(tail - head) / QLineF(tail, head).length();
    QVERIFY(near(at(picture(), QPointF(head) + 8 * along), PenTool::colourOf(2)));
    // a click draws no arrow
    QTest::mouseClick(m_canvas, Qt::LeftButton, {}, tail);
    QCOMPARE(pen->marks().size(), std::size_t(1));
    // freehand again; Shift+drag is an arrow anyway
    QTest::keyClick(m_canvas, Qt::Key_A);
    QCOMPARE(pen->kind(), MarkKind::Freehand);
    drag(m_canvas, tail, head, 10, Qt::ShiftModifier);
    QCOMPARE(pen->marks().back().kind, MarkKind::Arrow);
}

void TestPenTool::aLongStrokeIsSimplified() {
    PenTool* pen = startPen();
    // a slow drag: 400 moves along 200 px, half a pixel apart
    const QPoint from = m_canvas->toPixel({0.5, 0.8}).toPoint();
    const QPoint to = from + QPoint(200, 0);
    drag(m_canvas, from, to, 400);
    QCOMPARE(pen->marks().size(), std::size_t(1));
    const auto& points = pen->marks()[0].points;
    // points at least 1.5 px apart at the zoom it was drawn at: 200 / 1.5 + 2 at most
    QVERIFY2(points.size() <= 200 / 1.5 + 2, qPrintable(QString::number(points.size())));
    QVERIFY(points.size() >= 200 / 2.0);
    for (std::size_t i = 1; i + 1 < points.size(); ++i)
        QVERIFY(QLineF(m_canvas->toPixel({points[i - 1].first, points[i - 1].second}),
                       m_canvas->toPixel({points[i].first, points[i].second}))
                    .length() >= 1.5 - 1e-9);
}

void TestPenTool::drawsInPresentationMode() {
    m_window->presentation()->setFullScreen(false);
    m_window->presentation()->setActive(true);
    QCoreApplication::processEvents();
    QVERIFY(m_window->presentation()->isActive());
    m_canvas->fitScene();
    // F11's window keeps the pen's key and the canvas's P
    auto* penAction = m_window->findChild<QAction*>(QStringLiteral("penAction"));
    QTest::keySequence(m_window.get(), penAction->shortcut());
    QVERIFY(m_canvas->penMode());
    PenTool* pen = m_canvas->penTool();
    strokeAt(0.6);
    QCOMPARE(pen->marks().size(), std::size_t(1));
    const QImage image = picture();
    const QPointF middle = m_canvas->toPixel({2, 0.6});
    QVERIFY(m_canvas->drawingArea().contains(middle));
    QVERIFY(near(at(image, middle), PenTool::colourOf(0)));
    // the lines are wider when presenting: 3 px off the centre is still the colour
    // the lines are wider when presenting: the same mark is thicker than in the window
    QVERIFY(m_canvas->canvasStyle().lineScale > 1);
    const int presented = thickness(image, middle, PenTool::colourOf(0));
    m_window->presentation()->setActive(false);
    QCoreApplication::processEvents();
    const QPointF windowed = m_canvas->toPixel({2, 0.6});
    const int inWindow = thickness(picture(), windowed, PenTool::colourOf(0));
    QVERIFY2(
        presented > inWindow && inWindow >= 3,
        qPrintable(
            QStringLiteral("%1 px presenting, %2 px in the window").arg(presented).arg(inWindow)));
    m_window->presentation()->setActive(true);
    QCoreApplication::processEvents();
    QTest::keySequence(m_window.get(), QKeySequence::Undo);
    QVERIFY(pen->marks().empty());
    // leaving presentation mode keeps the marks
    strokeAt(0.6);
    m_window->presentation()->setActive(false);
    QCOMPARE(pen->marks().size(), std::size_t(1));
}

void TestPenTool::theSceneAndItsResultAreUnchanged() {
    SceneDocument* document = m_window->document();
    const Scene scene = document->scene();
    const auto solution = document->solution();
    const std::string summary = formatSummary(*solution);
    const std::string link = sceneToLink(scene);
    const int steps = document->undoStack()->count();
    QSignalSpy recomputed(document, &SceneDocument::solutionChanged);
    PenTool* pen = startPen();
    // marks across the path and the bodies, and an arrow
    drag(m_canvas, m_canvas->toPixel({-0.5, -0.5}).toPoint(),
         m_canvas->toPixel({4.5, 0.5}).toPoint());
    drag(m_canvas, m_canvas->toPixel({0, 1}).toPoint(), m_canvas->toPixel({0, 0}).toPoint(), 10,
         Qt::ShiftModifier);
    m_window->playback()->seek(1.0);
    strokeAt(0.1, 0, 4);
    QCOMPARE(pen->marks().size(), std::size_t(3));
    document->flush();
    QCOMPARE(recomputed.count(), 0);
    QCOMPARE(document->solution(), solution);
    QCOMPARE(formatSummary(*document->solution()), summary);
    QVERIFY(document->scene() == scene);
    QVERIFY(document->scene().annotations.empty());
    QCOMPARE(sceneToLink(document->scene()), link);
    QCOMPARE(document->undoStack()->count(), steps);
    QVERIFY(!document->isModified());
    // the path drawing tool is not the pen: the path is the same polyline
    QCOMPARE(document->scene().path.points, straightScene().path.points);
}

void TestPenTool::savedOnlyWhenAskedAndReadBack() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    auto* option = m_window->findChild<QAction*>(QStringLiteral("saveAnnotationsAction"));
    QVERIFY(option && option->isCheckable());
    QVERIFY(!option->isChecked()); // off by default
    QVERIFY(test::inMenuBar(m_window->menuBar(), option));
    PenTool* pen = startPen();
    strokeAt(0.8);
    drag(m_canvas, m_canvas->toPixel({1, 1}).toPoint(), m_canvas->toPixel({2, 0.5}).toPoint(), 10,
         Qt::ShiftModifier);
    m_canvas->setFocus();
    QTest::keyClick(m_canvas, Qt::Key_C);
    strokeAt(-0.8);
    const auto marks = pen->marks();
    QCOMPARE(marks.size(), std::size_t(3));
    const std::string link = sceneToLink(m_window->document()->scene());

    // not asked: the file is the scene's alone, byte for byte
    const QString plain = dir.filePath(QStringLiteral("plain.json"));
    QVERIFY(m_window->saveFile(plain));
    QFile plainFile(plain);
    QVERIFY(plainFile.open(QIODevice::ReadOnly));
    const QByteArray plainText = plainFile.readAll();
    QCOMPARE(plainText.toStdString(), sceneToJson(m_window->document()->scene()));
    QVERIFY(!plainText.contains("annotations"));

    // asked: the marks are in the file, and nothing else changed
    option->trigger();
    QVERIFY(pen->savesWithScene());
    const QString marked = dir.filePath(QStringLiteral("marked.json"));
    QVERIFY(m_window->saveFile(marked));
    QFile markedFile(marked);
    QVERIFY(markedFile.open(QIODevice::ReadOnly));
    const QByteArray markedText = markedFile.readAll();
    QVERIFY(markedText.contains("\"annotations\""));
    QJsonObject json = QJsonDocument::fromJson(markedText).object();
    json.remove(QStringLiteral("annotations"));
    QCOMPARE(json, QJsonDocument::fromJson(plainText).object());
    const Scene read = loadSceneFile(marked.toStdString());
    QCOMPARE(read.annotations, marks);

    // a new window opens it: the pen has the marks, the option is on, the scene as before
    m_window.reset();
    m_window = test::showTestWindow();
    m_canvas = m_window->canvas();
    QVERIFY(m_canvas->penTool()->marks().empty());
    QVERIFY(m_window->openFile(marked));
    QCOMPARE(m_canvas->penTool()->marks(), marks);
    QVERIFY(m_window->findChild<QAction*>(QStringLiteral("saveAnnotationsAction"))->isChecked());
    QVERIFY(m_window->document()->scene().annotations.empty());
    QCOMPARE(sceneToLink(m_window->document()->scene()), link);
    QVERIFY(!m_window->document()->isModified());
    // their pixels, without the pen on
    m_canvas->fitScene();
    QVERIFY(near(at(picture(), m_canvas->toPixel({2, 0.8})), PenTool::colourOf(0)));
    QVERIFY(near(at(picture(), m_canvas->toPixel({2, -0.8})), PenTool::colourOf(1)));
    // another scene comes without them
    m_window->openFile(plain);
    QVERIFY(m_canvas->penTool()->marks().empty());
}

void TestPenTool::marksToBeSavedAreUnsavedChangesUntilSaved() {
    // marks saved with the scene are part of what File > Save keeps: the title's star and the
    // question before closing know them; marks that are not to be saved are not asked for
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    auto* option = m_window->findChild<QAction*>(QStringLiteral("saveAnnotationsAction"));
    QVERIFY(option);
    const QString path = dir.filePath(QStringLiteral("scene.json"));
    QVERIFY(m_window->saveFile(path));
    auto starred = [this] { return m_window->windowTitle().contains(QLatin1Char('*')); };
    QVERIFY(!m_window->hasUnsavedChanges());
    QVERIFY(!starred());
    PenTool* pen = startPen();
    strokeAt(0.8);
    QCOMPARE(pen->marks().size(), std::size_t(1));
    QVERIFY(!m_window->hasUnsavedChanges()); // not to be saved
    QVERIFY(!starred());
    option->trigger();
    QVERIFY(m_window->hasUnsavedChanges());
    QVERIFY(starred());
    QVERIFY(m_window->saveFile(path));
    QVERIFY(!m_window->hasUnsavedChanges());
    QVERIFY(!starred());
    // a new mark, and its undo back to what the file holds
    strokeAt(-0.8);
    QVERIFY(m_window->hasUnsavedChanges());
    QVERIFY(starred());
    QVERIFY(pen->undoLast());
    QVERIFY(!m_window->hasUnsavedChanges());
    // cleared: the file still has the mark
    pen->clear();
    QVERIFY(m_window->hasUnsavedChanges());
    QVERIFY(starred());
    // the file read again: its marks are what is saved
    QVERIFY(m_window->openFile(path));
    QCOMPARE(pen->marks().size(), std::size_t(1));
    QVERIFY(!m_window->hasUnsavedChanges());
    QVERIFY(!starred());
    // the scene's own edits still count, marks or not
    Scene s = m_window->document()->scene();
    s.system.params["m"] = 2.0;
    m_window->document()->edit(s, QStringLiteral("mass"));
    m_window->document()->flush();
    QVERIFY(m_window->hasUnsavedChanges());
}

QTEST_MAIN(TestPenTool)
#include "test_pen_tool.moc"
