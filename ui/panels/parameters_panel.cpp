#include "panels/parameters_panel.h"

#include "common/input_error.h"
#include "scene/speed_choice.h"
#include "systems/system_parameters.h"
#include "widgets/number_field.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <set>

namespace chaplygin::ui {

namespace {

constexpr int kSliderSteps = 1000;

QString translated(const char* text) {
    return QCoreApplication::translate(kSystemParameterContext, text);
}

// a typed value beyond the slider's range puts the slider at its end
int toSlider(double v, double lo, double hi) {
    return static_cast<int>(std::lround(std::clamp((v - lo) / (hi - lo), 0.0, 1.0) * kSliderSteps));
}

} // namespace

ParametersPanel::ParametersPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    auto* top = new QFormLayout;
    m_system = new QComboBox;
    m_system->addItem(tr("Chaplygin sleigh"), int(SystemKind::Sleigh));
    m_system->addItem(tr("Rolling disk (App. A)"), int(SystemKind::Disk));
    m_system->addItem(tr("Two-wheeled carriage (App. B)"), int(SystemKind::Carriage));
    m_system->setToolTip(tr("The Chaplygin system; each reduces to a sleigh with m_eff, a and b"));
    top->addRow(tr("&System"), m_system);
    m_gyration = new QComboBox;
    m_gyration->addItem(tr("enter b, derive I"));
    m_gyration->addItem(tr("enter I, derive b"));
    m_gyration->setToolTip(tr("b\u00b2 = a\u00b2 + I/m: give the radius of gyration b [m] or the "
                              "inertia I [kg m\u00b2]"));
    m_gyrationLabel = new QLabel(tr("&Gyration"));
    m_gyrationLabel->setBuddy(m_gyration);
    top->addRow(m_gyrationLabel, m_gyration);
    layout->addLayout(top);

    m_rowsHost = new QWidget;
    m_form = new QFormLayout(m_rowsHost);
    m_form->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_rowsHost);

    m_derived = new QLabel;
    m_derived->setWordWrap(true);
    m_derived->setToolTip(
        tr("What the control law uses: effective mass [kg], CM offset a [m], "
           "radius of gyration b about P [m], inertia I about the CM [kg m\u00b2]"));
    layout->addWidget(m_derived);

    auto* speedForm = new QFormLayout;
    m_mode = new QComboBox;
    m_mode->addItem(tr("constant kinetic energy (v_T)"));
    m_mode->addItem(tr("constant speed along the path (v_s)"));
    m_mode->setToolTip(
        tr("Energy: T = m v_T\u00b2/2 fixed (sec. 4); speed: ds/dt = v_s fixed (App. C)"));
    speedForm->addRow(tr("&Mode"), m_mode);
    layout->addLayout(speedForm);
    m_speedLabel = new QLabel;
    m_speedLabel->setWordWrap(true); // a long translation wraps instead of widening the dock
    layout->addWidget(m_speedLabel);

    m_error = new QLabel;
    m_error->setObjectName(QStringLiteral("parameterError"));
    m_error->setWordWrap(true);
    m_error->setStyleSheet(QStringLiteral("color: #b00020;"));
    m_error->hide();
    layout->addWidget(m_error);
    layout->addStretch(1);
    for (QComboBox* combo : findChildren<QComboBox*>()) {
        combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        combo->setMinimumContentsLength(10);
    }

    connect(m_system, &QComboBox::activated, this, &ParametersPanel::onSystemChosen);
    connect(m_gyration, &QComboBox::activated, this, &ParametersPanel::onGyrationChosen);
    connect(m_mode, &QComboBox::activated, this, &ParametersPanel::onModeChosen);
}

