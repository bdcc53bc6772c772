// Exports as a new user meets them: the dialogs propose folders that exist, each export says where
// its files went, exported plots show the pinned runs, and an animation draws what the canvas
// shows.
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

class TestExports : public QObject, public test::WindowFixture {
    Q_OBJECT
  private slots:
    void initTestCase() { startSuite("ui_exports_tests"); }
    void init() { openWindowWithOwnSettings("ui_exports_tests"); }
    void cleanup() {
        ExportReport::setOpenUrlHook({});
        closeWindow();
    }

    void dialogsProposeAFolderThatExists();
    void exportsSayWhereTheFilesWent();
    void exportedPlotsShowThePinnedRuns();
    void animationDialogProposesAFileInAFolderThatExists();
    void animationDrawsWhatTheCanvasShows();
};

void TestExports::dialogsProposeAFolderThatExists() {
    QSettings settings;
    const QString gone = m_dir.filePath(QStringLiteral("gone"));
    QVERIFY(QDir().mkpath(gone));
    const QString kept = m_dir.filePath(QStringLiteral("kept"));
    QVERIFY(QDir().mkpath(kept));
    rememberFolder(QStringLiteral("csv"), kept); // the last folder used for anything
    settings.setValue(QStringLiteral("dialogs/plots"), gone);
    QVERIFY(QDir(gone).removeRecursively());
    test::DialogScript script; // cancels
    script.install();
    QAction* exportPlots = menuAction(m_window->menuBar(), QStringLiteral("Export plots\u2026"));
    QVERIFY(exportPlots);
    exportPlots->trigger();
    QCOMPARE(script.calls, 1);
    QCOMPARE(script.proposed, kept); // not the deleted plots folder
    // with nothing remembered that exists: a folder that exists (documents, else home)
    QVERIFY(QDir(kept).removeRecursively());
    for (const char* purpose : {"plots", "csv", "scene", "animation", "never-used"})
        QVERIFY2(QFileInfo(lastFolder(QString::fromLatin1(purpose))).isDir(), purpose);
    QAction* exportCsv = menuAction(m_window->menuBar(), QStringLiteral("Export CSV\u2026"));
    QVERIFY(exportCsv);
    exportCsv->trigger();
    QCOMPARE(script.calls, 2);
    QVERIFY2(QFileInfo(QFileInfo(script.proposed).absolutePath()).isDir(),
             qPrintable(script.proposed));
}

void TestExports::exportsSayWhereTheFilesWent() {
    QList<QUrl> opened;
    ExportReport::setOpenUrlHook([&opened](const QUrl& url) { opened << url; });
    ExportReport* report = m_window->exportReport();
    QVERIFY(report->isHidden());
    const QString plots = m_dir.filePath(QStringLiteral("plots"));
    QVERIFY(m_window->exportPlotsTo(plots, {QStringLiteral("png")}));
    QVERIFY(report->isVisible());
    QVERIFY2(report->text().contains(QDir::toNativeSeparators(plots)), qPrintable(report->text()));
    // a temporary message in the status bar does not hide it
    m_window->statusBar()->showMessage(QStringLiteral("something else"), 1000);
    QVERIFY(report->isVisible());
    QTest::mouseClick(report->openButton(), Qt::LeftButton);
    QCOMPARE(opened.size(), 1);
    QCOMPARE(opened.last(), QUrl::fromLocalFile(QDir(plots).absolutePath()));

    const QString csv = m_dir.filePath(QStringLiteral("runs/sinusoid.csv"));
    QVERIFY(QDir().mkpath(m_dir.filePath(QStringLiteral("runs"))));
    QVERIFY(m_window->exportCsvTo(csv));
    QVERIFY(QFileInfo(csv).isFile());
    QVERIFY2(report->text().contains(QDir::toNativeSeparators(csv)), qPrintable(report->text()));
    QTest::mouseClick(report->openButton(), Qt::LeftButton);
    QCOMPARE(opened.last(), QUrl::fromLocalFile(m_dir.filePath(QStringLiteral("runs"))));

    AnimationSettings frames;
    frames.file = m_dir.filePath(QStringLiteral("frames/"));
    frames.fps = 1;
    frames.size = QSize(96, 64);
    frames.speedFactor = 20;
    QVERIFY2(m_window->exportAnimationTo(frames), qPrintable(m_window->lastFileError()));
    QVERIFY(report->text().contains(
        QDir::toNativeSeparators(m_dir.filePath(QStringLiteral("frames")))));
    QTest::mouseClick(report->openButton(), Qt::LeftButton);
    QCOMPARE(opened.last(), QUrl::fromLocalFile(m_dir.filePath(QStringLiteral("frames"))));
    // the next animation export starts in the folder the frames went into
    QCOMPARE(lastFolder(QStringLiteral("animation")), m_dir.filePath(QStringLiteral("frames")));
}

