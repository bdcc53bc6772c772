// Every kind of number field typed into as a user does (the keys, then Enter) and the scene's
// stored value compared bit for bit with the double computed here: the expression syntax, the
// full double, a refusal that names the field and its bound and leaves the scene alone, a value
// beyond the slider, and arrows that step by round amounts.
#include "canvas/scene_canvas.h"
#include "panels/parameters_panel.h"
#include "panels/path_panel.h"
#include "panels/perturbation_panel.h"
#include "panels/sweep_panel.h"
#include "shell/animation_dialog.h"
#include "shell/playback.h"
#include "widgets/number_field.h"
#include "window_fixture.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSlider>
#include <QUndoStack>

#include <cmath>
#include <cstdlib>
#include <numbers>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

// what a user does: select the field's text, type, press Enter
void typeInto(NumberField* field, const QString& text) {
    field->setFocus();
    field->selectAll();
    QTest::keyClicks(field, text);
    QTest::keyClick(field, Qt::Key_Return);
}

// the double a C library reads from a decimal, independently of the program's parser
double decimal(const char* text) {
    return std::strtod(text, nullptr);
}

} // namespace

class TestNumberFields : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_number_fields_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void stepsAreRoundAmounts();
    void showsTheShortestTextThatReadsBack();
    void parametersKeepTheTypedDouble();
    void beyondTheSliderIsStoredWithTheSliderAtItsEnd();
    void outOfDomainIsRefusedNamingTheBound();
    void arrowsStepTheParameterRoundly();
    void rangeKeepsTwoPi();
    void perturbationFieldsKeepTheTypedDouble();
    void sweepFieldsKeepTheTypedDouble();
    void animationFieldsKeepTheTypedValue();
    void cornerAngleAppliesAtOnceAsOneStep();
};

void TestNumberFields::stepsAreRoundAmounts() {
    auto up = [](double v) { return NumberField::stepped(v, 1, 0.1, false); };
    auto down = [](double v) { return NumberField::stepped(v, -1, 0.1, false); };
    QCOMPARE(up(1.0), 1.1);
    QCOMPARE(up(1.1), 1.2);
    QCOMPARE(up(1.0495), 1.1); // off the grid: the next round value
    QCOMPARE(down(1.0495), 1.0);
    QCOMPARE(down(1.0), 0.99); // the finer step below a power of ten
    QCOMPARE(up(0.99), 1.0);
    QCOMPARE(up(9.9), 10.0);
    QCOMPARE(up(10.0), 11.0);
    QCOMPARE(up(2 * std::numbers::pi), 6.3);
    QCOMPARE(up(-1.0), -0.99);
    QCOMPARE(down(-1.0), -1.1);
    QCOMPARE(up(0.0), 0.1);
    QCOMPARE(down(0.0), -0.1);
    QCOMPARE(up(1200.0), 1300.0);
    QCOMPARE(NumberField::stepped(2.5, 1, 1, true), 3.0);
    QCOMPARE(NumberField::stepped(30, 1, 1, true), 31.0);
}

void TestNumberFields::showsTheShortestTextThatReadsBack() {
    for (double v : {2 * std::numbers::pi, 0.1, 1e6, 1e-7, std::numbers::sqrt2, -0.0025, 1e300,
                     6.283185, 0.0}) {
        const QString text = NumberField::formatted(v);
        QCOMPARE(std::strtod(text.toLatin1().constData(), nullptr), v);
    }
    QCOMPARE(NumberField::formatted(1e6), QStringLiteral("1000000"));
    QCOMPARE(NumberField::formatted(6.283185), QStringLiteral("6.283185"));
    QCOMPARE(NumberField::formatted(2 * std::numbers::pi), QStringLiteral("6.283185307179586"));
    QCOMPARE(NumberField::formatted(1e-7), QStringLiteral("1e-07"));
}

