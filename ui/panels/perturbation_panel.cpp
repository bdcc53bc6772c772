#include "panels/perturbation_panel.h"

#include "common/input_error.h"
#include "scene/perturbation.h"
#include "widgets/number_field.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace chaplygin::ui {

namespace {
// the feedback rate's slider: P from 0.1 to 5 per metre in steps of 0.01
constexpr double kRateLo = 0.1, kRateHi = 5, kRateStep = 0.01;
} // namespace

PerturbationPanel::PerturbationPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    m_enabled = new QCheckBox(tr("Perturbed bodies (open loop and feedback)"));
    m_enabled->setObjectName(QStringLiteral("perturbationEnabled"));
    m_enabled->setToolTip(tr("Two more bodies start from the controlled one moved by the offsets "
                             "and get the push: one keeps the nominal \u03bb(t), one is steered "
                             "back by feedback (docs/physics.md \u00a7"
                             "9)"));
    layout->addWidget(m_enabled);
    m_fields = new QWidget;
    auto* form = new QFormLayout(m_fields);
    form->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_fields);

    auto row = [form](const QString& label, QWidget* w) { form->addRow(label, w); };
    row(tr("offset dy (left)"), addSpin(QStringLiteral("dy"), 0.01, QStringLiteral("m")));
    row(tr("heading offset d\u03c6"), addSpin(QStringLiteral("dphi"), 0.01, QStringLiteral("rad")));
    row(tr("control angle offset d\u03a8"),
        addSpin(QStringLiteral("dpsi"), 0.01, QStringLiteral("rad")));
    m_push = new QCheckBox(tr("push at t"));
    m_push->setObjectName(QStringLiteral("perturbationPush"));
    form->addRow(m_push, addSpin(QStringLiteral("t_push"), 0.1, QStringLiteral("s")));
    row(tr("push: \u03a8 jumps by"),
        addSpin(QStringLiteral("push_psi"), 0.01, QStringLiteral("rad")));
    row(tr("push: P moves left by"), addSpin(QStringLiteral("push_dy"), 0.01, QStringLiteral("m")));

    m_rateSlider = new QSlider(Qt::Horizontal);
    m_rateSlider->setObjectName(QStringLiteral("feedbackRateSlider"));
    m_rateSlider->setRange(0, int(std::lround((kRateHi - kRateLo) / kRateStep)));
    NumberField* rate = addSpin(QStringLiteral("feedback_rate"), 0.1, QStringLiteral("1/m"));
    auto* rateRow = new QHBoxLayout;
    rateRow->addWidget(m_rateSlider, 1);
    rateRow->addWidget(rate);
    form->addRow(tr("feedback rate P"), rateRow);
    m_limit = new QCheckBox(tr("limit |\u03a8\u0307| to"));
    m_limit->setObjectName(QStringLiteral("perturbationLimit"));
    form->addRow(m_limit, addSpin(QStringLiteral("feedback_limit"), 0.1, tr("rad/s")));
    m_controllerB = new QCheckBox(tr("controller's b"));
    m_controllerB->setObjectName(QStringLiteral("perturbationControllerB"));
    m_controllerB->setToolTip(tr("The b the feedback assumes; unchecked, the plant's own"));
    form->addRow(m_controllerB, addSpin(QStringLiteral("controller_b"), 0.01, QStringLiteral("m")));
    m_error = new QLabel;
    m_error->setObjectName(QStringLiteral("perturbationError"));
    m_error->setWordWrap(true);
    m_error->setStyleSheet(QStringLiteral("color: #b00020"));
    m_error->hide();
    layout->addWidget(m_error);
    layout->addStretch(1);

    connect(m_enabled, &QCheckBox::toggled, this, [this](bool on) {
        if (!m_updating)
            emitEdit(on ? tr("Perturb the bodies") : tr("Remove the perturbation"));
    });
    for (QCheckBox* box : {m_push, m_limit, m_controllerB})
        connect(box, &QCheckBox::toggled, this, [this, box] {
            if (!m_updating)
                emitEdit(tr("Change the perturbation: %1").arg(box->text()));
        });
    connect(m_rateSlider, &QSlider::valueChanged, this, [this, rate](int v) {
        if (m_updating)
            return;
        m_updating = true;
        rate->setValue(kRateLo + v * kRateStep);
        m_updating = false;
        emitEdit(tr("Change the feedback rate"), QStringLiteral("perturbation/feedback_rate"));
    });
    connect(rate, &NumberField::valueChanged, this, [this](double v) {
        if (m_updating)
            return;
        m_updating = true;
        m_rateSlider->setValue(
            int(std::lround((std::clamp(v, kRateLo, kRateHi) - kRateLo) / kRateStep)));
        m_updating = false;
    });
    setScene(Scene());
}

