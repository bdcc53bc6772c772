// A lecture of one's own: made from the window (add, reorder, remove), saved, opened again like a
// scene, and stepped through with Page Down / Page Up, also in presentation mode. Offscreen.
#include "canvas/scene_canvas.h"
#include "desktop_entry.h"
#include "document/scene_files.h"
#include "lab/gallery.h"
#include "scene/lecture.h"
#include "scene/scene_json.h"
#include "shell/lecture_panel.h"
#include "shell/presentation_mode.h"
#include "window_fixture.h"

#include <QAction>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QStatusBar>
#include <QUndoStack>
#include <QtTest>

#include <fstream>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestLecture : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_lecture_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void lectureMadeSavedReopenedAndStepped();
    void lectureSteppedInPresentationMode();
    void badLectureKeepsTheSceneAndTheLecture();
    void withoutALecturePageDownStepsTheGallery();
    void lectureScreenshotOption();

  private:
    QAction* action(const char* name) const {
        auto* a = m_window->findChild<QAction*>(QString::fromLatin1(name));
        if (!a)
            qWarning("no action %s", name);
        return a;
    }
    LecturePanel* panel() const { return m_window->lecturePanel(); }
    const Scene& shown() const { return m_window->document()->scene(); }
    void press(Qt::Key key) {
        QTest::keyClick(m_window.get(), key);
        m_window->document()->flush();
    }
    /// The row's item clicked in the Lecture dock's list, as the user highlights it.
    void clickRow(int row) {
        QListWidget* list = panel()->list();
        QListWidgetItem* item = list->item(row);
        QVERIFY(item);
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {},
                          list->visualItemRect(item).center());
        QCOMPARE(panel()->current(), row);
    }
    /// The shown scene is `expected` with its arrows, and the view frames its path.
    void checkShown(const Scene& expected) {
        QVERIFY(shown() == expected);
        QCOMPARE(shown().vectors, expected.vectors);
        QVERIFY(m_window->undoStack()->canUndo());
        SceneCanvas* canvas = m_window->canvas();
        const QRectF path = canvas->worldToPixel().mapRect(canvas->pathBounds());
        QVERIFY2(canvas->drawingArea().adjusted(-2, -2, 2, 2).contains(path), "the path is framed");
        QVERIFY2(path.width() > 0.3 * canvas->drawingArea().width() ||
                     path.height() > 0.3 * canvas->drawingArea().height(),
                 "the path fills the view");
    }
    /// Three scenes with their own arrows and notes: two presets and a gallery scene.
    std::vector<Scene> threeScenes() const {
        std::vector<Scene> s;
        const auto names = presetNames();
        Scene a = presetScene(names[0]);
        a.note = "# First\nThe sinusoid.";
        Scene b = presetScene(names[1]);
        b.vectors.knifeVelocity.shown = true;
        b.vectors.lateralReaction = {true, 0.5};
        const GalleryEntry* c = nullptr;
        for (const GalleryEntry& e : galleryEntries())
            if (!c && !e.rejected)
                c = &e;
        s.push_back(a);
        s.push_back(b);
        s.push_back(c->scene);
        return s;
    }
};