ParametersPanel::Row ParametersPanel::addRow(const QString& name, const SystemParameter& parameter,
                                             double value) {
    const double lo = parameter.sliderMin, hi = parameter.sliderMax;
    const QString unit = QString::fromUtf8(parameter.unit);
    const QString caption = QString::fromUtf8(parameter.symbol);
    Row row;
    row.spin = new NumberField(name == QStringLiteral("speed") ? caption : name);
    row.spin->setObjectName(QStringLiteral("spin_") + name);
    if (parameter.bound != ParameterBound::Any) // the bound deriveSystem checks, said at once
        row.spin->setMinimum(0, parameter.bound == ParameterBound::Positive);
    row.spin->setZeroStep(std::pow(10.0, std::floor(std::log10((hi - lo) / 100))));
    row.spin->setUnit(unit);
    row.spin->setValue(value);
    row.slider = new QSlider(Qt::Horizontal);
    row.slider->setObjectName(QStringLiteral("slider_") + name);
    row.slider->setRange(0, kSliderSteps);
    row.slider->setValue(toSlider(value, lo, hi));
    QString tip = tr("%1 [%2]: %3; slider %4 \u2026 %5 %2; type any value or an expression such "
                     "as 2*pi or 1e6")
                      .arg(translated(parameter.label), unit, translated(parameter.tooltip))
                      .arg(lo)
                      .arg(hi);
    row.spin->setToolTip(tip);
    row.slider->setToolTip(tip);
    auto* line = new QWidget;
    auto* h = new QHBoxLayout(line);
    h->setContentsMargins(0, 0, 0, 0);
    h->addWidget(row.spin);
    h->addWidget(row.slider, 1);
    auto* captionLabel = new QLabel(caption + QStringLiteral(":"));
    captionLabel->setToolTip(tip);
    captionLabel->setBuddy(row.spin);
    m_form->addRow(captionLabel, line);

    NumberField* spin = row.spin;
    QSlider* slider = row.slider;
    connect(spin, &NumberField::messageChanged, this, [this](const QString& message) {
        m_error->setText(message);
        m_error->setVisible(!message.isEmpty());
    });
    connect(spin, &NumberField::valueChanged, this, [=, this](double v) {
        if (m_updating)
            return;
        m_updating = true;
        slider->setValue(toSlider(v, lo, hi));
        m_updating = false;
        onValueChanged(name, v);
    });
    connect(slider, &QSlider::valueChanged, this, [=, this](int pos) {
        if (m_updating)
            return;
        double v = lo + (hi - lo) * pos / kSliderSteps;
        m_updating = true;
        spin->setValue(v);
        m_updating = false;
        onValueChanged(name, v);
    });
    return row;
}

void ParametersPanel::rebuildRows() {
    while (m_form->rowCount() > 0)
        m_form->removeRow(0);
    m_rows.clear();
    for (const SystemParameter& parameter : systemParameters(m_scene.system.kind)) {
        auto it = m_scene.system.params.find(parameter.name);
        if (it == m_scene.system.params.end())
            continue; // the sleigh has b or I, not both
        QString name = QString::fromUtf8(parameter.name);
        m_rows[name] = addRow(name, parameter, it->second);
    }
    const SystemParameter& speed = speedParameter(m_scene.mode);
    m_speedLabel->setText(translated(speed.tooltip));
    m_rows[QStringLiteral("speed")] = addRow(QStringLiteral("speed"), speed, m_scene.speed);
}

void ParametersPanel::setScene(const Scene& scene) {
    // the panel's own edit coming back, or a change elsewhere in the scene: nothing to show anew
    if (m_shown && scene.system == m_scene.system && scene.mode == m_scene.mode &&
        scene.speed == m_scene.speed) {
        m_scene = scene;
        return;
    }
    m_shown = true;
    m_updating = true;
    // new rows when the parameter names (or the speed's name) change
    std::set<QString> shown, wanted{QStringLiteral("speed")};
    for (const auto& row : m_rows)
        shown.insert(row.first);
    for (const auto& param : scene.system.params)
        wanted.insert(QString::fromStdString(param.first));
    bool rebuild = shown != wanted || scene.mode != m_scene.mode;
    m_scene = scene;
    m_system->setCurrentIndex(m_system->findData(int(scene.system.kind)));
    bool sleigh = scene.system.kind == SystemKind::Sleigh;
    m_gyration->setVisible(sleigh);
    m_gyrationLabel->setVisible(sleigh);
    m_gyration->setCurrentIndex(scene.system.params.count("I") ? 1 : 0);
    m_mode->setCurrentIndex(scene.mode == SpeedMode::Energy ? 0 : 1);
    if (rebuild) {
        rebuildRows();
    } else {
        for (auto& [name, row] : m_rows) {
            double v = name == QStringLiteral("speed") ? scene.speed
                                                       : scene.system.params.at(name.toStdString());
            if (row.spin->value() != v) {
                row.spin->setValue(v);
                const SystemParameter& parameter =
                    name == QStringLiteral("speed")
                        ? speedParameter(m_scene.mode)
                        : *findSystemParameter(m_scene.system.kind, name.toStdString());
                row.slider->setValue(toSlider(v, parameter.sliderMin, parameter.sliderMax));
            }
        }
    }
    m_updating = false;
}

