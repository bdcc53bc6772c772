#include "panels/accuracy_readout.h"

#include "document/math_text.h"
#include "document/method_names.h"
#include "document/scene_document.h"
#include "scene/paper_closed_form.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QResizeEvent>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <optional>

namespace chaplygin::ui {

namespace {

// The read-out changes at most four times a second, as a meter's display does: faster digits
// cannot be read, and each change of its word-wrapped values lays out the dock (a twelfth of an
// animation frame at 1920 x 1080, docs/numerics.md §7).
constexpr int kRefreshMs = 250;

// the path's own point at the arc length s, looked up independently of the time law
double distanceFromPath(const Path& path, const MotionSample& m) {
    const auto& pieces = path.pieces();
    std::size_t k = 0;
    while (k + 1 < pieces.size() && pieces[k + 1].s0 <= m.s)
        ++k;
    const PathPiece& piece = pieces[k];
    if (piece.kind == PathPiece::Kind::Pivot)
        return std::hypot(m.x - piece.x, m.y - piece.y);
    PathNode n = piece.table->at(piece.table->uAtArcLength(m.s - piece.s0));
    return std::hypot(m.x - n.x, m.y - n.y);
}

QString metres(double v) {
    return QStringLiteral("%1 m").arg(v, 0, 'e', 1);
}

QString formatTime(double t) {
    return QStringLiteral("%1 s").arg(t, 0, 'f', 3);
}

QString relative(double v) {
    return QString::number(v, 'e', 1);
}

QLabel* valueLabel() {
    auto* l = new QLabel;
    l->setTextInteractionFlags(Qt::TextSelectableByMouse);
    l->setWordWrap(true);
    return l;
}

} // namespace

AccuracyReadout::AccuracyReadout(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    m_note = new QLabel;
    m_note->setWordWrap(true);
    m_note->setTextFormat(Qt::RichText);
    m_note->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_note->setFrameShape(QFrame::StyledPanel);
    m_note->setMargin(4);
    m_note->hide();
    // the Plan tool's chosen motion: its end on the target and its certificate
    m_planTitle = new QLabel;
    m_planTitle->setObjectName(QStringLiteral("accuracyPlan"));
    m_planEndError = valueLabel();
    m_planEndError->setToolTip(
        tr("How far the planned motion's end is from the target pose: |\u0394x|/b + |\u0394y|/b "
           "+ |\u0394\u03c6 mod 2\u03c0|, from its closed form"));
    m_planOptimal = valueLabel();
    m_planOptimal->setToolTip(tr("A motion is the fastest to the target up to its cut time, the "
                                 "first time another motion of the same length meets it"));
    m_time = new QLabel;
    m_time->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_time->setObjectName(QStringLiteral("accuracyTime"));
    m_tracking = valueLabel();
    m_tracking->setToolTip(
        tr("Distance of the controlled knife point P from the prescribed path's "
           "own point at the same arc length: the tracking constraint residual"));
    m_paper = valueLabel();
    m_paper->setToolTip(tr("Distance from the paper's closed form (line and circle presets, "
                           "constant energy)"));
    m_controlledDrift = valueLabel();
    m_freeDrift = valueLabel();
    m_plainModels = valueLabel();
    m_models = valueLabel();
    QFont small = m_models->font();
    small.setPointSizeF(small.pointSizeF() * 0.9);
    m_models->setFont(small);
    m_models->hide();
    m_details = new QToolButton;
    m_details->setText(tr("Details"));
    m_details->setCheckable(true);
    m_details->setAutoRaise(true);
    m_details->setArrowType(Qt::RightArrow);
    m_details->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_details->setToolTip(tr("The models and numerical methods in technical terms"));
    connect(m_details, &QToolButton::toggled, this, [this](bool on) {
        m_details->setArrowType(on ? Qt::DownArrow : Qt::RightArrow);
        m_models->setVisible(on);
    });

    auto* form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    // the plan's rows first, in the same columns as the scene's (shown in plan mode only)
    form->addRow(m_planTitle);
    form->addRow(tr("end error"), m_planEndError);
    form->addRow(tr("optimal"), m_planOptimal);
    for (QWidget* row : {static_cast<QWidget*>(m_planTitle), static_cast<QWidget*>(m_planEndError),
                         static_cast<QWidget*>(m_planOptimal)})
        form->setRowVisible(row, false);
    m_form = form;
    form->addRow(tr("t"), m_time);
    form->addRow(tr("off the path"), m_tracking);
    form->addRow(tr("vs closed form"), m_paper);
    form->addRow(tr("energy drift"), m_controlledDrift);
    form->addRow(tr("free energy drift"), m_freeDrift);

    auto* models = new QLabel(tr("<b>Models and methods</b>"));
    auto* header = new QHBoxLayout;
    header->addWidget(models);
    header->addWidget(m_details);
    header->addStretch(1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->addWidget(m_note);
    layout->addLayout(form);
    layout->addLayout(header);
    layout->addWidget(m_plainModels);
    layout->addWidget(m_models);
    layout->addStretch(1);

    m_refresh.setSingleShot(true);
    m_refresh.setInterval(kRefreshMs);
    connect(&m_refresh, &QTimer::timeout, this, &AccuracyReadout::refresh);
    connect(m_document, &SceneDocument::solutionChanged, this, &AccuracyReadout::onSolutionChanged);
    fixTimeSize();
    if (m_document->solution())
        onSolutionChanged();
}

QString AccuracyReadout::noteText() const {
    return m_note->isHidden() ? QString() : m_note->text();
}

QString AccuracyReadout::modelsText() const {
    return m_models->text();
}

QString AccuracyReadout::plainModelsText() const {
    return m_plainModels->text();
}

QString AccuracyReadout::timeText() const {
    return m_time->text();
}

void AccuracyReadout::setTime(double t) {
    m_t = t;
    // the canvas's time, this frame: only the numbers wait for the meter's pace
    const auto& solution = m_document->solution();
    m_time->setText(formatTime(solution ? std::clamp(t, 0.0, solution->tEnd()) : t));
    if (!m_refresh.isActive())
        m_refresh.start();
}

void AccuracyReadout::fixTimeSize() {
    // room for the longest horizon's times (a 5000 s gallery scene) in the current font
    const QFontMetrics metrics(m_time->font());
    const int margins = m_time->contentsMargins().left() + m_time->contentsMargins().right();
    m_time->setFixedSize(metrics.horizontalAdvance(formatTime(88888.888)) + margins + 2,
                         metrics.height() + m_time->contentsMargins().top() +
                             m_time->contentsMargins().bottom());
}

void AccuracyReadout::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange || event->type() == QEvent::StyleChange)
        fixTimeSize();
}