void TestLecture::lectureMadeSavedReopenedAndStepped() {
    const std::vector<Scene> scenes = threeScenes();
    QVERIFY(!panel()->isOpen());
    QVERIFY(!dock("lectureDock")->isVisible());
    // add the three as the user does: show each, Lecture > Add the current scene (Ctrl+L)
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        m_window->loadScene(scenes[i]);
        if (i == 0)
            QTest::keyClick(m_window.get(), Qt::Key_L, Qt::ControlModifier);
        else
            action("addToLectureAction")->trigger();
    }
    QVERIFY(panel()->isOpen());
    QVERIFY(dock("lectureDock")->isVisible());
    QCOMPARE(panel()->list()->count(), 3);
    QCOMPARE(panel()->current(), 2);
    QCOMPARE(panel()->list()->currentRow(), 2);
    QCOMPARE(panel()->list()->item(0)->text(), QStringLiteral("First")); // the note's heading
    for (int i = 0; i < 3; ++i)
        QVERIFY(panel()->lecture().entries[std::size_t(i)].scene == scenes[std::size_t(i)]);
    // reorder: the gallery scene up to the front, A B C -> C A B
    action("moveLectureUpAction")->trigger();
    action("moveLectureUpAction")->trigger();
    QCOMPARE(panel()->current(), 0);
    QVERIFY(!action("moveLectureUpAction")->isEnabled());
    // remove A, highlighted with a click: C B
    clickRow(1);
    QVERIFY(panel()->lecture().entries[1].scene == scenes[0]);
    action("removeFromLectureAction")->trigger();
    QCOMPARE(panel()->list()->count(), 2);
    QVERIFY(panel()->lecture().entries[0].scene == scenes[2]);
    QVERIFY(panel()->lecture().entries[1].scene == scenes[1]);
    QVERIFY(panel()->isModified());
    // renamed in the list (F2), and the lecture's title typed
    panel()->list()->item(1)->setText(QStringLiteral("  Arrows  "));
    QCOMPARE(panel()->lecture().entries[1].title, std::string("Arrows"));
    QTest::qWait(0);
    QCOMPARE(panel()->list()->item(1)->text(), QStringLiteral("Arrows"));
    panel()->list()->item(1)->setText(QString());
    QTest::qWait(0);
    QCOMPARE(panel()->list()->item(1)->text(), QStringLiteral("Scene 2"));
    auto* title = panel()->findChild<QLineEdit*>(QStringLiteral("lectureTitle"));
    QTest::keyClicks(title, QStringLiteral("Sleighs"));
    QCOMPARE(panel()->lecture().title, std::string("Sleighs"));

    // save: the file holds C then B, read by the core's reader
    const QString path = m_dir.filePath(QStringLiteral("my-lecture.json"));
    test::DialogScript save{path};
    save.install();
    action("saveLectureAction")->trigger();
    QCOMPARE(save.calls, 1);
    QVERIFY(!panel()->isModified());
    const Lecture written = loadLectureFile(path.toStdString());
    QCOMPARE(written.entries.size(), std::size_t(2));
    QVERIFY(written.entries[0].scene == scenes[2]);
    QVERIFY(written.entries[1].scene == scenes[1]);
    QCOMPARE(written.title, std::string("Sleighs"));

    // reopen as a scene is opened (File > Open, the command line): its first scene is shown
    action("closeLectureAction")->trigger();
    QVERIFY(!panel()->isOpen());
    m_window->loadScene(presetScene("circle"));
    QVERIFY(m_window->openFile(path));
    m_window->document()->flush();
    QVERIFY(panel()->isOpen());
    QCOMPARE(panel()->fileName(), path);
    QCOMPARE(panel()->current(), 0);
    checkShown(scenes[2]);
    QVERIFY(m_window->windowTitle().contains(QStringLiteral("scene 1 of 2")));
    QCOMPARE(m_window->findChild<QLabel*>(QStringLiteral("lecturePosition"))->text(),
             QStringLiteral("Lecture: scene 1 of 2"));

    // Page Down: B, with its arrows, framed; Page Down again goes round to C; Page Up back to B
    press(Qt::Key_PageDown);
    checkShown(scenes[1]);
    QCOMPARE(panel()->current(), 1);
    QCOMPARE(panel()->list()->currentRow(), 1);
    QVERIFY(m_window->windowTitle().contains(QStringLiteral("scene 2 of 2")));
    press(Qt::Key_PageDown);
    checkShown(scenes[2]);
    press(Qt::Key_PageUp);
    checkShown(scenes[1]);
    // each step is one undo step, as a gallery scene's
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QVERIFY(shown() == scenes[2]);
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QVERIFY(shown() == scenes[1]);
}

void TestLecture::lectureSteppedInPresentationMode() {
    const std::vector<Scene> scenes = threeScenes();
    Lecture l;
    for (const Scene& s : scenes)
        l.entries.push_back({"", s});
    const QString path = m_dir.filePath(QStringLiteral("three.json"));
    saveLectureFile(path.toStdString(), l);
    QVERIFY(m_window->openFile(path));
    m_window->document()->flush();
    checkShown(scenes[0]);
    m_window->presentation()->setFullScreen(false);
    m_window->presentation()->setActive(true);
    QVERIFY(!dock("lectureDock")->isVisible());
    press(Qt::Key_PageDown);
    checkShown(scenes[1]);
    press(Qt::Key_PageDown);
    checkShown(scenes[2]);
    // the Notes dock beside the scene says where the lecture is (the status bar is hidden)
    QVERIFY(dock("notesDock")->isVisible());
    QCOMPARE(dock("notesDock")->windowTitle(), QStringLiteral("Notes (scene 3 of 3)"));
    press(Qt::Key_PageDown);
    checkShown(scenes[0]);
    press(Qt::Key_PageUp);
    checkShown(scenes[2]);
    QVERIFY(m_window->presentation()->isActive());
    m_window->presentation()->setActive(false);
    QVERIFY(dock("lectureDock")->isVisible());
    QCOMPARE(panel()->list()->currentRow(), 2);
}

