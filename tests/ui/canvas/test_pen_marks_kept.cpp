// Nothing the lecturer drew with the pen is lost in silence (docs/user-guide.md, Drawing over the
// lesson; docs/robustness.md, Crash recovery): the crash-recovery copy keeps the marks in its
// "annotations" member and a restore in a fresh window puts back exactly the same points, without
// ticking File > Save annotations with the scene unless the scene's own file holds marks; a
// damaged member costs the marks only and is named; a preset or a gallery scene chosen over marks
// is one undo step, which brings the scene and its marks back, and its redo takes them again.
#include "canvas/pen_tool.h"
#include "canvas/scene_canvas.h"
#include "common/input_error.h"
#include "document/autosave.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "pen_strokes.h"
#include "scene/scene_json.h"
#include "scene/scene_link.h"
#include "shell/main_window.h"
#include "shell/playback.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <memory>

using namespace chaplygin;
using namespace chaplygin::ui;
using test::drag;
using test::near;

namespace {

// a straight drawn path along x from the origin, at a speed of its own
Scene straightScene() {
    Scene s = test::straightScene();
    s.speed = 1.5;
    return s;
}

const QColor kRed = PenTool::colourOf(0);

// where the windows keep their copies while XDG_STATE_HOME is `state`
QString autosaveFolder(const QTemporaryDir& state) {
    return state.path() + QStringLiteral("/chaplygin-lab/autosave");
}

// the name of a copy whose window is gone: no lock is held beside it
const QString kOrphanBase = QStringLiteral("window-999999-0");

// what a killed program leaves: the window's copy written now, under the name of a window whose
// lock is gone; "" when no copy was written
QString leaveOrphan(MainWindow& window, const QString& folder) {
    if (!window.autosave()->writeNow() || window.autosave()->file().isEmpty())
        return {};
    const QDir dir(folder);
    const QFileInfo copy(window.autosave()->file());
    const QString orphan = dir.filePath(kOrphanBase + QStringLiteral(".json"));
    if (!QFile::copy(copy.filePath(), orphan))
        return {};
    const QString origin = dir.filePath(copy.completeBaseName() + QStringLiteral(".origin"));
    if (QFile::exists(origin))
        QFile::copy(origin, dir.filePath(kOrphanBase + QStringLiteral(".origin")));
    return orphan;
}

// a window of the program's own kind (with its copy on disk), the straight scene loaded and fitted
std::unique_ptr<MainWindow> persistentWindow(bool shown) {
    auto window = std::make_unique<MainWindow>(true);
    window->resize(1280, 800);
    if (shown) {
        window->show();
        if (!QTest::qWaitForWindowExposed(window.get()))
            return nullptr;
    }
    window->document()->flush();
    return window;
}

QAction* action(const MainWindow& window, const char* name) {
    return window.findChild<QAction*>(QString::fromLatin1(name));
}

bool yes(const Autosave::Orphan&) {
    return true;
}

} // namespace

class TestPenMarksKept : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { test::useTestSettings(QStringLiteral("ui_pen_kept_tests")); }
    void cleanup() { qunsetenv("XDG_STATE_HOME"); }

    void autosavedMarksComeBackInAFreshWindow();
    void aRestoreNeverTicksSavingMarksIntoAFileWithout();
    void aDamagedMarksMemberCostsOnlyTheMarks_data();
    void aDamagedMarksMemberCostsOnlyTheMarks();
    void aPresetsUndoBringsTheMarksBackAndRedoTakesThem();
    void aGalleryScenesStepKeepsTheUnsavedMarksRule();

  private:
    // the straight scene, fitted, paused at t = 0
    static void loadStraight(MainWindow& window);
    // the pen on and three marks: a red stroke at y = 0.8, a red arrow, a blue stroke at y = -0.8
    static std::vector<AnnotationMark> drawThreeMarks(MainWindow& window);
    static QImage picture(const MainWindow& window) { return window.canvas()->grab().toImage(); }
    static QColor at(const MainWindow& window, QPointF world) {
        return picture(window).pixelColor(window.canvas()->toPixel(world).toPoint());
    }
};

