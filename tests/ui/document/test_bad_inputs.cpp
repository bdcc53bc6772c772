// GUI side of docs/robustness.md: bad input typed, chosen or opened through the real widgets shows
// an inline message naming the place, keeps the last valid scene, solution and plots, and never
// opens a modal dialog; saving under faults tells the user and keeps the old file and the '*'.
#include "canvas/scene_canvas.h"
#include "document/scene_document.h"
#include "fault_injection.h"
#include "gui_test_support.h"
#include "panels/parameters_panel.h"
#include "panels/path_panel.h"
#include "plots/plots_panel.h"
#include "scene/presets.h"
#include "scene/scene_json.h"
#include "shell/main_window.h"
#include "widgets/number_field.h"

#include <QComboBox>
#include <QDialog>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>
#include <qcustomplot.h>

#include <algorithm>
#include <memory>
#include <string>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

QVector<double> graphValues(QCustomPlot* plot) {
    QVector<double> v;
    for (const QCPGraphData& d : *plot->graph(0)->data())
        v << d.value;
    return v;
}

/// What must survive a rejected input.
struct Snapshot {
    std::shared_ptr<const Solution> solution;
    Scene scene;
    QVector<double> psi;
    int undoCount = 0;
};

/// A drawn path with a pivot corner at (1, 0), in the constant-energy mode.
Scene cornerScene() {
    Scene s = presetScene("line");
    s.path.kind = PathKind::Polyline;
    s.path.points = {{0, 0}, {1, 0}, {1, 1}};
    s.path.corners = CornerMode::Pivot;
    return s;
}

} // namespace

class TestBadInputs : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase();
    void init();
    void cleanup();

    void badGraphExpression_data();
    void badGraphExpression();
    void parametricCusp();
    void reversedRange();
    void badParameter_data();
    void badParameter();
    void negativeInertiaIsRefused();
    void diskZeroRadius();
    void speedModeAtPivotCorner();
    void openBadSceneFile_data();
    void openBadSceneFile();
    void openMissingFileOrDirectory();
    void openUnsolvableSceneKeepsScene();
    void saveRefusedWhileSceneFails();
    void saveToMissingDirectory();
    void saveOverDirectory();
    void saveOnFullDiskKeepsOldFile();
    void saveToFullDevice();
    void exportCsvUnderFaults();
    void exportPlotsUnderFaults();

  private:
    Snapshot snapshot() const;
    /// Verifies that the last valid solution, the plots and the undo stack are as before; the
    /// document's scene too unless only the solution is checked.
    void verifyKept(const Snapshot& before, bool sceneToo = true) const;
    void verifyNoModal() const;
    void typePath(const QString& text, double from, double to);
    void makeUnsaved();

    std::unique_ptr<MainWindow> m_window;
    QTemporaryDir m_dir;
};

void TestBadInputs::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_bad_input_tests"));
    QVERIFY(m_dir.isValid());
}

void TestBadInputs::init() {
    m_window = test::showTestWindow();
    QVERIFY(m_window && m_window->document()->solution());
}

void TestBadInputs::cleanup() {
    m_window.reset();
}

Snapshot TestBadInputs::snapshot() const {
    m_window->document()->flush();
    return {m_window->document()->solution(), m_window->document()->scene(),
            graphValues(m_window->plotsPanel()->plot(0)), m_window->undoStack()->count()};
}

void TestBadInputs::verifyKept(const Snapshot& before, bool sceneToo) const {
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution(), before.solution);
    QVERIFY(m_window->document()->solution()->scene() == before.solution->scene());
    if (sceneToo) {
        QVERIFY2(m_window->document()->scene() == before.scene, "the last valid scene stays");
        QCOMPARE(m_window->undoStack()->count(), before.undoCount);
    }
    QCOMPARE(graphValues(m_window->plotsPanel()->plot(0)), before.psi);
    verifyNoModal();
}

void TestBadInputs::verifyNoModal() const {
    QVERIFY(!QApplication::activeModalWidget());
    for (QWidget* w : QApplication::topLevelWidgets())
        QVERIFY2(!(w->isVisible() && qobject_cast<QDialog*>(w)), "no dialog pops up");
}