void TestLecture::badLectureKeepsTheSceneAndTheLecture() {
    const std::vector<Scene> scenes = threeScenes();
    Lecture good;
    good.entries.push_back({"good", scenes[1]});
    const QString goodPath = m_dir.filePath(QStringLiteral("good.json"));
    saveLectureFile(goodPath.toStdString(), good);
    QVERIFY(m_window->openFile(goodPath));
    m_window->document()->flush();
    const Scene before = shown();
    // the second scene's speed is a word: refused, naming the file, the scene and the field
    Lecture two;
    two.entries = {{"a", scenes[0]}, {"b", scenes[1]}};
    std::string text = lectureToJson(two);
    const auto at = text.find("\"speed\"", text.find("\"b\""));
    QVERIFY(at != std::string::npos);
    text.replace(at, text.find(',', at) - at, "\"speed\": \"fast\"");
    const QString badPath = m_dir.filePath(QStringLiteral("bad.json"));
    std::ofstream(badPath.toStdString()) << text;
    QVERIFY(!m_window->openFile(badPath));
    QVERIFY2(m_window->lastFileError().contains(QStringLiteral("/scenes/1/speed")),
             qPrintable(m_window->lastFileError()));
    QVERIFY(m_window->lastFileError().contains(badPath));
    QVERIFY(shown() == before);
    QCOMPARE(panel()->fileName(), goodPath);
    QCOMPARE(panel()->lecture().entries.size(), std::size_t(1));
}

void TestLecture::withoutALecturePageDownStepsTheGallery() {
    const Lecture gallery = galleryLecture();
    press(Qt::Key_PageDown);
    QVERIFY(shown() == gallery.entries[0].scene);
    press(Qt::Key_PageDown);
    QVERIFY(shown() == gallery.entries[1].scene);
    // the gallery as a lecture of one's own: the same scenes, then one's own order
    action("galleryLectureAction")->trigger();
    QCOMPARE(panel()->list()->count(), int(gallery.entries.size()));
    press(Qt::Key_PageUp);
    QVERIFY(shown() == gallery.entries.back().scene);
    QCOMPARE(panel()->current(), int(gallery.entries.size()) - 1);
    // an empty lecture says how to fill it and keeps the scene
    action("newLectureAction")->trigger();
    const Scene before = shown();
    press(Qt::Key_PageDown);
    QVERIFY(shown() == before);
    QVERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("no scenes yet")));
}

void TestLecture::lectureScreenshotOption() {
    Lecture l;
    for (const Scene& s : threeScenes())
        l.entries.push_back({"", s});
    const QString lecture = m_dir.filePath(QStringLiteral("shot.json"));
    saveLectureFile(lecture.toStdString(), l);
    const QString image = m_dir.filePath(QStringLiteral("lecture.png"));
    const QByteArray file = lecture.toUtf8(), png = image.toUtf8();
    auto run = [&](std::vector<const char*> extra) {
        std::vector<const char*> args = {"chaplygin-lab", "--screenshot", png.constData(), "--size",
                                         "1200x750"};
        args.insert(args.end(), extra.begin(), extra.end());
        return runScreenshot(int(args.size()), const_cast<char**>(args.data()));
    };
    QCOMPARE(run({"--lecture", file.constData(), "--lecture-entry", "2"}), 0);
    QCOMPARE(QImage(image).size(), QSize(1200, 750));
    QFile::remove(image);
    // past its last scene, with scene options, without --lecture, a scene file: exit 2, no image
    QCOMPARE(run({"--lecture", file.constData(), "--lecture-entry", "4"}), 2);
    QCOMPARE(run({"--lecture", file.constData(), "--preset", "circle"}), 2);
    QCOMPARE(run({"--preset", "circle", "--lecture-entry", "2"}), 2);
    QCOMPARE(run({"--lecture", file.constData(), "--lecture-entry", "0"}), 2);
    const QString scene = m_dir.filePath(QStringLiteral("scene.json"));
    saveSceneFile(scene, presetScene("circle"));
    QCOMPARE(run({"--lecture", scene.toUtf8().constData()}), 2);
    QVERIFY(!QFile::exists(image));
}

QTEST_MAIN(TestLecture)
#include "test_lecture.moc"