void TestPenMarksKept::loadStraight(MainWindow& window) {
    window.document()->loadNow(straightScene());
    window.playback()->pause();
    window.playback()->seek(0);
    window.canvas()->fitScene();
}

std::vector<AnnotationMark> TestPenMarksKept::drawThreeMarks(MainWindow& window) {
    SceneCanvas* canvas = window.canvas();
    canvas->setPenMode(true);
    auto pixel = [canvas](double x, double y) { return canvas->toPixel({x, y}).toPoint(); };
    drag(canvas, pixel(1, 0.8), pixel(3, 0.8));
    drag(canvas, pixel(1, 1.2), pixel(2, 0.5), 10, Qt::ShiftModifier);
    canvas->penTool()->setColour(1);
    drag(canvas, pixel(1, -0.8), pixel(3, -0.8));
    canvas->penTool()->setColour(0);
    return canvas->penTool()->marks();
}

void TestPenMarksKept::autosavedMarksComeBackInAFreshWindow() {
    QTemporaryDir state;
    QVERIFY(state.isValid());
    qputenv("XDG_STATE_HOME", state.path().toUtf8());
    auto window = persistentWindow(true);
    QVERIFY(window);
    loadStraight(*window);
    const auto marks = drawThreeMarks(*window);
    QCOMPARE(marks.size(), std::size_t(3));
    const Scene scene = window->document()->scene();
    const QPointF drawnAt = window->canvas()->toPixel({2, 0.8});
    QVERIFY(near(at(*window, {2, 0.8}), kRed));
    // no scene edit: the marks alone are worth a copy, although they are not to be saved
    QVERIFY(!window->document()->isModified());
    QVERIFY(!window->canvas()->penTool()->savesWithScene());
    const QString orphan = leaveOrphan(*window, autosaveFolder(state));
    QVERIFY(!orphan.isEmpty());
    // the copy is a scene file with its "annotations" member, read by the scene reader
    const Scene copied = loadSceneFile(orphan.toStdString());
    QCOMPARE(copied.annotations, marks);
    Scene plain = copied;
    plain.annotations.clear();
    QCOMPARE(sceneToJson(plain), sceneToJson(scene));
    window.reset();

    auto fresh = persistentWindow(false);
    QVERIFY(fresh);
    QVERIFY(fresh->offerRestore(yes));
    fresh->show();
    QVERIFY(QTest::qWaitForWindowExposed(fresh.get()));
    fresh->document()->flush();
    PenTool* pen = fresh->canvas()->penTool();
    QCOMPARE(pen->marks(), marks); // every point, exactly
    QCOMPARE(sceneToLink(fresh->document()->scene()), sceneToLink(scene));
    QVERIFY(fresh->lastFileError().isEmpty());
    // not ticked: the marks are shown, File > Save would not write them
    QVERIFY(!pen->savesWithScene());
    QVERIFY(!action(*fresh, "saveAnnotationsAction")->isChecked());
    QVERIFY(!pen->hasUnsavedMarks());
    // on the canvas where they were drawn
    fresh->canvas()->fitScene();
    QCOMPARE(fresh->canvas()->toPixel({2, 0.8}), drawnAt);
    const QImage image = picture(*fresh);
    QVERIFY2(near(image.pixelColor(drawnAt.toPoint()), kRed),
             qPrintable(image.pixelColor(drawnAt.toPoint()).name()));
    QVERIFY(near(image.pixelColor(fresh->canvas()->toPixel({2, -0.8}).toPoint()),
                 PenTool::colourOf(1)));
    // the old copy is gone; the fresh window keeps the marks in its own
    QVERIFY(!QFile::exists(orphan));
    QVERIFY(fresh->autosave()->writeNow());
    QVERIFY(!fresh->autosave()->file().isEmpty());
    QCOMPARE(loadSceneFile(fresh->autosave()->file().toStdString()).annotations, marks);
    // cleared and the scene saved: nothing left to keep
    QTemporaryDir files;
    pen->clear();
    QVERIFY(fresh->saveFile(files.filePath(QStringLiteral("saved.json"))));
    QVERIFY(fresh->autosave()->file().isEmpty());
}