void TestBadInputs::typePath(const QString& text, double from, double to) {
    PathPanel* panel = m_window->pathPanel();
    QLineEdit* edit = panel->graphEdit();
    panel->fromSpin()->setValue(from);
    panel->toSpin()->setValue(to);
    edit->selectAll();
    QTest::keyClick(edit, Qt::Key_Delete);
    bool ascii = std::all_of(text.begin(), text.end(), [](QChar c) { return c.unicode() < 128; });
    if (ascii && text.size() <= 100)
        QTest::keyClicks(edit, text);
    else
        edit->insert(text); // as a paste or an input method (QTest types only ASCII keys)
    QCOMPARE(edit->text(), text);
    QTest::keyClick(edit, Qt::Key_Return);
    m_window->document()->flush(); // a slow path is built on the worker
}

void TestBadInputs::makeUnsaved() {
    m_window->parametersPanel()->spinBox(QStringLiteral("m"))->setValue(2.0);
    m_window->document()->flush();
    QVERIFY(m_window->windowTitle().contains(QLatin1Char('*')));
}

void TestBadInputs::badGraphExpression_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<double>("from");
    QTest::addColumn<double>("to");
    QTest::addColumn<QString>("expected");
    QTest::newRow("missing paren") << "sin(x" << 0.0 << 1.0 << "position";
    QTest::newRow("unknown function")
        << "foo(x)" << 0.0 << 1.0 << "y(x), position 1: unknown name 'foo'";
    QTest::newRow("assignment") << "x=5" << 0.0 << 1.0 << "y(x), position 2";
    QTest::newRow("quoted assignment") << "'x=5'" << 0.0 << 1.0 << "y(x), position 1";
    QTest::newRow("logic UB") << "1/0&&2" << 0.0 << 1.0 << "position 4: character '&'";
    QTest::newRow("non-ASCII") << QStringLiteral("2\u03c0x") << 0.0 << 1.0
                               << "position 2: non-ASCII";
    QTest::newRow("empty") << "" << 0.0 << 1.0 << "empty";
    QTest::newRow("1/x at 0") << "1/x" << 0.0 << 1.0 << "path at x = 0";
    QTest::newRow("sqrt below 0") << "sqrt(x)" << -1.0 << 1.0 << "path at x = -1";
    QTest::newRow("ln at 0") << "ln(x)" << 0.0 << 2.0 << "path at x = 0";
    QTest::newRow("huge exponent")
        << "0e112222222222" << 0.0 << 1.0 << "the number '0e112222222222' is out of range";
    QTest::newRow("overflow") << "10^400*x" << 0.0 << 1.0 << "overflows";
    QTest::newRow("overflowing power")
        << "exp((x^(2+(x)^(1123356))*+2)^(2^(11233523356))*x)" << 0.0 << 1.0
        << "position 31: a constant overflows double precision";
    QString product = QStringLiteral("x");
    for (int i = 1; i < 400; ++i)
        product += QStringLiteral("*(x+%1)").arg(i);
    QTest::newRow("product of 400 factors")
        << product << 0.0 << 1.0 << "too complex to differentiate";
    QTest::newRow("20000 characters") << QStringLiteral("1+").repeated(9999) + QStringLiteral("x")
                                      << 0.0 << 1.0 << "characters long";
    QTest::newRow("3000 nested parentheses")
        << QStringLiteral("(").repeated(3000) + QStringLiteral("x") +
               QStringLiteral(")").repeated(3000)
        << 0.0 << 1.0 << "6001 characters long; the limit is 4000";
    QTest::newRow("150 nested parentheses")
        << QStringLiteral("(").repeated(150) + QStringLiteral("x") +
               QStringLiteral(")").repeated(150)
        << 0.0 << 1.0 << "nested deeper";
}

void TestBadInputs::badGraphExpression() {
    QFETCH(QString, text);
    QFETCH(double, from);
    QFETCH(double, to);
    QFETCH(QString, expected);
    Snapshot before = snapshot();
    typePath(text, from, to);
    PathPanel* panel = m_window->pathPanel();
    QVERIFY(panel->findChild<QLabel*>(QStringLiteral("pathError"))->isVisible());
    QVERIFY2(panel->errorText().contains(expected), qPrintable(panel->errorText()));
    verifyKept(before);
    // the user's text stays in the field to be corrected
    QCOMPARE(panel->graphEdit()->text(), text);
}

