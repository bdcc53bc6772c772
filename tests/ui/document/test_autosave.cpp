// Crash recovery (docs/robustness.md, Crash recovery): the unsaved scene is copied to the XDG state
// folder a few seconds after each change; a program killed with SIGKILL leaves its copy, and the
// next start offers exactly that scene back. The killed program is this test executable itself,
// started again as "--autosave-child DIR": a window that makes one edit, waits for its copy and
// says so on stdout.
#include "document/autosave.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "scene/presets.h"
#include "scene/scene_json.h"
#include "shell/main_window.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <cstdio>
#include <cstring>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

// the edit the child makes, as a slider would: the sinusoid with b = 1.7 and a note
Scene editedScene() {
    Scene s = presetScene("sinusoid");
    s.system.params["b"] = 1.7;
    s.system.params.erase("I");
    s.note = "Lecture 3: b = 1.7";
    return s;
}

// where a window keeps its copy when XDG_STATE_HOME is `state`
QString autosaveFolder(const QTemporaryDir& state) {
    return state.path() + QStringLiteral("/chaplygin-lab/autosave");
}

QStringList copiesIn(const QString& dir) {
    return QDir(dir).entryList({QStringLiteral("window-*.json")}, QDir::Files);
}

// the child: one edit, its copy written, then the event loop until it is killed
int runChild(int argc, char** argv, const char* dir) {
    qputenv("XDG_STATE_HOME", dir);
    QApplication app(argc, argv);
    test::useTestSettings(QStringLiteral("autosave-child"));
    MainWindow window(true);
    window.show();
    window.editScene(editedScene(), QStringLiteral("Change b"));
    for (int i = 0; i < 100 && window.autosave()->file().isEmpty(); ++i)
        QTest::qWait(100);
    if (window.autosave()->file().isEmpty())
        return 1;
    std::printf("written %s\n", qPrintable(window.autosave()->file()));
    std::fflush(stdout);
    return app.exec();
}

} // namespace

class TestAutosave : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() { test::useTestSettings(QStringLiteral("autosave-tests")); }
    void copyWrittenAfterTheChangeAndGoneWhenClean();
    void killedProgramsSceneOfferedBackExactly();
    void declinedCopyIsRemoved();
    void normalEndLeavesNothing();
};

void TestAutosave::copyWrittenAfterTheChangeAndGoneWhenClean() {
    QTemporaryDir dir;
    Autosave autosave(nullptr, dir.path());
    autosave.sceneChanged(editedScene(), QStringLiteral("/lessons/three.json"));
    QVERIFY(copiesIn(dir.path()).isEmpty()); // not before the delay
    QTRY_VERIFY_WITH_TIMEOUT(!autosave.file().isEmpty(), Autosave::kDelayMs + 2000);
    QFile copy(autosave.file());
    QVERIFY(copy.open(QIODevice::ReadOnly));
    QCOMPARE(copy.readAll().toStdString(), sceneToJson(editedScene()));
    // a window that is still open has no orphan to offer to another
    Autosave other(nullptr, dir.path());
    QVERIFY(other.orphans().empty());
    autosave.discard();
    QVERIFY(copiesIn(dir.path()).isEmpty());
}

void TestAutosave::killedProgramsSceneOfferedBackExactly() {
    QTemporaryDir dir;
    QProcess child;
    child.setProgram(QCoreApplication::applicationFilePath());
    child.setArguments({QStringLiteral("--autosave-child"), dir.path()});
    child.start();
    QVERIFY(child.waitForStarted());
    QVERIFY2(child.waitForReadyRead(30000), child.readAllStandardError().constData());
    const QByteArray said = child.readAllStandardOutput();
    QVERIFY2(said.startsWith("written "), said.constData());
    const QDateTime killedAt = QDateTime::currentDateTime();
    child.kill(); // SIGKILL: no close event, no destructor
    QVERIFY(child.waitForFinished());
    QCOMPARE(child.exitStatus(), QProcess::CrashExit);
    QCOMPARE(copiesIn(autosaveFolder(dir)).size(), 1);

    qputenv("XDG_STATE_HOME", dir.path().toUtf8());
    MainWindow window(true);
    QDateTime offered;
    QVERIFY(window.offerRestore([&](const Autosave::Orphan& orphan) {
        offered = orphan.written;
        return true;
    }));
    QVERIFY(qAbs(offered.secsTo(killedAt)) < 60);
    window.document()->flush();
    QCOMPARE(sceneToJson(window.document()->scene()), sceneToJson(editedScene()));
    QVERIFY(!window.undoStack()->isClean()); // restored, not saved
    QVERIFY(window.windowTitle().contains(QLatin1Char('*')));
    // the old copy is gone; this window keeps its own until the scene is saved
    QTRY_COMPARE_WITH_TIMEOUT(copiesIn(autosaveFolder(dir)).size(), 1, Autosave::kDelayMs + 2000);
    QVERIFY(window.autosave()->file().endsWith(copiesIn(autosaveFolder(dir)).front()));
    MainWindow second(true);
    QVERIFY(!second.offerRestore([](const Autosave::Orphan&) { return true; }));
    qunsetenv("XDG_STATE_HOME");
}

void TestAutosave::declinedCopyIsRemoved() {
    QTemporaryDir dir;
    {
        // a copy whose lock is stale, as a killed program leaves it
        Autosave dead(nullptr, autosaveFolder(dir));
        dead.sceneChanged(editedScene(), {});
        QVERIFY(dead.writeNow());
        QVERIFY(QFile::copy(dead.file(),
                            QDir(autosaveFolder(dir)).filePath(QStringLiteral("window-1-0.json"))));
    }
    qputenv("XDG_STATE_HOME", dir.path().toUtf8());
    MainWindow window(true);
    const std::string before = sceneToJson(window.document()->scene());
    QVERIFY(!window.offerRestore([](const Autosave::Orphan&) { return false; }));
    QCOMPARE(sceneToJson(window.document()->scene()), before);
    QVERIFY(copiesIn(autosaveFolder(dir)).isEmpty());
    qunsetenv("XDG_STATE_HOME");
}

void TestAutosave::normalEndLeavesNothing() {
    QTemporaryDir dir;
    qputenv("XDG_STATE_HOME", dir.path().toUtf8());
    {
        MainWindow window(true);
        window.editScene(editedScene(), QStringLiteral("Change b"));
        QVERIFY(window.autosave()->writeNow());
        QCOMPARE(copiesIn(autosaveFolder(dir)).size(), 1);
        window.undoStack()->undo(); // back to the scene as loaded: nothing to keep
        QVERIFY(copiesIn(autosaveFolder(dir)).isEmpty());
        window.undoStack()->redo();
        QVERIFY(window.autosave()->writeNow());
        QCOMPARE(copiesIn(autosaveFolder(dir)).size(), 1);
    }
    QVERIFY(copiesIn(autosaveFolder(dir)).isEmpty());
    QVERIFY(QDir(autosaveFolder(dir)).entryList({QStringLiteral("*.lock")}, QDir::Files).isEmpty());
    qunsetenv("XDG_STATE_HOME");
}

int main(int argc, char** argv) {
    if (argc == 3 && std::strcmp(argv[1], "--autosave-child") == 0)
        return runChild(argc, argv, argv[2]);
    QApplication app(argc, argv);
    TestAutosave tests;
    return QTest::qExec(&tests, argc, argv);
}

#include "test_autosave.moc"
