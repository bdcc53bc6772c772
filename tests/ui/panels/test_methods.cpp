// GUI tests of the method lab in the app: the Methods dock (work-precision in a worker thread with
// progress and cancel), the live accuracy readout, and the gallery of where methods fail.
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "lab/gallery.h"
#include "panels/accuracy_readout.h"
#include "panels/methods_panel.h"
#include "scene/presets.h"
#include "shell/main_window.h"
#include "shell/playback.h"

#include <QAction>
#include <QElapsedTimer>
#include <QHeaderView>
#include <QProgressBar>
#include <QPushButton>
#include <QStandardPaths>
#include <QTableWidget>
#include <QUndoStack>
#include <QtTest>
#include <qcustomplot.h>

#include <memory>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

// one series per method and one star per chosen configuration, in both panels
struct Series {
    int methods = 0, stars = 0;
};

Series countSeries(QCustomPlot* plot) {
    Series s;
    for (int i = 0; i < plot->plottableCount(); ++i) {
        if (plot->plottable(i)->name().startsWith(QLatin1String("chosen: ")))
            ++s.stars;
        else
            ++s.methods;
    }
    return s;
}

const GalleryEntry* firstEntry(bool rejected, const Scene& unlike) {
    for (const GalleryEntry& e : galleryEntries())
        if (e.rejected == rejected && e.scene != unlike)
            return &e;
    return nullptr;
}

} // namespace

class TestMethods : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase();
    void init();
    void cleanup();

    void workPrecisionRunsToCompletion();
    void cancelStopsCatenarySweep();
    void sceneChangeCancelsSweep();
    void accuracyReadoutOnCircleAndCatenary();
    void accuracyReadoutRefreshesAtAMetersPace();
    void galleryRefusedEntryKeepsScene();
    void galleryAcceptedEntryShowsExplanation();
    void tableShowsWholeColumnTitles();

  private:
    void load(const char* preset);
    std::unique_ptr<MainWindow> m_window;
};

void TestMethods::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_methods_tests"));
}

void TestMethods::init() {
    m_window = test::showTestWindow();
    QVERIFY(m_window && m_window->document()->solution());
}

void TestMethods::cleanup() {
    m_window.reset();
}

void TestMethods::load(const char* preset) {
    m_window->loadScene(presetScene(preset));
    QVERIFY(m_window->document()->error().isEmpty());
}

void TestMethods::workPrecisionRunsToCompletion() {
    load("line");
    MethodsPanel* panel = m_window->methodsPanel();
    m_window->showMethodsDock();
    QSignalSpy finished(panel, &MethodsPanel::finished);
    QTest::mouseClick(panel->runButton(), Qt::LeftButton);
    // the sweep runs off the UI thread: the click returns at once with the sweep under way
    QVERIFY(panel->isRunning());
    QVERIFY(!panel->runButton()->isEnabled());
    QVERIFY(panel->cancelButton()->isEnabled());
    QTRY_VERIFY_WITH_TIMEOUT(!panel->isRunning(), 60000);
    QCOMPARE(finished.count(), 1);
    QVERIFY(panel->report());
    const WorkPrecisionReport& report = *panel->report();
    QVERIFY(!report.cancelled);
    QVERIFY(report.rows.size() >= 6);
    QCOMPARE(panel->progressBar()->value(), panel->progressBar()->maximum());
    QVERIFY(panel->progressBar()->maximum() > 1);
    Series series = countSeries(panel->plot());
    QVERIFY2(series.methods >= 6, qPrintable(QString::number(series.methods)));
    QVERIFY(series.stars >= 1);
    // the chosen configurations of both problems, each on or off the Pareto front
    QTableWidget* table = panel->chosenTable();
    QCOMPARE(table->rowCount(), 2);
    for (int r = 0; r < table->rowCount(); ++r)
        QVERIFY(table->item(r, 4)->text() == QLatin1String("yes") ||
                table->item(r, 4)->text() == QLatin1String("no"));
    QVERIFY(panel->runButton()->isEnabled());
    QVERIFY(!panel->cancelButton()->isEnabled());
}