void AccuracyReadout::setNote(const QString& title, const QString& text, bool warning) {
    if (text.isEmpty() && title.isEmpty()) {
        m_note->clear();
        m_note->hide();
        return;
    }
    m_note->setStyleSheet(warning ? QStringLiteral("QLabel { color: #a40000; }") : QString());
    QString body = text.toHtmlEscaped();
    body.replace(QLatin1Char('\n'), QStringLiteral("<br>"));
    m_note->setText(
        withDottedSymbolFont(QStringLiteral("<b>%1</b><br>%2").arg(title.toHtmlEscaped(), body)));
    m_note->show();
}

QString AccuracyReadout::planEndErrorText() const {
    return m_plan ? m_planEndError->text() : QString();
}

QString AccuracyReadout::planOptimalText() const {
    return m_plan ? m_planOptimal->text() : QString();
}

void AccuracyReadout::showPlan(const std::optional<PlanAccuracy>& plan) {
    m_plan = plan;
    if (m_plan)
        fillPlan();
    for (QWidget* row : {static_cast<QWidget*>(m_planTitle), static_cast<QWidget*>(m_planEndError),
                         static_cast<QWidget*>(m_planOptimal)})
        m_form->setRowVisible(row, m_plan.has_value());
}

void AccuracyReadout::fillPlan() {
    const PlanAccuracy& p = *m_plan;
    m_planTitle->setText(tr("<b>Plan: motion %1 of %2</b> (t = %3 s)")
                             .arg(p.index)
                             .arg(p.count)
                             .arg(p.t, 0, 'f', 3));
    m_planEndError->setText(relative(p.endError));
    const QString cut =
        std::isfinite(p.cutTime) ? tr("%1 s").arg(p.cutTime, 0, 'f', 3) : QStringLiteral("\u221e");
    if (p.optimal)
        m_planOptimal->setText(tr("certified: t \u2264 cut time %1").arg(cut));
    else if (p.t > p.cutTime)
        m_planOptimal->setText(tr("no: t > cut time %1, a faster motion exists").arg(cut));
    else
        m_planOptimal->setText(tr("not certified (cut time %1)").arg(cut));
}

void AccuracyReadout::onSolutionChanged() {
    const auto& solution = m_document->solution();
    if (!solution)
        return;
    m_controlledT0 = solution->at(0).control.energy;
    m_freeT0 = solution->freeAt(0).energy;
    m_plainModels->setText(plainModelSummary(*solution));
    m_models->setText(technicalModels(*solution));
    refresh();
}

void AccuracyReadout::refresh() {
    m_refresh.stop();
    const auto& solution = m_document->solution();
    if (!solution)
        return;
    AccuracyValues v;
    v.t = std::clamp(m_t, 0.0, solution->tEnd());
    MotionSample m = solution->at(v.t);
    v.trackingResidual = distanceFromPath(*solution->path(), m);
    if (auto paper = paperClosedForm(solution->scene(), v.t)) {
        v.paperError = std::hypot(m.x - paper->x, m.y - paper->y);
        v.paperEquations = QString::fromStdString(paper->equations);
    }
    if (solution->params().mode == SpeedMode::Energy && m_controlledT0 > 0)
        v.controlledDrift = std::fabs(m.control.energy - m_controlledT0) / m_controlledT0;
    if (m_freeT0 > 0)
        v.freeDrift = std::fabs(m.free.energy - m_freeT0) / m_freeT0;
    m_values = v;

    m_time->setText(formatTime(v.t));
    m_tracking->setText(metres(v.trackingResidual));
    m_paper->setText(v.paperError ? tr("%1 (paper %2)").arg(metres(*v.paperError), v.paperEquations)
                                  : tr("no closed form for this scene"));
    m_controlledDrift->setText(v.controlledDrift ? relative(*v.controlledDrift)
                                                 : tr("T varies by design in constant-speed mode"));
    m_freeDrift->setText(relative(v.freeDrift));
}

void AccuracyReadout::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    // the form keeps the row heights of the old width otherwise: a wrapped value shows one line
    if (event->oldSize().width() != event->size().width())
        layout()->invalidate();
}

} // namespace chaplygin::ui