void TestNumberFields::parametersKeepTheTypedDouble() {
    m_window->showParametersDock();
    ParametersPanel* panel = m_window->parametersPanel();
    struct Case {
        const char* field;
        const char* typed;
        double expected;
    };
    const Case cases[] = {{"speed", "1e6", 1e6},
                          {"speed", "1000000", 1e6},
                          {"speed", "6.283185", decimal("6.283185")},
                          {"m", "sqrt(2)", std::sqrt(2.0)},
                          {"m", "2*pi", 2 * std::numbers::pi},
                          {"b", "1.0495", decimal("1.0495")},
                          {"a", "0.1 + 0.2", 0.1 + 0.2},
                          {"m", "3 kg", 3.0}};
    for (const Case& c : cases) {
        NumberField* field = panel->spinBox(QString::fromLatin1(c.field));
        QVERIFY(field);
        typeInto(field, QString::fromLatin1(c.typed));
        m_window->document()->flush();
        const Scene& scene = m_window->document()->scene();
        const double stored =
            std::string(c.field) == "speed" ? scene.speed : scene.system.params.at(c.field);
        QVERIFY2(stored == c.expected, c.typed);
        QCOMPARE(field->value(), c.expected);
        // shown so that reading it back gives the same double
        QCOMPARE(std::strtod(field->text().section(QLatin1Char(' '), 0, 0).toLatin1(), nullptr),
                 c.expected);
        QVERIFY(panel->errorText().isEmpty());
    }
}

void TestNumberFields::beyondTheSliderIsStoredWithTheSliderAtItsEnd() {
    m_window->showParametersDock();
    ParametersPanel* panel = m_window->parametersPanel();
    typeInto(panel->spinBox(QStringLiteral("speed")), QStringLiteral("1e3"));
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().speed, 1000.0);
    QCOMPARE(panel->slider(QStringLiteral("speed"))->value(),
             panel->slider(QStringLiteral("speed"))->maximum());
    typeInto(panel->spinBox(QStringLiteral("m")), QStringLiteral("1e-3"));
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().system.params.at("m"), 1e-3);
    QCOMPARE(panel->slider(QStringLiteral("m"))->value(),
             panel->slider(QStringLiteral("m"))->minimum());
}

void TestNumberFields::outOfDomainIsRefusedNamingTheBound() {
    m_window->showParametersDock();
    ParametersPanel* panel = m_window->parametersPanel();
    const Scene before = m_window->document()->scene();
    const int steps = m_window->undoStack()->count();
    for (const char* typed : {"-1", "0"}) {
        NumberField* m = panel->spinBox(QStringLiteral("m"));
        typeInto(m, QString::fromLatin1(typed));
        m_window->document()->flush();
        QVERIFY2(panel->errorText().contains(QStringLiteral("m must be greater than 0 kg")),
                 qPrintable(panel->errorText()));
        QVERIFY(m->property("invalid").toBool());
        QCOMPARE(m_window->document()->scene(), before);
        QCOMPARE(m_window->undoStack()->count(), steps);
        QCOMPARE(m->text(), QString::fromLatin1(typed)); // what was typed stays to be corrected
        QTRY_COMPARE(QApplication::focusWidget(), static_cast<QWidget*>(m)); // and the keyboard
    }
    // not a number: the parser's message, with the field's name
    typeInto(panel->spinBox(QStringLiteral("b")), QStringLiteral("2*"));
    QVERIFY2(panel->errorText().startsWith(QStringLiteral("b")), qPrintable(panel->errorText()));
    QCOMPARE(m_window->document()->scene(), before);
    // a good value clears the message and is used
    typeInto(panel->spinBox(QStringLiteral("m")), QStringLiteral("2"));
    m_window->document()->flush();
    QVERIFY(!panel->spinBox(QStringLiteral("m"))->property("invalid").toBool());
    QCOMPARE(m_window->document()->scene().system.params.at("m"), 2.0);
}