void TestPenMarksKept::aRestoreNeverTicksSavingMarksIntoAFileWithout() {
    QTemporaryDir state, files;
    QVERIFY(state.isValid() && files.isValid());
    qputenv("XDG_STATE_HOME", state.path().toUtf8());
    const QString plainFile = files.filePath(QStringLiteral("plain.json"));
    const QString markedFile = files.filePath(QStringLiteral("marked.json"));

    // a file without marks, marks drawn over it, the program killed
    auto window = persistentWindow(true);
    QVERIFY(window);
    loadStraight(*window);
    QVERIFY(window->saveFile(plainFile));
    const auto marks = drawThreeMarks(*window);
    QVERIFY(!leaveOrphan(*window, autosaveFolder(state)).isEmpty());
    window.reset();
    auto fresh = persistentWindow(true);
    QVERIFY(fresh);
    QVERIFY(fresh->offerRestore(yes));
    QCOMPARE(fresh->document()->fileName(), plainFile);
    QCOMPARE(fresh->canvas()->penTool()->marks(), marks);
    QVERIFY(!fresh->canvas()->penTool()->savesWithScene());
    // File > Save writes the scene alone into it
    QVERIFY(fresh->saveFile(plainFile));
    QFile plain(plainFile);
    QVERIFY(plain.open(QIODevice::ReadOnly));
    QVERIFY(!plain.readAll().contains("annotations"));
    QCOMPARE(fresh->canvas()->penTool()->marks(), marks); // still shown
    fresh.reset();

    // a file saved with two marks, a third drawn, the program killed
    window = persistentWindow(true);
    QVERIFY(window);
    loadStraight(*window);
    auto all = drawThreeMarks(*window);
    PenTool* pen = window->canvas()->penTool();
    QVERIFY(pen->undoLast());
    action(*window, "saveAnnotationsAction")->trigger();
    QVERIFY(window->saveFile(markedFile));
    const auto saved = pen->marks();
    QCOMPARE(saved.size(), std::size_t(2));
    pen->setColour(1);
    drag(window->canvas(), window->canvas()->toPixel({1, -0.8}).toPoint(),
         window->canvas()->toPixel({3, -0.8}).toPoint());
    all = pen->marks();
    QVERIFY(window->hasUnsavedChanges());
    QVERIFY(!leaveOrphan(*window, autosaveFolder(state)).isEmpty());
    window.reset();
    // the option as opening that file would set it: ticked, the file's two marks saved, the third
    // an unsaved change
    fresh = persistentWindow(true);
    QVERIFY(fresh);
    QVERIFY(fresh->offerRestore(yes));
    pen = fresh->canvas()->penTool();
    QCOMPARE(pen->marks(), all);
    QVERIFY(pen->savesWithScene());
    QVERIFY(action(*fresh, "saveAnnotationsAction")->isChecked());
    QVERIFY(pen->hasUnsavedMarks());
    QVERIFY(pen->undoLast());
    QVERIFY(!pen->hasUnsavedMarks()); // back to the file's marks
}

void TestPenMarksKept::aDamagedMarksMemberCostsOnlyTheMarks_data() {
    QTest::addColumn<QByteArray>("member");
    QTest::addColumn<QString>("where");
    const QByteArray dot = R"({"colour": "red", "kind": "freehand", "points": [[0, 0]]})";
    QByteArray many = "[";
    for (int i = 0; i < 501; ++i)
        many += (i ? ", " : "") + dot;
    QTest::newRow("501 marks") << (many + "]") << QStringLiteral("scene file /annotations");
    QByteArray long_ = R"([{"colour": "red", "kind": "freehand", "points": [)";
    for (int i = 0; i < 5001; ++i)
        long_ += (i ? ", [" : "[") + QByteArray::number(i) + ", 0]";
    QTest::newRow("5001 points") << (long_ + "]}]")
                                 << QStringLiteral("scene file /annotations/0/points");
    QTest::newRow("unknown colour")
        << QByteArray(R"([{"colour": "purple", "kind": "freehand", "points": [[0, 0]]}])")
        << QStringLiteral("scene file /annotations/0/colour");
    QTest::newRow("a coordinate that is text")
        << QByteArray(R"([{"colour": "red", "kind": "freehand", "points": [[0, 0], ["x", 1]]}])")
        << QStringLiteral("scene file /annotations/0/points/1/0");
    QTest::newRow("not an array") << QByteArray(R"({"colour": "red"})")
                                  << QStringLiteral("scene file /annotations");
}

