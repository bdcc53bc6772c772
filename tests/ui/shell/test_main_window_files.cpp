// GUI tests of the main window's files, driving the real widgets under the offscreen platform:
// save and open, a bad file that keeps the scene, the exported plots and CSV, --screenshot, the
// recent files and the layout kept in the settings.
#include "desktop_entry.h"
#include "document/scene_document.h"
#include "panels/parameters_panel.h"
#include "scene/presets.h"
#include "scene/scene_json.h"
#include "shell/main_window.h"
#include "widgets/number_field.h"
#include "window_fixture.h"

#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMenu>
#include <QSettings>
#include <QSvgRenderer>
#include <QtTest>

#include <algorithm>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestMainWindowFiles : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_main_window_files_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void saveLoadRoundTrip();
    void openBadFileKeepsScene();
    void exportFilesValid();
    void exportedCsvHasNoNegativeZero();
    void screenshotMode();
    void settingsKeepRecentFilesAndLayout();
};

void TestMainWindowFiles::saveLoadRoundTrip() {
    m_window->parametersPanel()->spinBox(QStringLiteral("a"))->setValue(0.25);
    m_window->parametersPanel()->spinBox(QStringLiteral("speed"))->setValue(1.5);
    m_window->document()->flush();
    Scene saved = m_window->document()->scene();
    QString file = m_dir.filePath(QStringLiteral("scene.json"));
    QVERIFY(m_window->saveFile(file));
    QVERIFY(loadSceneFile(file.toStdString()) == saved);
    MainWindow other(false);
    QVERIFY(other.openFile(file));
    other.document()->flush();
    QVERIFY(other.document()->scene() == saved);
    QCOMPARE(other.document()->solution()->system().a, 0.25);
    QCOMPARE(other.parametersPanel()->spinBox(QStringLiteral("speed"))->value(), 1.5);
    QCOMPARE(other.document()->fileName(), file);
}

void TestMainWindowFiles::openBadFileKeepsScene() {
    QString file = m_dir.filePath(QStringLiteral("bad.json"));
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("{\"version\": 1, \"system\": ");
    f.close();
    Scene before = m_window->document()->scene();
    QVERIFY(!m_window->openFile(file));
    QVERIFY(m_window->lastFileError().contains(QStringLiteral("scene file")));
    QVERIFY(m_window->document()->scene() == before);
}

void TestMainWindowFiles::exportFilesValid() {
    QString dir = m_dir.filePath(QStringLiteral("plots"));
    QVERIFY(m_window->exportPlotsTo(
        dir, {QStringLiteral("png"), QStringLiteral("pdf"), QStringLiteral("svg")}));
    QImage png(dir + QStringLiteral("/psi.png"));
    QVERIFY(!png.isNull());
    QVERIFY(png.width() >= 900);
    QFile pdf(dir + QStringLiteral("/energy.pdf"));
    QVERIFY(pdf.open(QIODevice::ReadOnly));
    QVERIFY(pdf.read(5).startsWith("%PDF"));
    QSvgRenderer svg(dir + QStringLiteral("/lambda.svg"));
    QVERIFY(svg.isValid());
    QString csv = m_dir.filePath(QStringLiteral("run.csv"));
    QVERIFY(m_window->exportCsvTo(csv));
    QFile c(csv);
    QVERIFY(c.open(QIODevice::ReadOnly));
    // one header row and the rows, nothing a spreadsheet would show as a row of its own
    QVERIFY(c.readLine().startsWith("t,s,x,y,phi,psi,chi,lambda,energy,free_x"));
    int rows = 0;
    while (!c.atEnd()) {
        const QByteArray line = c.readLine().trimmed();
        QVERIFY2(!line.startsWith('#'), line.constData());
        rows += line.isEmpty() ? 0 : 1;
    }
    QCOMPARE(rows, 501);
    // the parameters the comment line held are in the summary beside it
    QFile summary(m_dir.filePath(QStringLiteral("run.summary.json")));
    QVERIFY(summary.open(QIODevice::ReadOnly));
    const QJsonObject s = QJsonDocument::fromJson(summary.readAll()).object();
    QCOMPARE(s.value(QStringLiteral("preset")).toString(), QStringLiteral("sinusoid"));
    QCOMPARE(s.value(QStringLiteral("b")).toDouble(), 1.0);
    QCOMPARE(s.value(QStringLiteral("parameters")).toObject().value(QStringLiteral("m")).toDouble(),
             1.0);
}