void TestNumberFields::arrowsStepTheParameterRoundly() {
    m_window->showParametersDock();
    NumberField* b = m_window->parametersPanel()->spinBox(QStringLiteral("b"));
    QCOMPARE(b->value(), 1.0);
    QTest::keyClick(b, Qt::Key_Up);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().system.params.at("b"), 1.1);
    QTest::keyClick(b, Qt::Key_Up);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().system.params.at("b"), 1.2);
    QCOMPARE(b->text(), QStringLiteral("1.2 m"));
    for (int i = 0; i < 3; ++i)
        QTest::keyClick(b, Qt::Key_Down);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().system.params.at("b"), 0.99);
}

void TestNumberFields::rangeKeepsTwoPi() {
    PathPanel* panel = m_window->pathPanel();
    m_window->findChild<QDockWidget*>(QStringLiteral("pathDock"))->raise();
    panel->parametricButton()->click();
    panel->xOfUEdit()->setText(QStringLiteral("2*cos(u)"));
    panel->yOfUEdit()->setText(QStringLiteral("sin(2*u)"));
    typeInto(panel->fromSpin(), QStringLiteral("0"));
    typeInto(panel->toSpin(), QStringLiteral("2*pi"));
    QTRY_COMPARE(m_window->document()->scene().path.kind, PathKind::Parametric);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().path.to, 2 * std::numbers::pi);
    QCOMPARE(panel->toSpin()->text(), QStringLiteral("6.283185307179586"));
    typeInto(panel->toSpin(), QStringLiteral("6.283185"));
    QTRY_COMPARE(m_window->document()->scene().path.to, decimal("6.283185"));
    // Enter handed the keyboard to the canvas: Space plays, it types nothing
    QTRY_COMPARE(QApplication::focusWidget(), static_cast<QWidget*>(m_window->canvas()));
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);
    QVERIFY(m_window->playback()->isPlaying());
    m_window->playback()->pause();
}

void TestNumberFields::perturbationFieldsKeepTheTypedDouble() {
    auto* panel = m_window->findChild<PerturbationPanel*>();
    QVERIFY(panel);
    panel->enabledBox()->setChecked(true);
    m_window->document()->flush();
    QVERIFY(m_window->document()->scene().perturbation);
    typeInto(panel->spin(QStringLiteral("dphi")), QStringLiteral("pi/7"));
    typeInto(panel->spin(QStringLiteral("dy")), QStringLiteral("1e-3"));
    typeInto(panel->spin(QStringLiteral("feedback_rate")), QStringLiteral("12.5"));
    m_window->document()->flush();
    const Perturbation& p = *m_window->document()->scene().perturbation;
    QCOMPARE(p.dphi, std::numbers::pi / 7);
    QCOMPARE(p.dy, 1e-3);
    QCOMPARE(p.feedbackRate, 12.5); // beyond the rate slider's 5
    QCOMPARE(panel->rateSlider()->value(), panel->rateSlider()->maximum());
    // the core's bound |d\u03c6| < \u03c0/2, said at once; the scene keeps \u03c0/7
    const Scene before = m_window->document()->scene();
    typeInto(panel->spin(QStringLiteral("dphi")), QStringLiteral("2"));
    m_window->document()->flush();
    auto* error = panel->findChild<QLabel*>(QStringLiteral("perturbationError"));
    QVERIFY2(error->isVisibleTo(panel) && error->text().contains(QStringLiteral("dphi")) &&
                 error->text().contains(QStringLiteral("pi/2")),
             qPrintable(error->text()));
    QCOMPARE(m_window->document()->scene(), before);
}