void TestPenMarksKept::aDamagedMarksMemberCostsOnlyTheMarks() {
    QFETCH(QByteArray, member);
    QFETCH(QString, where);
    QTemporaryDir state;
    QVERIFY(state.isValid());
    qputenv("XDG_STATE_HOME", state.path().toUtf8());
    QVERIFY(QDir().mkpath(autosaveFolder(state)));
    QJsonObject copy =
        QJsonDocument::fromJson(QByteArray::fromStdString(sceneToJson(straightScene()))).object();
    const QJsonDocument damaged = QJsonDocument::fromJson("{\"m\": " + member + "}");
    QVERIFY(damaged.isObject());
    copy.insert(QStringLiteral("annotations"), damaged.object().value(QStringLiteral("m")));
    const QString orphan = QDir(autosaveFolder(state)).filePath(kOrphanBase + ".json");
    QFile file(orphan);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(QJsonDocument(copy).toJson());
    file.close();
    // the scene reader alone refuses the whole file
    QVERIFY_THROWS_EXCEPTION(InputError, loadSceneFile(orphan.toStdString()));

    auto window = persistentWindow(false);
    QVERIFY(window);
    QVERIFY(window->offerRestore(yes));
    window->document()->flush();
    // the scene is back, modified, without marks; the message names the marks and the place
    QCOMPARE(sceneToLink(window->document()->scene()), sceneToLink(straightScene()));
    QVERIFY(window->document()->isModified());
    QVERIFY(window->canvas()->penTool()->marks().empty());
    QVERIFY(!window->canvas()->penTool()->savesWithScene());
    const QString message = window->lastFileError();
    QVERIFY2(message.contains(where + QLatin1Char(':')), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("marks")), qPrintable(message));
    QVERIFY(!QFile::exists(orphan));
}

void TestPenMarksKept::aPresetsUndoBringsTheMarksBackAndRedoTakesThem() {
    auto window = test::showTestWindow();
    QVERIFY(window);
    loadStraight(*window);
    const auto marks = drawThreeMarks(*window);
    const QPointF drawnAt = window->canvas()->toPixel({2, 0.8});
    QVERIFY(near(picture(*window).pixelColor(drawnAt.toPoint()), kRed));
    SceneDocument* document = window->document();
    QUndoStack* stack = document->undoStack();
    const int steps = stack->index();
    const std::string link = sceneToLink(document->scene());

    // key 2: the line; the pen's marks go with the straight scene, and the pen stays on
    window->choosePresetNumber(1);
    QTRY_COMPARE(stack->index(), steps + 1);
    document->flush();
    PenTool* pen = window->canvas()->penTool();
    QVERIFY(pen->marks().empty());
    QVERIFY(window->canvas()->penMode());
    QVERIFY(sceneToLink(document->scene()) != link);
    auto* undo = action(*window, "undoAction");
    auto* redo = action(*window, "redoAction");
    QVERIFY(undo && redo);
    for (int round = 0; round < 2; ++round) {
        // Edit > Undo from the menu (Ctrl+Z is the pen's while it is on): the scene and its marks
        QVERIFY(undo->isEnabled());
        undo->trigger();
        document->flush();
        QCOMPARE(stack->index(), steps);
        QCOMPARE(sceneToLink(document->scene()), link);
        QCOMPARE(pen->marks(), marks);
        // at the same place of the scene: where the view puts the metres they were drawn at
        const QPointF shownAt = window->canvas()->toPixel({2, 0.8});
        QImage image = picture(*window);
        QVERIFY2(near(image.pixelColor(shownAt.toPoint()), kRed),
                 qPrintable(image.pixelColor(shownAt.toPoint()).name()));
        QVERIFY(near(image.pixelColor(window->canvas()->toPixel({2, -0.8}).toPoint()),
                     PenTool::colourOf(1)));
        // Edit > Redo: the line again, without them
        redo->trigger();
        document->flush();
        QCOMPARE(stack->index(), steps + 1);
        QVERIFY(pen->marks().empty());
        image = picture(*window);
        QVERIFY(!near(image.pixelColor(window->canvas()->toPixel({2, 0.8}).toPoint()), kRed, 60));
    }
    // the same preset again is no step, and takes no mark drawn over it
    drag(window->canvas(), drawnAt.toPoint(), drawnAt.toPoint() + QPoint(80, 0));
    QCOMPARE(pen->marks().size(), std::size_t(1));
    window->choosePresetNumber(1);
    QTest::qWait(50);
    document->flush();
    QCOMPARE(stack->index(), steps + 1);
    QCOMPARE(pen->marks().size(), std::size_t(1));
}

