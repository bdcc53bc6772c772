// The parameters dock on its own: a row per parameter the scene gives, the b-or-I choice by
// b² = a² + I/m (docs/physics.md §1), slider ends inside each parameter's physical range,
// the speed's row by mode, and the words of the core's parameter table translated (pt_BR).
#include "common/input_error.h"
#include "panels/parameters_panel.h"
#include "scene/presets.h"
#include "widgets/number_field.h"

#include <QComboBox>
#include <QSlider>
#include <QTranslator>
#include <QtTest>

#include <cmath>
#include <vector>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestParametersPanel : public QObject {
    Q_OBJECT

  private slots:
    void rowsAreTheScenesParameters();
    void gyrationChoiceConvertsBAndI();
    void sliderEndsArePhysical();
    void speedRowFollowsTheMode();
    void wordsAreTranslated();
};

namespace {

// the scenes the panel emits, in order
struct Edits {
    explicit Edits(ParametersPanel& panel) {
        QObject::connect(
            &panel, &ParametersPanel::sceneEdited,
            [this](const Scene& s, const QString&, const QString&) { scenes.push_back(s); });
    }
    std::vector<Scene> scenes;
    const Scene& last() const { return scenes.back(); }
};

Scene sceneOf(SystemKind kind) {
    Scene s = presetScene("circle");
    s.system = {kind, defaultSystemParams(kind)};
    return s;
}

QStringList shownParameters(const ParametersPanel& panel) {
    QStringList names;
    for (const char* name : {"m", "a", "b", "I", "R", "I1", "I2", "M"})
        if (panel.spinBox(QString::fromLatin1(name)))
            names << QString::fromLatin1(name);
    names.sort();
    return names;
}

} // namespace

void TestParametersPanel::rowsAreTheScenesParameters() {
    ParametersPanel panel;
    // docs/physics.md §1: the sleigh m, a, b (or I); the disk m, R, I1, I2; the carriage R, a, m,
    // I1, I2, M, I
    panel.setScene(sceneOf(SystemKind::Sleigh));
    QCOMPARE(shownParameters(panel), (QStringList{"a", "b", "m"}));
    panel.setScene(sceneOf(SystemKind::Disk));
    QCOMPARE(shownParameters(panel), (QStringList{"I1", "I2", "R", "m"}));
    panel.setScene(sceneOf(SystemKind::Carriage));
    QCOMPARE(shownParameters(panel), (QStringList{"I", "I1", "I2", "M", "R", "a", "m"}));
    // each spin box shows its value with its SI unit
    QCOMPARE(panel.spinBox("R")->value(), 0.3);
    QCOMPARE(panel.spinBox("R")->unit(), QStringLiteral("m"));
    QCOMPARE(panel.spinBox("M")->unit(), QStringLiteral("kg"));
    QCOMPARE(panel.spinBox("I")->unit(), QStringLiteral("kg m\u00b2"));
    QVERIFY(panel.spinBox("speed"));
}

void TestParametersPanel::gyrationChoiceConvertsBAndI() {
    ParametersPanel panel;
    Scene s = sceneOf(SystemKind::Sleigh);
    s.system.params = {{"m", 2.0}, {"a", 0.3}, {"b", 0.8}};
    panel.setScene(s);
    Edits edits(panel);
    auto* gyration = panel.findChildren<QComboBox*>().at(1);
    QCOMPARE(gyration->count(), 2);
    gyration->setCurrentIndex(1);
    emit gyration->activated(1);
    QCOMPARE(edits.scenes.size(), 1u);
    Scene edited = edits.last();
    // I = m (b² - a²) = 2 (0.64 - 0.09) = 1.1, and b is no longer given
    QCOMPARE(edited.system.params.count("b"), 0u);
    QVERIFY(std::fabs(edited.system.params.at("I") - 1.1) < 1e-14);
    QVERIFY(panel.spinBox("I"));
    QVERIFY(!panel.spinBox("b"));
    gyration->setCurrentIndex(0);
    emit gyration->activated(0);
    edited = edits.last();
    QCOMPARE(edited.system.params.count("I"), 0u);
    QVERIFY(std::fabs(edited.system.params.at("b") - 0.8) < 1e-14);
}

// every slider's ends lie inside the physical range of docs/physics.md §1 (m > 0, R > 0, I2 > 0,
// inertias and the carriage's masses >= 0): the defaults with that one value are accepted. The
// sleigh's a and b are left out: b >= |a| couples them.
void TestParametersPanel::sliderEndsArePhysical() {
    for (SystemKind kind : {SystemKind::Sleigh, SystemKind::Disk, SystemKind::Carriage}) {
        ParametersPanel panel;
        panel.setScene(sceneOf(kind));
        Edits edits(panel);
        for (const auto& [name, value] : defaultSystemParams(kind)) {
            if (kind == SystemKind::Sleigh && (name == "a" || name == "b"))
                continue;
            QSlider* slider = panel.slider(QString::fromStdString(name));
            QVERIFY(slider);
            for (int end : {slider->minimum(), slider->maximum()}) {
                panel.setScene(sceneOf(kind));
                slider->setValue((slider->minimum() + slider->maximum()) / 2);
                slider->setValue(end); // a change whatever the default's position
                QVERIFY(!edits.scenes.empty());
                const Scene edited = edits.last();
                try {
                    deriveSystem(edited.system);
                } catch (const InputError& e) {
                    QFAIL(qPrintable(QStringLiteral("%1 %2 at the slider's end: %3")
                                         .arg(QString::fromStdString(systemKindName(kind)),
                                              QString::fromStdString(name), e.what())));
                }
            }
        }
    }
}

void TestParametersPanel::speedRowFollowsTheMode() {
    ParametersPanel panel;
    Scene s = sceneOf(SystemKind::Sleigh);
    s.speed = 1.7;
    panel.setScene(s);
    QCOMPARE(panel.spinBox("speed")->value(), 1.7);
    QCOMPARE(panel.spinBox("speed")->unit(), QStringLiteral("m/s"));
    QVERIFY(panel.spinBox("speed")->toolTip().contains(QStringLiteral("v_T")));
    s.mode = SpeedMode::Speed;
    panel.setScene(s);
    QVERIFY(panel.spinBox("speed")->toolTip().contains(QStringLiteral("v_s")));
    // the speed is > 0 at the slider's lower end
    Edits edits(panel);
    panel.slider("speed")->setValue(500);
    panel.slider("speed")->setValue(0);
    QVERIFY(edits.last().speed > 0);
}

void TestParametersPanel::wordsAreTranslated() {
    QTranslator pt;
    QVERIFY(pt.load(QStringLiteral(":/i18n/chaplygin-lab_pt_BR.qm")));
    QCoreApplication::installTranslator(&pt);
    ParametersPanel panel;
    panel.setScene(sceneOf(SystemKind::Sleigh));
    const QString tip = panel.spinBox("m")->toolTip();
    QCoreApplication::removeTranslator(&pt);
    // the label and the tooltip sentence come from the core's table, translated
    QVERIFY2(tip.contains(QStringLiteral("massa m")), qPrintable(tip));
    QVERIFY2(tip.contains(QStringLiteral("A massa do tren\u00f3")), qPrintable(tip));
    QVERIFY2(tip.contains(QStringLiteral("controle deslizante")), qPrintable(tip));
    ParametersPanel english;
    english.setScene(sceneOf(SystemKind::Sleigh));
    QVERIFY(english.spinBox("m")->toolTip().contains(QStringLiteral("The sleigh's mass")));
}

QTEST_MAIN(TestParametersPanel)
#include "test_parameters_panel.moc"
