#include "panels/sweep_panel.h"

#include "common/input_error.h"
#include "document/job_runner.h"
#include "document/scene_document.h"
#include "plots/sweep_plot.h"
#include "widgets/number_field.h"

#include <qcustomplot.h>

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

#include <cmath>
#include <exception>

namespace chaplygin::ui {

SweepPanel::SweepPanel(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_runner(new JobRunner(this)) {
    m_parameter = new QComboBox;
    m_parameter->setToolTip(tr("The parameter to vary; the others keep the scene's values"));
    m_from = new NumberField(tr("from"));
    m_to = new NumberField(tr("to"));
    m_count = new NumberField(tr("values"));
    m_count->setIntegers(true);
    m_count->setMinimum(2);
    m_count->setMaximum(1000);
    m_count->setValue(12);
    for (NumberField* field : {m_from, m_to, m_count})
        connect(field, &NumberField::messageChanged, this, [this](const QString& message) {
            if (!message.isEmpty())
                m_status->setText(QStringLiteral("<span style='color:#b00'>%1</span>")
                                      .arg(message.toHtmlEscaped()));
        });
    m_quantity = new QComboBox;
    for (int q = 0; q < kSweepQuantityCount; ++q)
        m_quantity->addItem(QCoreApplication::translate(
            "SweepQuantity", sweepQuantityLabel(static_cast<SweepQuantity>(q)).c_str()));
    m_quantity->setCurrentIndex(static_cast<int>(SweepQuantity::MaxAbsLambda));
    m_run = new QPushButton(tr("Run sweep"));
    m_cancel = new QPushButton(tr("Cancel"));
    m_cancel->setEnabled(false);
    m_progress = new QProgressBar;
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_status = new QLabel(tr("Choose a parameter and a range, then Run sweep. Click a point to "
                             "load its value."));
    m_status->setWordWrap(true);
    m_plot = new QCustomPlot;
    m_plot->setMinimumHeight(80); // the dock shares the plots' height on a 1280x800 screen
    m_plot->setInteraction(QCP::iSelectPlottables, false);

    auto* range = new QHBoxLayout;
    range->addWidget(m_parameter);
    range->addWidget(new QLabel(tr("from")));
    range->addWidget(m_from);
    range->addWidget(new QLabel(tr("to")));
    range->addWidget(m_to);
    range->addWidget(new QLabel(tr("values")));
    range->addWidget(m_count);
    range->addStretch();
    auto* show = new QHBoxLayout;
    show->addWidget(new QLabel(tr("Plot")));
    show->addWidget(m_quantity, 1);
    show->addWidget(m_run);
    show->addWidget(m_cancel);
    show->addWidget(m_progress, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(range);
    layout->addLayout(show);
    layout->addWidget(m_status);
    layout->addWidget(m_plot, 1);

    connect(m_run, &QPushButton::clicked, this, &SweepPanel::start);
    connect(m_cancel, &QPushButton::clicked, this, &SweepPanel::cancel);
    connect(m_quantity, &QComboBox::currentIndexChanged, this, &SweepPanel::redraw);
    connect(m_parameter, &QComboBox::currentIndexChanged, this, &SweepPanel::onParameterChosen);
    connect(m_runner, &JobRunner::progress, this, [this](int done, int total) {
        m_progress->setRange(0, std::max(total, 1));
        m_progress->setValue(done);
    });
    connect(m_runner, &JobRunner::finished, this, &SweepPanel::onFinished);
    connect(m_document, &SceneDocument::solutionChanged, this, &SweepPanel::onSceneChanged);
    connect(m_plot, &QCustomPlot::mousePress, this, &SweepPanel::onPlotClicked);
    onSceneChanged();
}

SweepPanel::~SweepPanel() {
    m_runner->disconnect(this);
}

bool SweepPanel::isRunning() const {
    return m_runner->isRunning();
}

QString SweepPanel::statusText() const {
    return m_status->text();
}

void SweepPanel::onSceneChanged() {
    // the sweep would describe a scene that is no longer shown
    if (m_runner->isRunning() && m_document->solution() &&
        m_document->solution()->scene() != m_runScene) {
        m_sceneChanged = true;
        m_runner->cancel();
    }
    const Scene& scene = m_document->scene();
    if (m_namesShown && scene.system.kind == m_shownKind && scene.mode == m_shownMode)
        return;
    m_namesShown = true;
    m_shownKind = scene.system.kind;
    m_shownMode = scene.mode;
    QString keep = m_parameter->currentText();
    QSignalBlocker block(m_parameter);
    m_parameter->clear();
    for (const std::string& name : sweepParameterNames(scene.system.kind, scene.mode))
        m_parameter->addItem(QString::fromStdString(name));
    int index = m_parameter->findText(keep);
    m_parameter->setCurrentIndex(index >= 0 ? index : 0);
    if (index < 0)
        onParameterChosen();
}

void SweepPanel::onParameterChosen() {
    // a range around the scene's value: half to twice it
    double v = 1;
    try {
        v = sceneParameter(m_document->scene(), m_parameter->currentText().toStdString());
    } catch (const InputError&) {
    }
    double lo = v > 0 ? 0.5 * v : v - 1, hi = v > 0 ? 2 * v : v + 1;
    m_from->setValue(lo);
    m_to->setValue(hi);
}

void SweepPanel::start() {
    if (m_runner->isRunning() || !m_document->solution())
        return;
    m_runScene = m_document->solution()->scene();
    SweepSpec spec{m_parameter->currentText().toStdString(), m_from->value(), m_to->value(),
                   int(m_count->value())};
    try {
        validateSweep(m_runScene, spec);
    } catch (const InputError& e) {
        m_status->setText(QStringLiteral("<span style='color:#b00'>%1</span>")
                              .arg(QString::fromStdString(e.what()).toHtmlEscaped()));
        return;
    }
    m_outcome = std::make_shared<Outcome>();
    m_sceneChanged = false;
    m_progress->setRange(0, spec.count);
    m_progress->setValue(0);
    m_run->setEnabled(false);
    m_cancel->setEnabled(true);
    m_status->setText(tr("Sweeping %1 over %2 values\u2026")
                          .arg(QString::fromStdString(spec.parameter))
                          .arg(spec.count));
    m_runner->start([scene = m_runScene, spec, out = m_outcome](
                        const std::atomic<bool>& stop, const JobRunner::Progress& progress) {
        SweepOptions options;
        options.cancel = &stop;
        options.progress = progress;
        try {
            out->report = runParameterSweep(scene, spec, options);
        } catch (const std::exception& e) {
            out->error = QString::fromStdString(e.what());
        }
    });
}

void SweepPanel::cancel() {
    m_runner->cancel();
}

void SweepPanel::waitForFinished() {
    m_runner->waitForFinished();
}

void SweepPanel::onFinished() {
    m_run->setEnabled(true);
    m_cancel->setEnabled(false);
    if (!m_outcome)
        return;
    if (!m_outcome->error.isEmpty()) {
        m_status->setText(tr("The sweep failed: %1").arg(m_outcome->error));
    } else if (m_outcome->report) {
        m_report = m_outcome->report;
        const SweepReport& r = *m_report;
        const QString name = QString::fromStdString(r.spec.parameter);
        QString what =
            r.rows.size() == 1
                ? tr("1 value of %1 from %2 to %3").arg(name).arg(r.spec.from).arg(r.spec.to)
                : tr("%1 values of %2 from %3 to %4")
                      .arg(r.rows.size())
                      .arg(name)
                      .arg(r.spec.from)
                      .arg(r.spec.to);
        m_status->setText(!r.cancelled ? tr("%1. Click a point to load it.").arg(what)
                          : m_sceneChanged
                              ? tr("Cancelled (the scene changed) after %1.").arg(what)
                              : tr("Cancelled after %1. Click a point to load it.").arg(what));
        if (!r.cancelled)
            m_progress->setValue(m_progress->maximum());
        redraw();
    }
    m_outcome.reset();
    emit finished();
}

void SweepPanel::redraw() {
    if (!m_report)
        return;
    drawSweep(*m_plot, *m_report, static_cast<SweepQuantity>(m_quantity->currentIndex()));
    m_plot->replot();
}

void SweepPanel::onPlotClicked(QMouseEvent* event) {
    if (!m_report || m_report->rows.empty())
        return;
    int best = -1;
    double bestDistance = 12; // px
    auto q = static_cast<SweepQuantity>(m_quantity->currentIndex());
    for (std::size_t i = 0; i < m_report->rows.size(); ++i) {
        double px = m_plot->xAxis->coordToPixel(m_report->rows[i].value);
        double py = m_plot->yAxis->coordToPixel(sweepQuantityValue(m_report->rows[i], q));
        double d = std::hypot(px - event->position().x(), py - event->position().y());
        if (d < bestDistance) {
            bestDistance = d;
            best = static_cast<int>(i);
        }
    }
    if (best >= 0)
        loadRow(best);
}

void SweepPanel::loadRow(int row) {
    if (!m_report || row < 0 || row >= static_cast<int>(m_report->rows.size()))
        return;
    double value = m_report->rows[row].value;
    const std::string& name = m_report->spec.parameter;
    Scene scene;
    try {
        scene = sceneWithParameter(m_document->scene(), name, value);
    } catch (const InputError& e) {
        m_status->setText(QString::fromStdString(e.what()));
        return;
    }
    emit sceneEdited(
        scene,
        tr("Set %1 = %2 from the sweep").arg(QString::fromStdString(name)).arg(value, 0, 'g', 6),
        QString());
}

} // namespace chaplygin::ui