// the line preset's y, psi and lambda are zeros that arithmetic makes negative: written as 0
void TestMainWindowFiles::exportedCsvHasNoNegativeZero() {
    const auto names = presetNames();
    m_window->choosePresetNumber(
        int(std::find(names.begin(), names.end(), "line") - names.begin()));
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().preset, std::string("line"));
    const QString csv = m_dir.filePath(QStringLiteral("line.csv"));
    QVERIFY(m_window->exportCsvTo(csv));
    QFile c(csv);
    QVERIFY(c.open(QIODevice::ReadOnly));
    int zeros = 0;
    while (!c.atEnd()) {
        const QList<QByteArray> fields = c.readLine().trimmed().split(',');
        for (const QByteArray& f : fields) {
            QVERIFY2(f != "-0", "a -0 in the CSV");
            zeros += f == "0";
        }
    }
    QVERIFY(zeros > 1000);
}

void TestMainWindowFiles::screenshotMode() {
    QString file = m_dir.filePath(QStringLiteral("shot.png"));
    QByteArray f = file.toUtf8();
    const char* args[] = {"chaplygin-lab", "--screenshot", f.constData(), "--preset", "circle",
                          "--at",          "2.5",          "--size",      "1024x700"};
    QCOMPARE(runScreenshot(9, const_cast<char**>(args)), 0);
    QImage image(file);
    QVERIFY(!image.isNull());
    QCOMPARE(image.size(), QSize(1024, 700));
    // the canvas is not blank: the path and the body put colour on it
    int coloured = 0;
    for (int y = 0; y < image.height(); y += 4)
        for (int x = 0; x < image.width(); x += 4) {
            QColor c = image.pixelColor(x, y);
            coloured += c.saturation() > 80 ? 1 : 0;
        }
    QVERIFY(coloured > 200);
    const char* bad[] = {"chaplygin-lab", "--screenshot", f.constData(), "--path",
                         "y=sin(",        "--x-range",    "0,3"};
    QCOMPARE(runScreenshot(7, const_cast<char**>(bad)), 2);
    const char* late[] = {"chaplygin-lab", "--screenshot", f.constData(), "--preset",
                          "line",          "--at",         "1000"};
    QCOMPARE(runScreenshot(7, const_cast<char**>(late)), 2);
    const char* badSize[] = {"chaplygin-lab", "--screenshot", f.constData(), "--size", "big"};
    QCOMPARE(runScreenshot(5, const_cast<char**>(badSize)), 2);
}

void TestMainWindowFiles::settingsKeepRecentFilesAndLayout() {
    // only this test writes settings (the other windows are made without them)
    QCoreApplication::setApplicationName(QStringLiteral("ui_tests_settings"));
    QSettings().clear();
    QString file = m_dir.filePath(QStringLiteral("recent.json"));
    {
        MainWindow window(true);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.resize(1000, 700);
        QVERIFY(window.saveFile(file));
        QCOMPARE(window.recentMenu()->actions().size(), 1);
        window.findChild<QDockWidget*>(QStringLiteral("plotsDock"))->hide();
        window.close();
    }
    MainWindow again(true);
    QCOMPARE(again.recentMenu()->actions().size(), 1);
    QCOMPARE(again.recentMenu()->actions().first()->toolTip(), QFileInfo(file).absoluteFilePath());
    QCOMPARE(again.size(), QSize(1000, 700));
    QVERIFY(!again.findChild<QDockWidget*>(QStringLiteral("plotsDock"))->isVisibleTo(&again));
    QSettings().clear();
}

QTEST_MAIN(TestMainWindowFiles)
#include "test_main_window_files.moc"
