// GUI tests of scene links: File > Copy link puts the scene's chaplygin-lab: link on the
// clipboard, File > Open link reads one, and a damaged or hostile link never replaces the scene.
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "scene/presets.h"
#include "scene/scene_json.h"
#include "scene/scene_link.h"
#include "shell/main_window.h"

#include <QAction>
#include <QClipboard>
#include <QGuiApplication>
#include <QInputDialog>
#include <QTimer>
#include <QUndoStack>
#include <QtTest>

#include <zlib.h>

#include <memory>
#include <string>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

// a link that zlib and a base64url encoder written here make of any bytes
QString linkHolding(const std::string& bytes) {
    uLongf size = compressBound(static_cast<uLong>(bytes.size()));
    std::string compressed(size, '\0');
    compress2(reinterpret_cast<Bytef*>(compressed.data()), &size,
              reinterpret_cast<const Bytef*>(bytes.data()), static_cast<uLong>(bytes.size()), 9);
    compressed.resize(size);
    const QByteArray encoded =
        QByteArray(compressed.data(), qsizetype(compressed.size()))
            .toBase64(QByteArray::Base64UrlEncoding | QByteArray::OmitTrailingEquals);
    return QStringLiteral("chaplygin-lab:") + QString::fromLatin1(encoded);
}

QAction* fileAction(MainWindow* window, const char* name) {
    return window->findChild<QAction*>(QString::fromLatin1(name));
}

} // namespace

class TestSceneLinks : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase();
    void init();
    void cleanup();

    void copyLinkPutsTheSceneOnTheClipboard();
    void openLinkLoadsTheSceneAsANewDocument();
    void openLinkDialogOffersTheClipboardsLink();
    void badLinksKeepTheScene_data();
    void badLinksKeepTheScene();
    void copyLinkRefusesAnUnsolvedScene();

  private:
    std::unique_ptr<MainWindow> m_window;
};

void TestSceneLinks::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_link_tests"));
}

void TestSceneLinks::init() {
    m_window = test::showTestWindow();
    QVERIFY(m_window && m_window->document()->solution());
}

void TestSceneLinks::cleanup() {
    m_window.reset();
}

void TestSceneLinks::copyLinkPutsTheSceneOnTheClipboard() {
    m_window->loadScene(presetScene("catenary"));
    QGuiApplication::clipboard()->clear();
    QAction* copy = fileAction(m_window.get(), "copyLinkAction");
    QVERIFY(copy);
    QCOMPARE(copy->shortcut(), QKeySequence(QStringLiteral("Ctrl+Shift+C")));
    copy->trigger();
    const QString link = QGuiApplication::clipboard()->text();
    QVERIFY2(link.startsWith(QStringLiteral("chaplygin-lab:")), qPrintable(link.left(40)));
    QVERIFY(link.size() < 2000);
    QVERIFY(sceneFromLink(link.toStdString()) == m_window->document()->scene());
    // the key does it as well, from the canvas
    QGuiApplication::clipboard()->clear();
    QTest::keyClick(m_window.get(), Qt::Key_C, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(QGuiApplication::clipboard()->text(), link);
}

void TestSceneLinks::openLinkLoadsTheSceneAsANewDocument() {
    Scene circle = presetScene("circle");
    circle.system.params["m"] = 2.5;
    const QString link = QString::fromStdString(sceneToLink(circle));
    QVERIFY(m_window->openLink(link));
    m_window->document()->flush();
    QVERIFY(m_window->document()->scene() == circle);
    QCOMPARE(m_window->document()->solution()->system().mass, 2.5);
    QVERIFY(m_window->document()->fileName().isEmpty());
    QVERIFY(m_window->undoStack()->isClean());
}

void TestSceneLinks::openLinkDialogOffersTheClipboardsLink() {
    const Scene line = presetScene("line");
    const QString link = QString::fromStdString(sceneToLink(line));
    QGuiApplication::clipboard()->setText(link);
    QString offered;
    QTimer::singleShot(0, this, [&offered] {
        auto* dialog = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
        QVERIFY(dialog);
        offered = dialog->textValue();
        dialog->accept();
    });
    QAction* open = fileAction(m_window.get(), "openLinkAction");
    QVERIFY(open);
    open->trigger();
    QCOMPARE(offered, link);
    m_window->document()->flush();
    QVERIFY(m_window->document()->scene() == line);
}

void TestSceneLinks::badLinksKeepTheScene_data() {
    QTest::addColumn<QString>("link");
    QTest::addColumn<QString>("expected");
    const QString good = QString::fromStdString(sceneToLink(presetScene("line")));
    QTest::newRow("truncated") << good.left(good.size() / 2) << "truncated";
    QString plus = good;
    plus[20] = QLatin1Char('+');
    QTest::newRow("not base64url") << plus << "character '+' at position 21";
    QTest::newRow("another scheme") << "https://example.org/scene.json"
                                    << "'https:' is another scheme";
    QTest::newRow("empty") << "chaplygin-lab:"
                           << "nothing follows";
    QTest::newRow("noise") << "chaplygin-lab:q83vEjRWeJq83vEjRWeJq83vEjRWeJ"
                           << "damaged";
    QTest::newRow("bomb") << linkHolding(std::string(32u << 20, ' ')) << "decompression bomb";
    QTest::newRow("future version")
        << linkHolding(R"({"format": "chaplygin-lab-scene", "version": 99})") << "/version";
    // a scene that reads but does not solve: the window's own check refuses it
    std::string negativeMass = sceneToJson(presetScene("line"));
    const std::string mass = "\"m\": 1.0";
    QVERIFY(negativeMass.find(mass) != std::string::npos);
    negativeMass.replace(negativeMass.find(mass), mass.size(), "\"m\": -1.0");
    QTest::newRow("mass below zero") << linkHolding(negativeMass) << "must be > 0";
}

void TestSceneLinks::badLinksKeepTheScene() {
    QFETCH(QString, link);
    QFETCH(QString, expected);
    Scene sinusoid = presetScene("sinusoid");
    sinusoid.system.params["a"] = 0.3;
    m_window->editScene(sinusoid, QStringLiteral("a"));
    m_window->document()->flush();
    const Scene before = m_window->document()->scene();
    const int undoSteps = m_window->undoStack()->count();
    QElapsedTimer clock;
    clock.start();
    QVERIFY(!m_window->openLink(link));
    QVERIFY2(clock.elapsed() < 1000, qPrintable(QString::number(clock.elapsed())));
    QVERIFY2(m_window->lastFileError().contains(expected), qPrintable(m_window->lastFileError()));
    m_window->document()->flush();
    QVERIFY(m_window->document()->scene() == before);
    QCOMPARE(m_window->undoStack()->count(), undoSteps);
    QVERIFY(m_window->document()->error().isEmpty());
}

void TestSceneLinks::copyLinkRefusesAnUnsolvedScene() {
    Scene broken = m_window->document()->scene();
    broken.system.params["m"] = -1;
    m_window->editScene(broken, QStringLiteral("m"));
    m_window->document()->flush();
    QVERIFY(!m_window->document()->error().isEmpty());
    QGuiApplication::clipboard()->setText(QStringLiteral("before"));
    QVERIFY(!m_window->copyLink());
    QCOMPARE(QGuiApplication::clipboard()->text(), QStringLiteral("before"));
    QVERIFY(m_window->lastFileError().contains(QStringLiteral("does not solve")));
}

QTEST_MAIN(TestSceneLinks)
#include "test_scene_links.moc"