void TestBadInputs::parametricCusp() {
    Snapshot before = snapshot();
    PathPanel* panel = m_window->pathPanel();
    panel->parametricButton()->click();
    // x = u^2, y = u^4 stops and retraces itself at u = 0: refused, naming the place
    panel->xOfUEdit()->setText(QStringLiteral("u^2"));
    panel->yOfUEdit()->setText(QStringLiteral("u^4"));
    panel->fromSpin()->setValue(-1);
    panel->toSpin()->setValue(1);
    panel->applyButton()->click();
    m_window->document()->flush();
    QVERIFY2(panel->errorText().contains(QStringLiteral("path at u = 0")),
             qPrintable(panel->errorText()));
    verifyKept(before);
    // x = u^2, y = u^3 has a cusp the sleigh backs up through (docs/physics.md §3)
    panel->yOfUEdit()->setText(QStringLiteral("u^3"));
    panel->applyButton()->click();
    m_window->document()->flush();
    QVERIFY2(panel->errorText().isEmpty(), qPrintable(panel->errorText()));
    QCOMPARE(m_window->document()->solution()->path()->pieces().size(), std::size_t(2));
}

void TestBadInputs::reversedRange() {
    // an empty range is refused; a reversed one runs from right to left
    Snapshot before = snapshot();
    typePath(QStringLiteral("x^2"), 1.5, 1.5);
    QString error = m_window->pathPanel()->errorText();
    QVERIFY2(error.contains(QStringLiteral("range")) && error.contains(QStringLiteral("1.5")),
             qPrintable(error));
    verifyKept(before);
    typePath(QStringLiteral("x^2"), 2.0, 1.0);
    QVERIFY2(m_window->pathPanel()->errorText().isEmpty(),
             qPrintable(m_window->pathPanel()->errorText()));
    const Path& path = *m_window->document()->solution()->path();
    QCOMPARE(path.start().x, 2.0);
    QCOMPARE(path.end().x, 1.0);
}

void TestBadInputs::badParameter_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("expected");
    QTest::newRow("b below |a|") << "b" << 0.2 << "parameter b: must be >= |a| = 0.5";
    QTest::newRow("m = 0") << "m" << 0.0 << "parameter m: must be > 0";
    QTest::newRow("m = -1") << "m" << -1.0 << "parameter m: must be > 0";
}

void TestBadInputs::badParameter() {
    QFETCH(QString, name);
    QFETCH(double, value);
    QFETCH(QString, expected);
    Snapshot before = snapshot();
    NumberField* spin = m_window->parametersPanel()->spinBox(name);
    QVERIFY(spin);
    spin->setValue(value);
    ParametersPanel* panel = m_window->parametersPanel();
    QVERIFY(panel->findChild<QLabel*>(QStringLiteral("parameterError"))->isVisible());
    QVERIFY2(panel->errorText().contains(expected), qPrintable(panel->errorText()));
    verifyKept(before);
}

void TestBadInputs::negativeInertiaIsRefused() {
    ParametersPanel* panel = m_window->parametersPanel();
    QComboBox* gyration = panel->findChildren<QComboBox*>().at(1);
    gyration->setCurrentIndex(1);
    emit gyration->activated(1);
    m_window->document()->flush();
    NumberField* inertia = panel->spinBox(QStringLiteral("I"));
    QVERIFY(inertia);
    const Scene before = m_window->document()->scene();
    // typed, I < 0 is refused by the field with its bound, never clamped to it
    auto type = [inertia](const char* text) {
        inertia->setFocus();
        inertia->selectAll();
        QTest::keyClicks(inertia, QString::fromLatin1(text));
        QTest::keyClick(inertia, Qt::Key_Return);
    };
    type("-0.1");
    m_window->document()->flush();
    QVERIFY2(panel->errorText().contains(QStringLiteral("I must be at least 0 kg m\u00b2")),
             qPrintable(panel->errorText()));
    QCOMPARE(m_window->document()->scene(), before);
    QCOMPARE(inertia->value(), 0.75);
    // the bound itself is allowed and solves (b = |a|)
    type("0");
    m_window->document()->flush();
    QVERIFY2(panel->errorText().isEmpty(), qPrintable(panel->errorText()));
    QCOMPARE(m_window->document()->solution()->system().b, 0.5);
}

