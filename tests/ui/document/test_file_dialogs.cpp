// File dialogs: a proposed name with the extension added, the last folder per purpose, the
// extension of the chosen filter and the file stems of scenes. Offscreen, real widgets.
#include "window_fixture.h"

#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestFileDialogs : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_file_dialogs_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void saveProposesNameAndAddsExtension();
    void dialogsRememberLastFolder();
    void firstDialogOfAKindStartsInTheFolderJustUsed();
    void filterExtensionAndStems();
};

void TestFileDialogs::saveProposesNameAndAddsExtension() {
    choosePreset("catenary");
    test::DialogScript dialog;
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
    QVERIFY(csv.readLine().startsWith("t,s,x,y,"));
    QVERIFY(QFile::exists(m_dir.filePath(QStringLiteral("table.summary.json"))));
}

void TestFileDialogs::dialogsRememberLastFolder() {
    QTemporaryDir other;
    test::DialogScript dialog;
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
    // a kind not used yet starts in the last folder used at all
    QCOMPARE(lastFolder(QStringLiteral("csv")), QFileInfo(other.path()).absoluteFilePath());
    // a kind used keeps its own folder when another kind goes elsewhere
    QTemporaryDir tables;
    dialog.answer = QDir(tables.path()).filePath(QStringLiteral("t.csv"));
    chooseSaveFile(nullptr, QStringLiteral("Export CSV"), QStringLiteral("csv"),
                   QStringLiteral("t"), QStringLiteral("CSV (*.csv)"));
    QCOMPARE(lastFolder(QStringLiteral("csv")), QFileInfo(tables.path()).absoluteFilePath());
    QCOMPARE(lastFolder(QStringLiteral("scene")), QFileInfo(other.path()).absoluteFilePath());
    // a cancelled dialog changes nothing
    QTemporaryDir third;
    dialog.answer.clear();
    QVERIFY(chooseSaveFile(nullptr, QStringLiteral("Save"), QStringLiteral("scene"),
                           QStringLiteral("z"), QStringLiteral("Scenes (*.json)"))
                .isEmpty());
    QCOMPARE(lastFolder(QStringLiteral("scene")), QFileInfo(other.path()).absoluteFilePath());
    QCOMPARE(lastFolder(QStringLiteral("plots")), QFileInfo(tables.path()).absoluteFilePath());
}

// the first Export CSV after a save, and the first Save As after opening a file from the recent
// list or the command line, start in the folder just used, not in Documents or home
void TestFileDialogs::firstDialogOfAKindStartsInTheFolderJustUsed() {
    QTemporaryDir lecture, runs;
    test::DialogScript dialog;
    dialog.install();
    dialog.answer = QDir(lecture.path()).filePath(QStringLiteral("lecture.json"));
    dialog.filter = QStringLiteral("Scenes (*.json)");
    QAction* saveAs = nullptr;
    for (QAction* a : m_window->findChildren<QAction*>())
        if (a->text().startsWith(QStringLiteral("Save &As")))
            saveAs = a;
    QVERIFY(saveAs);
    saveAs->trigger();
    QCOMPARE(dialog.calls, 1);
    QVERIFY(QFile::exists(dialog.answer));
    dialog.answer.clear(); // cancel the next dialogs
    QTest::keyClick(m_window.get(), Qt::Key_E, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(dialog.calls, 2);
    QCOMPARE(QFileInfo(dialog.proposed).absolutePath(),
             QFileInfo(lecture.path()).absoluteFilePath());
    // a scene opened without a dialog: the next Save As starts beside it
    const QString opened = QDir(runs.path()).filePath(QStringLiteral("opened.json"));
    QVERIFY(QFile::copy(QDir(lecture.path()).filePath(QStringLiteral("lecture.json")), opened));
    QSettings().clear();
    QVERIFY(m_window->openFile(opened));
    saveAs->trigger();
    QCOMPARE(dialog.calls, 3);
    QCOMPARE(
        dialog.proposed,
        QDir(QFileInfo(runs.path()).absoluteFilePath()).filePath(QStringLiteral("opened.json")));
    QTest::keyClick(m_window.get(), Qt::Key_E, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(QFileInfo(dialog.proposed).absolutePath(), QFileInfo(runs.path()).absoluteFilePath());
}

void TestFileDialogs::filterExtensionAndStems() {
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

QTEST_MAIN(TestFileDialogs)
#include "test_file_dialogs.moc"