void TestExports::exportedPlotsShowThePinnedRuns() {
    // three runs pinned at b = 0.5, 1 and 2 m: the Plots dock shows them, and so do the files
    QVERIFY(m_window->openFile(QStringLiteral(CHAPLYGIN_SOURCE_DIR) +
                               QStringLiteral("/docs/images/scenes/pins-three-b.json")));
    PinSet* pins = m_window->document()->pins();
    QVERIFY(pins->count() > 0);
    const QString dir = m_dir.filePath(QStringLiteral("pinned"));
    QVERIFY(m_window->exportPlotsTo(dir, {QStringLiteral("svg")}));
    for (const char* stem : {"psi", "chi", "lambda", "energy"}) {
        QFile svg(QDir(dir).filePath(QString::fromLatin1(stem) + QStringLiteral(".svg")));
        QVERIFY2(svg.open(QIODevice::ReadOnly), stem);
        const QString text = QString::fromUtf8(svg.readAll());
        for (int i = 0; i < pins->count(); ++i)
            QVERIFY2(text.contains(m_window->document()->pins()->label(i).toHtmlEscaped()),
                     qPrintable(QStringLiteral("%1: %2").arg(QLatin1String(stem), pins->label(i))));
        // each pinned curve sampled as densely as the run's own: a point at least every 2 px
        // along the time axis (they were the path table's nodes, 105 points a curve, visibly
        // polygonal at the file's width)
        for (int i = 0; i < pins->count(); ++i) {
            const QString stroke =
                QStringLiteral("stroke=\"%1\"").arg(PinSet::color(i).name(QColor::HexRgb));
            double longest = 0;
            int points = 0;
            for (qsizetype at = text.indexOf(stroke); at >= 0; at = text.indexOf(stroke, at + 1)) {
                const qsizetype end = text.indexOf(QStringLiteral("</g>"), at);
                static const QRegularExpression polyline(
                    QStringLiteral("<polyline[^>]*points=\"([^\"]*)\""));
                for (auto m = polyline.globalMatch(text.mid(at, end - at)); m.hasNext();) {
                    const QStringList xy = m.next().captured(1).split(
                        QRegularExpression(QStringLiteral("[ ,]+")), Qt::SkipEmptyParts);
                    if (xy.size() < 20) // the legend's sample of the line
                        continue;
                    for (int k = 2; k + 1 < xy.size(); k += 2, ++points)
                        longest =
                            std::max(longest, std::abs(xy[k].toDouble() - xy[k - 2].toDouble()));
                }
            }
            QVERIFY2(points > 200, qPrintable(QStringLiteral("%1: pin %2, %3 points")
                                                  .arg(QLatin1String(stem))
                                                  .arg(i)
                                                  .arg(points)));
            QVERIFY2(longest <= 2, qPrintable(QStringLiteral("%1: pin %2, a gap of %3 px")
                                                  .arg(QLatin1String(stem))
                                                  .arg(i)
                                                  .arg(longest)));
        }
    }
}

void TestExports::animationDialogProposesAFileInAFolderThatExists() {
    QSettings().setValue(QStringLiteral("dialogs/animation"), m_dir.filePath(QStringLiteral("no")));
    rememberFolder(QStringLiteral("scene"), m_dir.path());
    QString proposed;
    QTimer::singleShot(0, this, [&proposed] {
        for (QWidget* w : QApplication::topLevelWidgets())
            if (auto* dialog = qobject_cast<AnimationDialog*>(w)) {
                proposed = dialog->fileEdit()->text();
                dialog->reject();
            }
    });
    m_window->exportAnimationDialog();
    QVERIFY(!proposed.isEmpty());
    QVERIFY2(QFileInfo(proposed).isAbsolute(), qPrintable(proposed));
    QVERIFY2(proposed.startsWith(m_dir.path()), qPrintable(proposed));
}

void TestExports::animationDrawsWhatTheCanvasShows() {
    // the user chose markers and hid the vakonomic body: the exported clip does the same
    SceneCanvas* canvas = m_window->canvas();
    CanvasStyle style = canvas->canvasStyle();
    style.body = BodyDisplay::Marker;
    canvas->setCanvasStyle(style);
    canvas->setShowVakonomic(false);
    const QString folder = m_dir.filePath(QStringLiteral("look/"));
    QTimer::singleShot(0, this, [folder] {
        for (QWidget* w : QApplication::topLevelWidgets())
            if (auto* dialog = qobject_cast<AnimationDialog*>(w)) {
                dialog->fileEdit()->setText(folder);
                dialog->fpsBox()->setValue(1);
                dialog->widthBox()->setValue(320);
                dialog->heightBox()->setValue(200);
                dialog->speedBox()->setValue(2);
                dialog->accept();
            }
    });
    m_window->exportAnimationDialog();
    const QImage written(QDir(folder).filePath(QStringLiteral("frame_00001.png")));
    QVERIFY(!written.isNull());

    QCOMPARE(written.size(), QSize(320, 200));
    AnimationSettings settings;
    settings.file = m_dir.filePath(QStringLiteral("unused/"));
    settings.size = written.size();
    const double t = 2.0; // frame 1 at 1 frame per second, twice real time
    const QImage fresh = AnimationExporter(m_window->document(), settings)
                             .renderFrame(t)
                             .convertToFormat(written.format());
    settings.look = canvas->look();
    QCOMPARE(settings.look.style.body, BodyDisplay::Marker);
    QVERIFY(!settings.look.vakonomic);
    const QImage alike = AnimationExporter(m_window->document(), settings)
                             .renderFrame(t)
                             .convertToFormat(written.format());
    QVERIFY(written == alike);
    QVERIFY(written != fresh); // a fresh canvas's look (to scale, vakonomic body) differs
}

QTEST_MAIN(TestExports)
#include "test_exports.moc"