void TestBadInputs::diskZeroRadius() {
    ParametersPanel* panel = m_window->parametersPanel();
    QComboBox* system = panel->findChildren<QComboBox*>().at(0);
    system->setCurrentIndex(1);
    emit system->activated(1);
    Snapshot before = snapshot();
    QCOMPARE(before.solution->scene().system.kind, SystemKind::Disk);
    panel->spinBox(QStringLiteral("R"))->setValue(0.0);
    QVERIFY2(panel->errorText().contains(QStringLiteral("parameter R")),
             qPrintable(panel->errorText()));
    verifyKept(before);
}

void TestBadInputs::speedModeAtPivotCorner() {
    // a drawn path with pivot corners, then the constant-speed mode, which cannot turn in place
    m_window->pathPanel()->cornersBox()->setCurrentIndex(1);
    m_window->pathPanel()->drawButton()->click();
    SceneCanvas* canvas = m_window->canvas();
    test::dragStroke(canvas, QPoint(100, 300),
                     {QPoint(250, 300), QPoint(400, 300), QPoint(400, 150)}, QPoint(400, 100));
    Snapshot before = snapshot();
    QVERIFY(before.solution->path()->pivotCount() > 0);
    QComboBox* mode = m_window->parametersPanel()->findChildren<QComboBox*>().at(2);
    mode->setCurrentIndex(1);
    emit mode->activated(1);
    m_window->document()->flush();
    QString error = m_window->parametersPanel()->errorText();
    QVERIFY2(error.contains(QStringLiteral("corner at (")), qPrintable(error));
    // the chosen mode stays chosen (one undo step away) while the last valid solution is drawn
    verifyKept(before, false);
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QVERIFY(m_window->document()->scene() == before.scene);
    QVERIFY(m_window->parametersPanel()->errorText().isEmpty());
}