void TestPenMarksKept::aGalleryScenesStepKeepsTheUnsavedMarksRule() {
    QTemporaryDir files;
    QVERIFY(files.isValid());
    auto window = test::showTestWindow();
    QVERIFY(window);
    loadStraight(*window);
    const auto marks = drawThreeMarks(*window);
    PenTool* pen = window->canvas()->penTool();
    action(*window, "saveAnnotationsAction")->trigger();
    const QString path = files.filePath(QStringLiteral("marked.json"));
    QVERIFY(window->saveFile(path));
    QVERIFY(!window->hasUnsavedChanges());
    auto* undo = action(*window, "undoAction");
    auto* redo = action(*window, "redoAction");

    // saved marks: the gallery scene is clean and untitled, its undo the file with its marks
    QVERIFY(window->loadGalleryEntry(QStringLiteral("cusp")));
    QVERIFY(pen->marks().empty());
    QVERIFY(window->document()->fileName().isEmpty());
    QVERIFY(!window->hasUnsavedChanges());
    QVERIFY(!window->windowTitle().contains(QLatin1Char('*')));
    undo->trigger();
    window->document()->flush();
    QCOMPARE(pen->marks(), marks);
    QCOMPARE(window->document()->fileName(), path);
    QVERIFY(pen->savesWithScene());
    QVERIFY(!pen->hasUnsavedMarks()); // the file's own
    redo->trigger();
    QVERIFY(pen->marks().empty());
    QVERIFY(!pen->hasUnsavedMarks());

    // the file again, clean, and a mark it does not hold: an unsaved change that stays a step
    // back, the document modified, as the scene's own unsaved edits do
    QVERIFY(window->openFile(path));
    QCOMPARE(pen->marks(), marks);
    QVERIFY(!window->hasUnsavedChanges());
    window->canvas()->setPenMode(true);
    drag(window->canvas(), window->canvas()->toPixel({1, 0.4}).toPoint(),
         window->canvas()->toPixel({3, 0.4}).toPoint());
    const auto more = pen->marks();
    QCOMPARE(more.size(), marks.size() + 1);
    QVERIFY(window->hasUnsavedChanges());
    QVERIFY(window->loadGalleryEntry(QStringLiteral("cusp")));
    QVERIFY(pen->marks().empty());
    QVERIFY(!pen->hasUnsavedMarks());
    QVERIFY(window->document()->isModified());
    QVERIFY(window->hasUnsavedChanges());
    QVERIFY(window->windowTitle().contains(QLatin1Char('*')));
    undo->trigger();
    window->document()->flush();
    QCOMPARE(pen->marks(), more);
    QCOMPARE(window->document()->fileName(), path);
    QVERIFY(pen->hasUnsavedMarks());
    QVERIFY(window->hasUnsavedChanges());
    // the last mark undone: the file's marks and scene, nothing unsaved
    QVERIFY(pen->undoLast());
    QVERIFY(!pen->hasUnsavedMarks());
    QVERIFY(!window->hasUnsavedChanges());
}

QTEST_MAIN(TestPenMarksKept)
#include "test_pen_marks_kept.moc"
