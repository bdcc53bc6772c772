#include "panels/methods_panel.h"

#include "common/input_error.h"
#include "document/job_runner.h"
#include "document/method_names.h"
#include "document/scene_document.h"
#include "plots/plot_context_menu.h"
#include "plots/work_precision_plot.h"

#include <qcustomplot.h>

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QStyle>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <exception>

namespace chaplygin::ui {

namespace {

QString number(double v) {
    return QString::number(v, 'g', 3);
}

// the tolerance or step size, where the method has one
QString settingText(const WorkPrecisionRow& r) {
    if (r.setting == 0)
        return {};
    return QStringLiteral(" (%1)").arg(number(r.setting));
}

} // namespace

MethodsPanel::MethodsPanel(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_runner(new JobRunner(this)) {
    m_run = new QPushButton(tr("Compute work-precision"));
    m_run->setToolTip(tr("Sweep every method's tolerances and step sizes for the current scene "
                         "(Ctrl+Shift+W)"));
    m_cancel = new QPushButton(tr("Cancel"));
    m_cancel->setEnabled(false);
    m_progress = new QProgressBar;
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_progress->setTextVisible(true);
    m_status = new QLabel(tr("Error against cost per solve for every method: press Compute."));
    m_status->setWordWrap(true);
    m_references = new QLabel;
    m_references->setWordWrap(true);
    m_references->setTextInteractionFlags(Qt::TextSelectableByMouse);

    m_plot = new QCustomPlot;
    m_plot->setMinimumHeight(120); // the tabified plots dock may be low on a 1280 x 800 screen
    m_plot->setNoAntialiasingOnDrag(true);

    m_table = new QTableWidget(0, 5);
    m_table->setHorizontalHeaderLabels(
        {tr("problem"), tr("chosen method"), tr("error [m]"), tr("s/solve"), tr("Pareto")});
    m_table->verticalHeader()->hide();
    // the short columns as wide as their titles and cells; the method's name takes what is left
    // and is elided, whole in its tooltip
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
    m_table->setTextElideMode(Qt::ElideRight);
    m_table->setWordWrap(false);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_table->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_table->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    m_table->setMaximumHeight(m_table->horizontalHeader()->sizeHint().height() * 4);
    m_table->setTabKeyNavigation(false); // Tab leaves the table
    fitColumns();
    m_plotMenu = installPlotExportMenu(
        m_plot, [] { return QStringLiteral("work_precision"); },
        [this](const QString& error) { m_status->setText(error); });

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_run);
    buttons->addWidget(m_cancel);
    buttons->addWidget(m_progress, 1);

    auto* side = new QVBoxLayout;
    side->addWidget(m_status);
    side->addWidget(m_table);
    side->addWidget(m_references);
    side->addStretch(1);

    auto* sideWidget = new QWidget;
    sideWidget->setLayout(side);
    sideWidget->setMaximumWidth(450);
    side->setContentsMargins(0, 0, 0, 0);
    auto* body = new QHBoxLayout;
    body->addWidget(m_plot, 1);
    body->addWidget(sideWidget);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(buttons);
    layout->addLayout(body, 1);

    connect(m_run, &QPushButton::clicked, this, &MethodsPanel::start);
    connect(m_cancel, &QPushButton::clicked, this, &MethodsPanel::cancel);
    connect(m_runner, &JobRunner::progress, this, &MethodsPanel::onProgress);
    connect(m_runner, &JobRunner::finished, this, &MethodsPanel::onFinished);
    connect(m_document, &SceneDocument::solutionChanged, this, &MethodsPanel::onSceneChanged);
}

// the table never narrower than its short columns and the method column's title
void MethodsPanel::fitColumns() {
    QHeaderView* header = m_table->horizontalHeader();
    const int padding = 2 * m_table->style()->pixelMetric(QStyle::PM_FocusFrameHMargin) + 8;
    int width = 2 * m_table->frameWidth();
    for (int c = 0; c < m_table->columnCount(); ++c) {
        const QString title = m_table->horizontalHeaderItem(c)->text();
        int column = c == 1 ? header->fontMetrics().horizontalAdvance(title) + 2 * padding
                            : header->sectionSizeHint(c);
        for (int r = 0; c != 1 && r < m_table->rowCount(); ++r)
            if (const QTableWidgetItem* item = m_table->item(r, c))
                column = std::max(column,
                                  m_table->fontMetrics().horizontalAdvance(item->text()) + padding);
        width += column;
    }
    m_table->setMinimumWidth(width);
}

MethodsPanel::~MethodsPanel() {
    // the runner (a child) cancels and waits for the worker when it is destroyed
    m_runner->disconnect(this);
}

bool MethodsPanel::isRunning() const {
    return m_runner->isRunning();
}

QString MethodsPanel::statusText() const {
    return m_status->text();
}

void MethodsPanel::start() {
    if (isRunning() || !m_document->solution())
        return;
    m_runScene = m_document->solution()->scene();
    m_cancelReason.clear();
    m_outcome = std::make_shared<Outcome>();
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_run->setEnabled(false);
    m_cancel->setEnabled(true);
    m_status->setText(tr("Sweeping the methods in a worker thread\u2026"));
    // the worker owns a copy of the scene and builds its own path
    m_runner->start([scene = m_runScene, out = m_outcome](const std::atomic<bool>& stop,
                                                          const JobRunner::Progress& progress) {
        WorkPrecisionOptions options;
        options.cancel = &stop;
        options.progress = progress;
        try {
            out->report = runWorkPrecision(scene, options);
        } catch (const InputError& e) {
            out->error = QString::fromStdString(e.what());
        } catch (const std::exception& e) {
            out->error = tr("internal error: %1").arg(QString::fromUtf8(e.what()));
        }
    });
}

void MethodsPanel::cancel() {
    if (!isRunning())
        return;
    m_runner->cancel();
    if (m_cancelReason.isEmpty())
        m_cancelReason = tr("cancelled");
    m_cancel->setEnabled(false);
    m_status->setText(tr("Cancelling after the configuration under way\u2026"));
}

void MethodsPanel::waitForFinished() {
    m_runner->waitForFinished();
}

void MethodsPanel::onProgress(int done, int total) {
    m_progress->setRange(0, std::max(total, 1));
    m_progress->setValue(done);
}

void MethodsPanel::onSceneChanged() {
    if (isRunning() && m_document->solution() && m_document->solution()->scene() != m_runScene) {
        m_cancelReason = tr("cancelled: the scene changed");
        cancel();
    } else if (!isRunning() && m_report && m_document->solution() &&
               m_document->solution()->scene() != m_runScene) {
        clearReport();
    }
}

void MethodsPanel::clearReport() {
    // a diagram of another scene would be read as this one's
    m_report.reset();
    m_plot->clearPlottables();
    m_plot->plotLayout()->clear();
    m_plot->replot();
    m_table->setRowCount(0);
    m_references->clear();
    m_progress->setValue(0);
    m_status->setText(tr("The scene changed: press Compute for this scene's diagram."));
}

void MethodsPanel::onFinished() {
    if (!m_outcome)
        return;
    Outcome out = std::move(*m_outcome);
    m_outcome.reset();
    m_run->setEnabled(true);
    m_cancel->setEnabled(false);
    if (!out.error.isEmpty()) {
        m_status->setText(tr("The sweep failed: %1").arg(out.error));
        m_progress->setRange(0, 1);
        m_progress->setValue(0);
        emit finished();
        return;
    }
    m_progress->setValue(m_progress->maximum());
    m_report = std::move(out.report);
    showReport(*m_report);
    if (m_document->solution() && m_document->solution()->scene() != m_runScene &&
        !m_report->cancelled)
        clearReport();
    emit finished();
}

void MethodsPanel::showReport(const WorkPrecisionReport& report) {
    drawWorkPrecision(*m_plot, report);
    // the dock is shorter than an exported figure: each legend moves from inside its panel to a
    // column beside it, so that no curve hides behind a legend
    auto* panels = qobject_cast<QCPLayoutGrid*>(m_plot->plotLayout()->element(0, 0));
    QList<QCPAxisRect*> rects = m_plot->axisRects();
    for (int k = 0; panels && k < rects.size(); ++k) {
        QCPLayoutInset* inset = rects[k]->insetLayout();
        for (int i = inset->elementCount() - 1; i >= 0; --i) {
            auto* legend = qobject_cast<QCPLegend*>(inset->elementAt(i));
            if (!legend || !inset->take(legend))
                continue;
            inset->simplify();
            legend->setRowSpacing(0);
            legend->setIconSize(14, 8);
            legend->setMargins(QMargins(2, 2, 2, 2));
            legend->setBorderPen(Qt::NoPen);
            panels->insertColumn(2 * k + 1);
            panels->addElement(0, 2 * k + 1, legend);
            panels->setColumnStretchFactor(2 * k + 1, 0.01);
        }
    }
    m_plot->replot();

    m_table->setRowCount(0);
    for (std::size_t i = 0; i < report.rows.size(); ++i) {
        const WorkPrecisionRow& r = report.rows[i];
        if (!r.chosen)
            continue;
        int row = m_table->rowCount();
        m_table->insertRow(row);
        const bool front = onParetoFront(report.rows, i);
        const QString problem =
            r.problem == MotionProblem::Controlled ? tr("controlled") : tr("free");
        const QStringList cells = {problem, plainMethodName(r.method) + settingText(r),
                                   number(r.error), number(r.seconds),
                                   front ? tr("yes") : tr("no")};
        for (int c = 0; c < cells.size(); ++c)
            m_table->setItem(row, c, new QTableWidgetItem(cells[c]));
        // the whole name and the registry's id
        m_table->item(row, 1)->setToolTip(cells[1] + QStringLiteral("\n") +
                                          QString::fromStdString(r.method));
    }
    fitColumns();
    // the references by their plain names; the registry's ids in the tooltip
    QString controlled = plainMethodName(report.controlledReferenceMethod);
    if (report.controlledReferenceTightest)
        controlled = tr("%1, Gauss\u2013Kronrod 61 at tolerance 1e-14 (the tightest method)")
                         .arg(controlled);
    else if (!report.controlledReferenceIndependent)
        controlled = tr("%1 (no independent method for this path)").arg(controlled);
    m_references->setText(tr("<b>References</b><br>controlled: %1<br>free: %2")
                              .arg(controlled.toHtmlEscaped(),
                                   plainMethodName(report.freeReferenceMethod).toHtmlEscaped()));
    m_references->setToolTip(tr("controlled: %1\nfree: %2")
                                 .arg(QString::fromStdString(report.controlledReferenceMethod),
                                      QString::fromStdString(report.freeReferenceMethod)));
    QString summary = tr("%1 configurations; horizons %2 s (controlled), %3 s (free).")
                          .arg(report.rows.size())
                          .arg(number(report.controlledEnd), number(report.freeEnd));
    if (report.cancelled)
        summary = tr("Stopped (%1) after %2").arg(m_cancelReason, summary);
    m_status->setText(summary);
}

} // namespace chaplygin::ui