void TestBadInputs::openBadSceneFile_data() {
    std::string valid = sceneToJson(presetScene("line"));
    auto replaced = [&](const std::string& what, const std::string& with) {
        std::string s = valid;
        auto at = s.find(what);
        if (at != std::string::npos)
            s.replace(at, what.size(), with);
        return QByteArray::fromStdString(s);
    };
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("expected");
    QTest::newRow("empty") << QByteArray() << "scene file /: the file is empty";
    QTest::newRow("truncated") << QByteArray::fromStdString(valid.substr(0, valid.size() / 2))
                               << "not valid JSON";
    QTest::newRow("binary") << QByteArray("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16)
                            << "NUL byte at offset 8";
    QTest::newRow("wrong type") << replaced("\"m\": 1.0", "\"m\": \"heavy\"")
                                << "/system/params/m: must be a number";
    QTest::newRow("future version")
        << replaced("\"version\": 1", "\"version\": 99") << "/version: the file is version 99";
    QTest::newRow("BOM") << QByteArray("\xEF\xBB\xBF") + QByteArray::fromStdString(valid)
                         << "byte-order mark";
    QTest::newRow("invalid UTF-8")
        << replaced("\"line\"", "\"li\xff\xfene\"") << "ill-formed UTF-8";
    QTest::newRow("NaN") << replaced("\"m\": 1.0", "\"m\": NaN") << "not valid JSON";
    QTest::newRow("deeply nested")
        << QByteArray(100, '[') + QByteArray(100, ']') << "nested deeper than 32 levels";
}

void TestBadInputs::openBadSceneFile() {
    QFETCH(QByteArray, bytes);
    QFETCH(QString, expected);
    QString file = m_dir.filePath(QStringLiteral("bad_%1.json").arg(QTest::currentDataTag()));
    QVERIFY(writeBytes(file, bytes));
    makeUnsaved();
    Snapshot before = snapshot();
    QString title = m_window->windowTitle();
    QVERIFY(!m_window->openFile(file));
    QString error = m_window->lastFileError();
    qInfo().noquote() << error;
    QVERIFY2(error.contains(expected), qPrintable(error));
    QVERIFY2(m_window->statusBar()->currentMessage() == error, "the user is told");
    verifyKept(before);
    QCOMPARE(m_window->windowTitle(), title);
    QVERIFY(m_window->document()->fileName().isEmpty());
}

void TestBadInputs::openMissingFileOrDirectory() {
    Snapshot before = snapshot();
    for (const QString& path : {m_dir.filePath(QStringLiteral("nowhere.json")), m_dir.path()}) {
        QVERIFY(!m_window->openFile(path));
        qInfo().noquote() << m_window->lastFileError();
        QVERIFY2(m_window->lastFileError().contains(path), qPrintable(m_window->lastFileError()));
        verifyKept(before);
    }
}

void TestBadInputs::openUnsolvableSceneKeepsScene() {
    // well-formed, but the constant-speed mode cannot turn the pivot corner: rejected at load
    Scene corner = cornerScene();
    corner.mode = SpeedMode::Speed;
    QString file = m_dir.filePath(QStringLiteral("corner.json"));
    QVERIFY(writeBytes(file, QByteArray::fromStdString(sceneToJson(corner))));
    Snapshot before = snapshot();
    QVERIFY(!m_window->openFile(file));
    QVERIFY2(m_window->lastFileError().contains(QStringLiteral("corner at (1, 0)")),
             qPrintable(m_window->lastFileError()));
    verifyKept(before);
    QVERIFY(m_window->document()->error().isEmpty());
    QVERIFY(m_window->document()->fileName().isEmpty());
}

void TestBadInputs::saveRefusedWhileSceneFails() {
    // a drawn path with pivot corners, saved; then the constant-speed mode, which fails to solve
    Scene corner = cornerScene();
    QString file = m_dir.filePath(QStringLiteral("corner.json"));
    QVERIFY(writeBytes(file, QByteArray::fromStdString(sceneToJson(corner))));
    QVERIFY(m_window->openFile(file));
    QByteArray old = readAll(file);
    QComboBox* mode = m_window->parametersPanel()->findChildren<QComboBox*>().at(2);
    mode->setCurrentIndex(1);
    emit mode->activated(1);
    m_window->document()->flush();
    QVERIFY(!m_window->document()->error().isEmpty());
    QVERIFY(!m_window->saveFile(file));
    QVERIFY2(m_window->lastFileError().contains(QStringLiteral("does not solve")) &&
                 m_window->lastFileError().contains(QStringLiteral("corner at (1, 0)")),
             qPrintable(m_window->lastFileError()));
    QCOMPARE(readAll(file), old);
    QVERIFY(m_window->windowTitle().contains(QLatin1Char('*')));
    verifyNoModal();
    m_window->undoStack()->undo();
    QVERIFY(m_window->saveFile(file));
}

void TestBadInputs::saveToMissingDirectory() {
    makeUnsaved();
    QString file = m_dir.filePath(QStringLiteral("no/such/dir/scene.json"));
    QVERIFY(!m_window->saveFile(file));
    QVERIFY2(m_window->lastFileError().contains(file), qPrintable(m_window->lastFileError()));
    QCOMPARE(m_window->statusBar()->currentMessage(), m_window->lastFileError());
    QVERIFY(m_window->windowTitle().contains(QLatin1Char('*')));
    QVERIFY(!m_window->undoStack()->isClean());
    QVERIFY(m_window->document()->fileName().isEmpty());
    QVERIFY(!QFile::exists(file));
    verifyNoModal();
}

void TestBadInputs::saveOverDirectory() {
    makeUnsaved();
    QString dir = m_dir.filePath(QStringLiteral("a_directory"));
    QVERIFY(QDir().mkpath(dir));
    QVERIFY(!m_window->saveFile(dir));
    QVERIFY2(m_window->lastFileError().contains(QStringLiteral("directory")),
             qPrintable(m_window->lastFileError()));
    QVERIFY(m_window->windowTitle().contains(QLatin1Char('*')));
    QVERIFY(QFileInfo(dir).isDir());
    verifyNoModal();
}

void TestBadInputs::saveOnFullDiskKeepsOldFile() {
    // a saved scene, then a change, then a save that runs out of space half-way
    QString file = m_dir.filePath(QStringLiteral("lecture.json"));
    QVERIFY(m_window->saveFile(file));
    QByteArray old = readAll(file);
    QVERIFY(old.size() > 200);
    makeUnsaved();
    {
        FileSizeLimit limit(64);
        if (!limit.ok())
            QSKIP("setrlimit(RLIMIT_FSIZE) is not allowed here: no full disk to simulate");
        QVERIFY(!m_window->saveFile(file));
    }
    QString error = m_window->lastFileError();
    QVERIFY2(error.contains(file) && error.contains(QStringLiteral("short write")),
             qPrintable(error));
    QCOMPARE(readAll(file), old);
    QCOMPARE(QDir(m_dir.path()).entryList({QStringLiteral("lecture.json.tmp*")}).size(), 0);
    QVERIFY(m_window->windowTitle().contains(QLatin1Char('*')));
    QCOMPARE(m_window->document()->fileName(), file);
    verifyNoModal();
    // once there is room again the same command succeeds
    QVERIFY(m_window->saveFile(file));
    QVERIFY(!m_window->windowTitle().contains(QLatin1Char('*')));
}

void TestBadInputs::saveToFullDevice() {
    QTemporaryDir dir;
    QString full = dir.filePath(QStringLiteral("scene.json"));
    QString why;
    if (!makeFullDevice(full, &why))
        QSKIP(qPrintable(why));
    makeUnsaved();
    QVERIFY(!m_window->saveFile(full));
    QVERIFY2(m_window->lastFileError().contains(QStringLiteral("No space left")),
             qPrintable(m_window->lastFileError()));
    QVERIFY(m_window->windowTitle().contains(QLatin1Char('*')));
    QVERIFY(m_window->document()->fileName().isEmpty());
    verifyNoModal();
}

void TestBadInputs::exportCsvUnderFaults() {
    QString csv = m_dir.filePath(QStringLiteral("run.csv"));
    QVERIFY(m_window->exportCsvTo(csv));
    QByteArray old = readAll(csv);
    QVERIFY(old.size() > 1000);
    makeUnsaved();
    QVERIFY(!m_window->exportCsvTo(m_dir.filePath(QStringLiteral("missing/run.csv"))));
    QVERIFY(m_window->lastFileError().contains(QStringLiteral("missing/run.csv")));
    {
        FileSizeLimit limit(256);
        if (!limit.ok())
            QSKIP("setrlimit(RLIMIT_FSIZE) is not allowed here: no full disk to simulate");
        QVERIFY(!m_window->exportCsvTo(csv));
    }
    QVERIFY2(m_window->lastFileError().contains(QStringLiteral("short write")),
             qPrintable(m_window->lastFileError()));
    QCOMPARE(readAll(csv), old);
    QTemporaryDir dir;
    QString full = dir.filePath(QStringLiteral("run.csv"));
    if (makeFullDevice(full)) {
        QVERIFY(!m_window->exportCsvTo(full));
        QVERIFY(m_window->lastFileError().contains(QStringLiteral("No space left")));
    }
    // an export is not a save: the scene is still unsaved
    QVERIFY(m_window->windowTitle().contains(QLatin1Char('*')));
    verifyNoModal();
}

void TestBadInputs::exportPlotsUnderFaults() {
    QString plots = m_dir.filePath(QStringLiteral("plots"));
    QStringList png{QStringLiteral("png")};
    QVERIFY(m_window->exportPlotsTo(plots, png));
    QByteArray old = readAll(plots + QStringLiteral("/psi.png"));
    QVERIFY(!old.isEmpty());
    // the target directory is a file
    QString notDir = m_dir.filePath(QStringLiteral("plain_file"));
    QVERIFY(writeBytes(notDir, "x"));
    QVERIFY(!m_window->exportPlotsTo(notDir, png));
    QVERIFY2(m_window->lastFileError().contains(QStringLiteral("plot directory")),
             qPrintable(m_window->lastFileError()));
    {
        FileSizeLimit limit(512);
        if (!limit.ok())
            QSKIP("setrlimit(RLIMIT_FSIZE) is not allowed here: no full disk to simulate");
        QVERIFY(!m_window->exportPlotsTo(plots, png));
    }
    QVERIFY2(m_window->lastFileError().contains(QStringLiteral("psi.png")),
             qPrintable(m_window->lastFileError()));
    QCOMPARE(readAll(plots + QStringLiteral("/psi.png")), old);
    QTemporaryDir dir;
    if (makeFullDevice(dir.filePath(QStringLiteral("psi.png")))) {
        QVERIFY(!m_window->exportPlotsTo(dir.path(), png));
        QVERIFY(m_window->lastFileError().contains(QStringLiteral("No space left")));
    }
    verifyNoModal();
}

QTEST_MAIN(TestBadInputs)
#include "test_bad_inputs.moc"