void TestMethods::cancelStopsCatenarySweep() {
    load("catenary");
    MethodsPanel* panel = m_window->methodsPanel();
    panel->start();
    QVERIFY(panel->isRunning());
    // progress arrives on the UI thread while the worker sweeps
    QTRY_VERIFY_WITH_TIMEOUT(panel->progressBar()->value() > 0, 20000);
    const int total = panel->progressBar()->maximum();
    // Cancel only raises the stop flag; the worker stops after the configuration under way
    QTest::mouseClick(panel->cancelButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!panel->isRunning(), 10000);
    QVERIFY(panel->report());
    QVERIFY(panel->report()->cancelled);
    QVERIFY(int(panel->report()->rows.size()) < total);
    QVERIFY(panel->statusText().contains(QLatin1String("Stopped")));
}

void TestMethods::sceneChangeCancelsSweep() {
    load("catenary");
    MethodsPanel* panel = m_window->methodsPanel();
    panel->start();
    QVERIFY(panel->isRunning());
    load("circle");
    QTRY_VERIFY_WITH_TIMEOUT(!panel->isRunning(), 10000);
    QVERIFY(panel->report() && panel->report()->cancelled);
    QVERIFY(panel->statusText().contains(QLatin1String("scene changed")));
}

void TestMethods::accuracyReadoutOnCircleAndCatenary() {
    AccuracyReadout* readout = m_window->accuracyReadout();
    load("circle");
    for (double t : {0.0, 1.7, 5.3}) {
        m_window->playback()->seek(t);
        readout->refresh();
        const AccuracyValues& v = readout->values();
        QCOMPARE(v.t, t);
        QVERIFY2(v.trackingResidual <= 1e-9, qPrintable(QString::number(v.trackingResidual)));
        QVERIFY(v.paperError);
        QVERIFY2(*v.paperError <= 1e-9, qPrintable(QString::number(*v.paperError)));
        QVERIFY(v.paperEquations.contains(QLatin1String("(93)")));
        QVERIFY(v.controlledDrift && *v.controlledDrift <= 1e-12);
        QVERIFY(v.freeDrift <= 1e-12);
    }
    QVERIFY(readout->modelsText().contains(QLatin1String("closed form")));

    load("catenary");
    m_window->playback()->seek(2);
    // the readout follows the playback time within a quarter second
    QTRY_COMPARE(readout->values().t, 2.0);
    const AccuracyValues& v = readout->values();
    QVERIFY2(v.trackingResidual <= 1e-9, qPrintable(QString::number(v.trackingResidual)));
    QVERIFY(!v.paperError);
    QVERIFY(v.controlledDrift && *v.controlledDrift <= 1e-12);
    QVERIFY(readout->modelsText().contains(QLatin1String("quadrature")));
}

void TestMethods::accuracyReadoutRefreshesAtAMetersPace() {
    // during playback the read-out takes the latest time a few times a second, not every frame:
    // frames 16 ms apart change nothing until a quarter second has passed
    load("circle");
    AccuracyReadout* readout = m_window->accuracyReadout();
    readout->setTime(0.5);
    QTRY_COMPARE(readout->values().t, 0.5);
    QElapsedTimer clock;
    clock.start();
    for (double t : {1.0, 1.5, 2.0}) {
        readout->setTime(t);
        QTest::qWait(16);
    }
    if (clock.elapsed() < 200) // a slow machine may reach the refresh within the frames
        QCOMPARE(readout->values().t, 0.5);
    QTRY_COMPARE(readout->values().t, 2.0);
    QVERIFY2(clock.elapsed() >= 200, qPrintable(QString::number(clock.elapsed())));
}

