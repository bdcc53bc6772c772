// State that does not go stale: a scene change clears the Methods chart and the messages of the
// scene before; an invalid parameter is marked and never used. Offscreen, real widgets.
#include "lab/gallery.h"
#include "panels/accuracy_readout.h"
#include "panels/methods_panel.h"
#include "panels/parameters_panel.h"
#include "widgets/number_field.h"
#include "window_fixture.h"

#include <QStatusBar>
#include <QTableWidget>
#include <QtTest>
#include <qcustomplot.h>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestStaleState : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_stale_state_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void methodsChartClearedOnSceneChange();
    void messagesBelongToTheirScene();
    void invalidSpinBoxIsMarked();
};

void TestStaleState::methodsChartClearedOnSceneChange() {
    choosePreset("line");
    MethodsPanel* panel = m_window->methodsPanel();
    panel->start();
    panel->waitForFinished();
    QVERIFY(panel->report());
    QVERIFY(panel->plot()->plottableCount() > 0);
    QVERIFY(panel->chosenTable()->rowCount() > 0);
    choosePreset("circle");
    QVERIFY(!panel->report());
    QCOMPARE(panel->plot()->plottableCount(), 0);
    QCOMPARE(panel->chosenTable()->rowCount(), 0);
    QVERIFY(panel->statusText().contains(QStringLiteral("scene changed")));
}

void TestStaleState::messagesBelongToTheirScene() {
    QString refused;
    for (const GalleryEntry& e : galleryEntries())
        if (e.rejected)
            refused = QString::fromStdString(e.name);
    QVERIFY(!refused.isEmpty());
    QVERIFY(!m_window->loadGalleryEntry(refused));
    const QString refusal = m_window->statusBar()->currentMessage();
    QVERIFY(!refusal.isEmpty());
    QVERIFY(m_window->accuracyReadout()->noteText().contains(QStringLiteral("Refused")));
    choosePreset("circle");
    // the refusal is gone; the status bar names the preset that came instead
    QVERIFY(!m_window->statusBar()->currentMessage().contains(refusal));
    QVERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("circle")));
    QVERIFY(!m_window->accuracyReadout()->noteText().contains(QStringLiteral("Refused")));
    // a refused parameter's message goes with the next scene too
    NumberField* m = m_window->parametersPanel()->spinBox(QStringLiteral("m"));
    m->setValue(0);
    QVERIFY(!m_window->parametersPanel()->errorText().isEmpty());
    choosePreset("catenary");
    QVERIFY(m_window->parametersPanel()->errorText().isEmpty());
}

void TestStaleState::invalidSpinBoxIsMarked() {
    ParametersPanel* panel = m_window->parametersPanel();
    NumberField* m = panel->spinBox(QStringLiteral("m"));
    QVERIFY(m);
    const double used = m_window->document()->scene().system.params.at("m");
    m->setValue(0); // a massless body is refused
    m_window->document()->flush();
    QVERIFY(!panel->errorText().isEmpty());
    QVERIFY(panel->isMarkedInvalid(QStringLiteral("m")));
    QVERIFY(!m->styleSheet().isEmpty());
    QCOMPARE(m_window->document()->scene().system.params.at("m"), used);
    // a valid value is used and the mark goes
    m->setValue(used + 1);
    m_window->document()->flush();
    QVERIFY(!panel->isMarkedInvalid(QStringLiteral("m")));
    QVERIFY(m->styleSheet().isEmpty());
    QCOMPARE(m_window->document()->scene().system.params.at("m"), used + 1);
}

QTEST_MAIN(TestStaleState)
#include "test_stale_state.moc"
