// What one slider move triggers (docs/architecture.md, ui/: the desktop application): the edit
// goes to the document, which derives the system once and solves once, and each view is told
// once; nothing goes back into the panel that sent it.
#include "canvas/scene_canvas.h"
#include "document/scene_document.h"
#include "event_counter.h"
#include "panels/parameters_panel.h"
#include "plots/plots_panel.h"
#include "systems/system.h"
#include "widgets/number_field.h"
#include "window_fixture.h"

#include <QSignalSpy>
#include <QSlider>
#include <QtTest>
#include <qcustomplot.h>

#include <array>
#include <memory>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestSliderPath : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_slider_path_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }
    void oneSliderMoveDerivesOnceSolvesOnceAndPaintsEachViewOnce();
    void undoOfASliderMoveShowsTheValueAgain();
};

namespace {

// lets every queued event and deferred paint happen
void settle() {
    for (int i = 0; i < 5; ++i)
        QCoreApplication::processEvents();
}

} // namespace

void TestSliderPath::oneSliderMoveDerivesOnceSolvesOnceAndPaintsEachViewOnce() {
    SceneDocument* document = m_window->document();
    ParametersPanel* panel = m_window->parametersPanel();
    m_window->showParametersDock();
    document->flush();
    settle();
    QSlider* slider = panel->slider(QStringLiteral("m"));
    NumberField* spin = panel->spinBox(QStringLiteral("m"));
    QVERIFY(slider && spin);

    test::EventCounter canvasPaints(QEvent::Paint);
    m_window->canvas()->installEventFilter(&canvasPaints);
    // a plot is drawn anew once (its replot); a paint event may follow for the strip its time
    // cursor uncovers when the axes moved
    std::array<std::unique_ptr<QSignalSpy>, 4> replots;
    for (int i = 0; i < 4; ++i)
        replots[std::size_t(i)] = std::make_unique<QSignalSpy>(m_window->plotsPanel()->plot(i),
                                                               &QCustomPlot::beforeReplot);
    QSignalSpy solved(document, &SceneDocument::solutionChanged);
    QSignalSpy applied(document, &SceneDocument::sceneApplied);
    const double before = document->scene().system.params.at("m");
    const long derivations = derivationCount();

    slider->setValue(slider->value() + 7);
    const double typed = spin->value(); // what the row shows for the slider's place
    QSignalSpy spinAgain(spin, &NumberField::valueChanged);
    document->flush();
    settle();

    QCOMPARE(document->scene().system.params.at("m"), typed);
    QVERIFY(typed != before);
    QCOMPARE(derivationCount() - derivations, 1L); // the document's check, which the solve reuses
    QCOMPARE(applied.count(), 1);
    QCOMPARE(solved.count(), 1); // one solve
    QCOMPARE(canvasPaints.count, 1);
    for (int i = 0; i < 4; ++i)
        QVERIFY2(replots[std::size_t(i)]->count() == 1,
                 qPrintable(QStringLiteral("plot %1 drawn %2 times")
                                .arg(i)
                                .arg(replots[std::size_t(i)]->count())));
    QCOMPARE(spinAgain.count(), 0); // no round trip into the panel that sent the edit
}

void TestSliderPath::undoOfASliderMoveShowsTheValueAgain() {
    SceneDocument* document = m_window->document();
    ParametersPanel* panel = m_window->parametersPanel();
    document->flush();
    QSlider* slider = panel->slider(QStringLiteral("m"));
    NumberField* spin = panel->spinBox(QStringLiteral("m"));
    const double before = spin->value();
    slider->setValue(slider->value() + 7);
    document->flush();
    QVERIFY(spin->value() != before);
    document->undoStack()->undo();
    document->flush();
    // the change came from elsewhere: the panel shows the document's value again
    QCOMPARE(spin->value(), before);
    QCOMPARE(document->scene().system.params.at("m"), before);
}

QTEST_MAIN(TestSliderPath)
#include "test_slider_path.moc"