void TestMethods::galleryRefusedEntryKeepsScene() {
    load("circle");
    const Scene before = m_window->document()->scene();
    const int undoCount = m_window->undoStack()->count();
    int refused = 0;
    for (const GalleryEntry& e : galleryEntries()) {
        if (!e.rejected)
            continue;
        ++refused;
        QAction* action = m_window->findChild<QAction*>(QStringLiteral("gallery-") +
                                                        QString::fromStdString(e.name));
        QVERIFY(action);
        action->trigger();
        m_window->document()->flush();
        QVERIFY(m_window->document()->scene() == before);
        QVERIFY(m_window->document()->solution()->scene() == before);
        QCOMPARE(m_window->undoStack()->count(), undoCount);
        const QString note = m_window->accuracyReadout()->noteText();
        QVERIFY2(note.contains(QString::fromStdString(e.message).toHtmlEscaped()),
                 qPrintable(note));
        QVERIFY(note.contains(QLatin1String("Refused")));
    }
    QVERIFY(refused >= 1);
}

void TestMethods::galleryAcceptedEntryShowsExplanation() {
    const Scene before = m_window->document()->scene();
    const GalleryEntry* entry = firstEntry(false, before);
    QVERIFY(entry);
    QVERIFY(m_window->loadGalleryEntry(QString::fromStdString(entry->name)));
    QVERIFY(m_window->document()->scene() == entry->scene);
    QVERIFY(m_window->document()->error().isEmpty());
    const QString note = m_window->accuracyReadout()->noteText();
    QVERIFY(note.contains(QString::fromStdString(entry->title).toHtmlEscaped()));
    QVERIFY(note.contains(QString::fromStdString(entry->scene.note.substr(0, 40)).toHtmlEscaped()));
    QVERIFY(!note.contains(QLatin1String("Refused")));
    // loaded through the undo stack: undo brings the previous scene back and drops the note
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QVERIFY(m_window->document()->scene() == before);
    QVERIFY(m_window->accuracyReadout()->noteText().isEmpty());
}

// at 1024x768 the chosen configurations' table keeps every column title whole ("Pareto" read
// "ye") and every short cell; the long method name is elided with its whole text in the tooltip
void TestMethods::tableShowsWholeColumnTitles() {
    m_window->resize(1024, 768);
    m_window->balanceDocks();
    load("sinusoid");
    MethodsPanel* panel = m_window->methodsPanel();
    m_window->showMethodsDock();
    panel->start();
    QTRY_VERIFY_WITH_TIMEOUT(!panel->isRunning(), 60000);
    QApplication::processEvents();
    QTableWidget* table = panel->chosenTable();
    QCOMPARE(table->rowCount(), 2);
    QHeaderView* header = table->horizontalHeader();
    int used = 0;
    for (int c = 0; c < table->columnCount(); ++c) {
        const QString title = table->horizontalHeaderItem(c)->text();
        const int need = header->fontMetrics().horizontalAdvance(title);
        QVERIFY2(header->sectionSize(c) >= need + 8,
                 qPrintable(QStringLiteral("\"%1\" needs %2 px, its column is %3 px")
                                .arg(title)
                                .arg(need)
                                .arg(header->sectionSize(c))));
        used += header->sectionSize(c);
        for (int r = 0; r < table->rowCount(); ++r) {
            const QString text = table->item(r, c)->text();
            const int cell = table->fontMetrics().horizontalAdvance(text);
            if (c == 1)
                QCOMPARE(table->item(r, c)->toolTip().contains(text), true);
            else
                QVERIFY2(header->sectionSize(c) >= cell + 4,
                         qPrintable(QStringLiteral("%1: %2 px in %3")
                                        .arg(text)
                                        .arg(cell)
                                        .arg(header->sectionSize(c))));
        }
    }
    QVERIFY2(
        used <= table->viewport()->width() + 1,
        qPrintable(
            QStringLiteral("%1 px of columns in %2 px").arg(used).arg(table->viewport()->width())));
}

QTEST_MAIN(TestMethods)
#include "test_methods.moc"