void ParametersPanel::showDerived(const DerivedSystem* d) {
    if (!d) {
        m_derived->setText(tr("(no valid system)"));
        return;
    }
    m_derived->setText(
        tr("m_eff = %1 kg, CM offset = %2 m, b = %3 m, I about the CM = %4 kg m\u00b2")
            .arg(d->mass, 0, 'g', 5)
            .arg(d->a, 0, 'g', 5)
            .arg(d->b, 0, 'g', 5)
            .arg(d->inertia(), 0, 'g', 5));
}

void ParametersPanel::showError(const QString& message) {
    m_error->setText(message);
    m_error->setVisible(!message.isEmpty());
    // the entry that was refused stays marked until a value is accepted: what is shown red is
    // not what is used
    for (auto& [name, row] : m_rows) {
        // a field's own refusal stays marked too
        bool invalid =
            (!message.isEmpty() && name == m_lastEdited) || !row.spin->message().isEmpty();
        if (row.spin->property("invalid").toBool() == invalid)
            continue;
        row.spin->setProperty("invalid", invalid);
        row.spin->setStyleSheet(invalid ? QStringLiteral("QAbstractSpinBox { border: 2px solid "
                                                         "#b00020; background: #fdecee; }")
                                        : QString());
        row.spin->setAccessibleDescription(invalid ? tr("invalid: %1").arg(message) : QString());
    }
}

bool ParametersPanel::isMarkedInvalid(const QString& name) const {
    auto it = m_rows.find(name);
    return it != m_rows.end() && it->second.spin->property("invalid").toBool();
}

QString ParametersPanel::errorText() const {
    return m_error->isVisible() ? m_error->text() : QString();
}

NumberField* ParametersPanel::spinBox(const QString& name) const {
    auto it = m_rows.find(name);
    return it == m_rows.end() ? nullptr : it->second.spin;
}

QSlider* ParametersPanel::slider(const QString& name) const {
    auto it = m_rows.find(name);
    return it == m_rows.end() ? nullptr : it->second.slider;
}

void ParametersPanel::onValueChanged(const QString& name, double value) {
    m_lastEdited = name;
    if (name == QStringLiteral("speed"))
        m_scene.speed = value;
    else
        m_scene.system.params[name.toStdString()] = value;
    emitEdit(tr("Change %1 to %2")
                 .arg(name == QStringLiteral("speed") ? tr("speed") : name)
                 .arg(value, 0, 'g', 4),
             QStringLiteral("param:") + name);
}

void ParametersPanel::onSystemChosen(int index) {
    auto kind = static_cast<SystemKind>(m_system->itemData(index).toInt());
    if (kind == m_scene.system.kind)
        return;
    Scene next = m_scene;
    next.system.kind = kind;
    next.system.params = defaultSystemParams(kind);
    setScene(next);
    emitEdit(tr("Choose the %1").arg(m_system->currentText()), {});
}

void ParametersPanel::onGyrationChosen(int index) {
    bool wantI = index == 1;
    if (wantI == (m_scene.system.params.count("I") > 0))
        return;
    Scene next = m_scene;
    try {
        DerivedSystem d = deriveSystem(m_scene.system);
        setSystemParameter(next.system, wantI ? "I" : "b", wantI ? d.inertia() : d.b);
    } catch (const InputError& e) {
        showError(QString::fromStdString(e.what()));
        return;
    }
    setScene(next);
    emitEdit(wantI ? tr("Enter I instead of b") : tr("Enter b instead of I"), {});
}

void ParametersPanel::onModeChosen(int index) {
    SpeedMode mode = index == 0 ? SpeedMode::Energy : SpeedMode::Speed;
    if (mode == m_scene.mode)
        return;
    Scene next = m_scene;
    next.mode = mode;
    setScene(next);
    emitEdit(mode == SpeedMode::Energy ? tr("Constant energy") : tr("Constant speed"), {});
}

void ParametersPanel::emitEdit(const QString& description, const QString& mergeKey) {
    emit sceneEdited(m_scene, description, mergeKey);
}

} // namespace chaplygin::ui
