// GUI tests of the main window's parameters, driving the real widgets under the offscreen
// platform: a change that updates the plots, a slider drag that is one solve and one undo step, a
// refused value that keeps the solution, the system, gyration and mode switches, undo and redo.
#include "canvas/scene_canvas.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "panels/parameters_panel.h"
#include "panels/path_panel.h"
#include "plots/plots_panel.h"
#include "shell/main_window.h"
#include "widgets/number_field.h"
#include "window_fixture.h"

#include <QComboBox>
#include <QLineEdit>
#include <QSlider>
#include <QUndoStack>
#include <QtTest>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

using namespace chaplygin;
using namespace chaplygin::ui;
using namespace chaplygin::ui::test;

namespace {

QVector<double> graphValues(QCustomPlot* plot, int graph = 0) {
    QVector<double> v;
    for (const QCPGraphData& d : *plot->graph(graph)->data())
        v << d.value;
    return v;
}

double maxAbsDifference(const QVector<double>& a, const QVector<double>& b) {
    double worst = a.size() == b.size() ? 0 : INFINITY;
    for (int i = 0; i < std::min(a.size(), b.size()); ++i)
        worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
}

} // namespace

class TestMainWindowParameters : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_main_window_parameters_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void parameterChangeUpdatesPlots();
    void sliderDragCoalesces();
    void invalidParameterKeepsSolution();
    void systemSwitch();
    void gyrationAndModeSwitch();
    void undoRedo();
};

void TestMainWindowParameters::parameterChangeUpdatesPlots() {
    QCustomPlot* psi = m_window->plotsPanel()->plot(0);
    QVector<double> before = graphValues(psi);
    QVERIFY(before.size() > 10);
    NumberField* b = m_window->parametersPanel()->spinBox(QStringLiteral("b"));
    QVERIFY(b);
    b->setValue(2.0);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution()->system().b, 2.0);
    QVector<double> after = graphValues(psi);
    QVERIFY2(maxAbsDifference(before, after) > 0.05, "Psi = atan2(1, b kappa) changed with b");
    // tan Psi = 1/(b kappa) and max |kappa| = 1 on y = -sin x: |Psi - pi/2| peaks at pi/2 -
    // atan(1/b) on the crests
    double devBefore = 0, devAfter = 0;
    for (double v : before)
        devBefore = std::max(devBefore, std::abs(v - M_PI / 2));
    for (double v : after)
        devAfter = std::max(devAfter, std::abs(v - M_PI / 2));
    QVERIFY2(std::abs(devBefore - (M_PI / 2 - std::atan(1.0))) < 1e-2,
             qPrintable(QString::number(devBefore)));
    QVERIFY2(std::abs(devAfter - (M_PI / 2 - std::atan(0.5))) < 1e-2,
             qPrintable(QString::number(devAfter)));
}

void TestMainWindowParameters::sliderDragCoalesces() {
    QSlider* slider = m_window->parametersPanel()->slider(QStringLiteral("speed"));
    QVERIFY(slider);
    QSignalSpy solved(m_window->document(), &SceneDocument::solutionChanged);
    for (int v = 200; v <= 400; v += 10)
        slider->setValue(v); // one drag, no event processing in between
    QTRY_COMPARE(solved.count(), 1);
    double speed = m_window->document()->solution()->scene().speed;
    QVERIFY(std::abs(speed - (0.05 + 4.95 * 400 / 1000.0)) < 1e-9);
    QCOMPARE(m_window->undoStack()->count(), 1); // the drag is one undo step
}

void TestMainWindowParameters::invalidParameterKeepsSolution() {
    auto before = m_window->document()->solution();
    NumberField* b = m_window->parametersPanel()->spinBox(QStringLiteral("b"));
    b->setValue(0.2); // below a = 0.5
    m_window->document()->flush();
    QVERIFY(m_window->parametersPanel()->errorText().contains(QStringLiteral("b")));
    QCOMPARE(m_window->document()->solution(), before);
    QCOMPARE(m_window->document()->solution()->system().b, 1.0);
    b->setValue(1.2);
    m_window->document()->flush();
    QVERIFY(m_window->parametersPanel()->errorText().isEmpty());
    QCOMPARE(m_window->document()->solution()->system().b, 1.2);
}