void TestNumberFields::sweepFieldsKeepTheTypedDouble() {
    m_window->showSweepDock();
    SweepPanel* panel = m_window->sweepPanel();
    panel->parameterBox()->setCurrentText(QStringLiteral("b"));
    typeInto(panel->fromBox(), QStringLiteral("sqrt(2)"));
    typeInto(panel->toBox(), QStringLiteral("2*pi"));
    typeInto(panel->countBox(), QStringLiteral("1e1"));
    QCOMPARE(panel->fromBox()->value(), std::numbers::sqrt2);
    QCOMPARE(panel->toBox()->value(), 2 * std::numbers::pi);
    QCOMPARE(panel->countBox()->value(), 10.0);
    typeInto(panel->countBox(), QStringLiteral("2.5"));
    QVERIFY(panel->statusText().contains(QStringLiteral("whole number")));
    QCOMPARE(panel->countBox()->value(), 10.0);
    typeInto(panel->countBox(), QStringLiteral("4"));
    panel->start();
    panel->waitForFinished();
    QTRY_VERIFY(panel->report());
    QCOMPARE(panel->report()->spec.from, std::numbers::sqrt2);
    QCOMPARE(panel->report()->spec.to, 2 * std::numbers::pi);
    QCOMPARE(panel->report()->spec.count, 4);
}

void TestNumberFields::animationFieldsKeepTheTypedValue() {
    AnimationDialog dialog(AnimationSettings{}, m_window.get());
    typeInto(dialog.speedBox(), QStringLiteral("sqrt(2)"));
    typeInto(dialog.widthBox(), QStringLiteral("1e3"));
    typeInto(dialog.fpsBox(), QStringLiteral("24"));
    QCOMPARE(dialog.settings().speedFactor, std::numbers::sqrt2);
    QCOMPARE(dialog.settings().size.width(), 1000);
    QCOMPARE(dialog.settings().fps, 24);
    typeInto(dialog.fpsBox(), QStringLiteral("500"));
    QVERIFY2(dialog.errorText().contains(QStringLiteral("at most 120")),
             qPrintable(dialog.errorText()));
    QCOMPARE(dialog.settings().fps, 24);
}

void TestNumberFields::cornerAngleAppliesAtOnceAsOneStep() {
    PathPanel* panel = m_window->pathPanel();
    m_window->findChild<QDockWidget*>(QStringLiteral("pathDock"))->raise();
    panel->drawButton()->click();
    panel->cornersBox()->setCurrentIndex(panel->cornersBox()->findData(int(CornerMode::Pivot)));
    QVERIFY(panel->cornerAngleField()->isEnabled());
    QCOMPARE(panel->cornerAngleField()->value(), kDefaultCornerAngleDeg);
    // a zig-zag turning by 90 degrees at each of its three corners
    test::dragStroke(
        m_window->canvas(), {100, 300},
        {{140, 260}, {180, 220}, {220, 260}, {260, 300}, {300, 260}, {340, 220}, {380, 260}},
        {420, 300});
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().path.kind, PathKind::Polyline);
    QCOMPARE(m_window->document()->solution()->path()->pivotCount(), 3);
    const int steps = m_window->undoStack()->count();
    // still in draw mode: a corner angle above the turns makes none of them a pivot, at once
    typeInto(panel->cornerAngleField(), QStringLiteral("100"));
    QTRY_COMPARE(m_window->document()->scene().path.cornerAngle, 100.0);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution()->path()->pivotCount(), 0);
    QCOMPARE(m_window->undoStack()->count(), steps + 1);
    QVERIFY(m_window->canvas()->drawMode());
    typeInto(panel->cornerAngleField(), QStringLiteral("200"));
    QVERIFY(panel->errorText().contains(QStringLiteral("at most 180")));
    QCOMPARE(m_window->document()->scene().path.cornerAngle, 100.0);
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().path.cornerAngle, kDefaultCornerAngleDeg);
    QCOMPARE(panel->cornerAngleField()->value(), kDefaultCornerAngleDeg);
    QCOMPARE(m_window->document()->solution()->path()->pivotCount(), 3);
}

QTEST_MAIN(TestNumberFields)
#include "test_number_fields.moc"