NumberField* PerturbationPanel::addSpin(const QString& field, double zeroStep,
                                        const QString& unit) {
    auto* spin = new NumberField(field);
    spin->setObjectName(QStringLiteral("perturbation_") + field);
    spin->setZeroStep(zeroStep);
    spin->setUnit(unit);
    // the core's bound of the field (|d\u03c6| < \u03c0/2, P > 0, ...), said at once
    spin->setCheck([field](double value) {
        Perturbation scratch;
        try {
            setPerturbationField(scratch, field.toStdString(), value);
        } catch (const InputError& e) {
            return QString::fromStdString(e.what());
        }
        return QString();
    });
    connect(spin, &NumberField::messageChanged, this, &PerturbationPanel::showError);
    // spin arrows held down merge into one undo step, like the parameters' sliders
    connect(spin, &NumberField::valueChanged, this, [this, field] {
        if (!m_updating)
            emitEdit(tr("Change the perturbation: %1").arg(field),
                     QStringLiteral("perturbation/") + field);
    });
    m_spins.emplace_back(field, spin);
    return spin;
}

NumberField* PerturbationPanel::spin(const QString& field) const {
    for (const auto& [name, spin] : m_spins)
        if (name == field)
            return spin;
    return nullptr;
}

Perturbation PerturbationPanel::fromWidgets() const {
    Perturbation p;
    p.dy = spin(QStringLiteral("dy"))->value();
    p.dphi = spin(QStringLiteral("dphi"))->value();
    p.dpsi = spin(QStringLiteral("dpsi"))->value();
    if (m_push->isChecked()) {
        p.tPush = spin(QStringLiteral("t_push"))->value();
        p.pushPsi = spin(QStringLiteral("push_psi"))->value();
        p.pushDy = spin(QStringLiteral("push_dy"))->value();
    }
    p.feedbackRate = spin(QStringLiteral("feedback_rate"))->value();
    if (m_limit->isChecked())
        p.feedbackLimit = spin(QStringLiteral("feedback_limit"))->value();
    if (m_controllerB->isChecked())
        p.controllerB = spin(QStringLiteral("controller_b"))->value();
    return p;
}

void PerturbationPanel::emitEdit(const QString& description, const QString& mergeKey) {
    Scene next = m_scene;
    if (m_enabled->isChecked())
        next.perturbation = fromWidgets();
    else
        next.perturbation.reset();
    updateEnabled();
    m_scene = next;
    emit sceneEdited(next, description, mergeKey);
}

void PerturbationPanel::updateEnabled() {
    m_fields->setEnabled(m_enabled->isChecked());
    for (const char* f : {"t_push", "push_psi", "push_dy"})
        spin(QLatin1String(f))->setEnabled(m_push->isChecked());
    spin(QStringLiteral("feedback_limit"))->setEnabled(m_limit->isChecked());
    spin(QStringLiteral("controller_b"))->setEnabled(m_controllerB->isChecked());
}

void PerturbationPanel::setScene(const Scene& scene) {
    m_scene = scene;
    m_updating = true;
    const Perturbation p = scene.perturbation.value_or(Perturbation());
    m_enabled->setChecked(scene.perturbation.has_value());
    spin(QStringLiteral("dy"))->setValue(p.dy);
    spin(QStringLiteral("dphi"))->setValue(p.dphi);
    spin(QStringLiteral("dpsi"))->setValue(p.dpsi);
    m_push->setChecked(p.tPush.has_value());
    spin(QStringLiteral("t_push"))->setValue(p.tPush.value_or(1.0));
    spin(QStringLiteral("push_psi"))->setValue(p.pushPsi);
    spin(QStringLiteral("push_dy"))->setValue(p.pushDy);
    spin(QStringLiteral("feedback_rate"))->setValue(p.feedbackRate);
    m_rateSlider->setValue(
        int(std::lround((std::clamp(p.feedbackRate, kRateLo, kRateHi) - kRateLo) / kRateStep)));
    m_limit->setChecked(p.feedbackLimit.has_value());
    spin(QStringLiteral("feedback_limit"))->setValue(p.feedbackLimit.value_or(1.0));
    m_controllerB->setChecked(p.controllerB.has_value());
    spin(QStringLiteral("controller_b"))
        ->setValue(p.controllerB.value_or(
            scene.system.params.count("b") ? scene.system.params.at("b") : 1.0));
    m_updating = false;
    updateEnabled();
}

void PerturbationPanel::showError(const QString& message) {
    m_error->setText(message);
    m_error->setVisible(!message.isEmpty());
}

} // namespace chaplygin::ui