void TestMainWindowParameters::systemSwitch() {
    auto* combo = m_window->parametersPanel()->findChild<QComboBox*>();
    QVERIFY(combo);
    combo->setFocus();
    combo->setCurrentIndex(1);
    emit combo->activated(1);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().system.kind, SystemKind::Disk);
    QVERIFY(m_window->parametersPanel()->spinBox(QStringLiteral("I2")));
    QVERIFY(!m_window->parametersPanel()->spinBox(QStringLiteral("b")));
    QCOMPARE(m_window->document()->solution()->system().a, 0.0);
    m_window->canvas()->grab(); // the disk paints
    // back to the sleigh (same number of parameters as the disk), then the carriage, then undo
    combo->setCurrentIndex(0);
    emit combo->activated(0);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution()->system().b, 1.0);
    QVERIFY(m_window->parametersPanel()->spinBox(QStringLiteral("b")));
    QVERIFY(!m_window->parametersPanel()->spinBox(QStringLiteral("R")));
    combo->setCurrentIndex(2);
    emit combo->activated(2);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().system.kind, SystemKind::Carriage);
    QCOMPARE(m_window->parametersPanel()->spinBox(QStringLiteral("M"))->value(), 2.0);
    m_window->canvas()->grab();
    m_window->undoStack()->undo();
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution()->scene().system.kind, SystemKind::Disk);
    QVERIFY(m_window->parametersPanel()->spinBox(QStringLiteral("I1")));
    QCOMPARE(combo->currentIndex(), 1);
}

void TestMainWindowParameters::gyrationAndModeSwitch() {
    ParametersPanel* panel = m_window->parametersPanel();
    auto combos = panel->findChildren<QComboBox*>();
    QCOMPARE(combos.size(), 3); // system, gyration, mode
    QComboBox* gyration = combos[1];
    gyration->setCurrentIndex(1);
    emit gyration->activated(1);
    m_window->document()->flush();
    // I = m (b^2 - a^2) = 1 * (1 - 0.25)
    QVERIFY(panel->spinBox(QStringLiteral("I")));
    QVERIFY(!panel->spinBox(QStringLiteral("b")));
    QCOMPARE(panel->spinBox(QStringLiteral("I"))->value(), 0.75);
    panel->spinBox(QStringLiteral("I"))->setValue(3.0);
    m_window->document()->flush();
    QVERIFY(std::abs(m_window->document()->solution()->system().b - std::sqrt(0.25 + 3.0)) < 1e-12);
    QComboBox* mode = combos[2];
    mode->setCurrentIndex(1);
    emit mode->activated(1);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution()->scene().mode, SpeedMode::Speed);
    // constant speed: sdot = v_s everywhere, so the time to traverse is length / v_s
    const auto& solution = m_window->document()->solution();
    QVERIFY(std::abs(solution->duration() - solution->path()->length() / solution->scene().speed) <
            1e-9);
}

void TestMainWindowParameters::undoRedo() {
    QUndoStack* undo = m_window->undoStack();
    PathPanel* panel = m_window->pathPanel();
    typeInto(panel->graphEdit(), QStringLiteral("0.5*sin(2*x)"));
    QTest::keyClick(panel->graphEdit(), Qt::Key_Return);
    m_window->document()->flush();
    m_window->parametersPanel()->spinBox(QStringLiteral("m"))->setValue(3.0);
    m_window->document()->flush();
    QCOMPARE(undo->count(), 2);
    QCOMPARE(m_window->document()->solution()->system().mass, 3.0);
    undo->undo();
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution()->system().mass, 1.0);
    QCOMPARE(m_window->parametersPanel()->spinBox(QStringLiteral("m"))->value(), 1.0);
    undo->undo();
    m_window->document()->flush();
    QCOMPARE(QString::fromStdString(m_window->document()->scene().path.y),
             QStringLiteral("-sin(x)"));
    QCOMPARE(panel->graphEdit()->text(), QStringLiteral("-sin(x)"));
    undo->redo();
    undo->redo();
    m_window->document()->flush();
    QCOMPARE(QString::fromStdString(m_window->document()->solution()->scene().path.y),
             QStringLiteral("0.5*sin(2*x)"));
    QCOMPARE(m_window->document()->solution()->system().mass, 3.0);
}

QTEST_MAIN(TestMainWindowParameters)
#include "test_main_window_parameters.moc"
