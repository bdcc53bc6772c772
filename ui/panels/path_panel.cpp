#include "panels/path_panel.h"

#include "document/scene_texts.h"
#include "scene/presets.h"
#include "widgets/number_field.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

namespace chaplygin::ui {

namespace {
// strokes are sampled every 10 px: 3 spacings irons out a shaky hand and keeps the shape
constexpr double kDrawnSmoothing = 3.0;
// a parametric curve's first range: one turn of the tooltip's 2 cos u, 2 sin u
constexpr double kTurn = 6.283185307179586;
} // namespace

PathPanel::PathPanel(QWidget* parent)
    : QWidget(parent), m_newCorners(CornerMode::Smooth), m_newSmoothing(kDrawnSmoothing),
      m_newCornerAngle(kDefaultCornerAngleDeg), m_graphRange(PathSource().from, PathSource().to),
      m_uRange(0.0, kTurn) {
    auto* layout = new QVBoxLayout(this);

    auto* presetBox = new QGroupBox(tr("Preset (the paper's examples)"));
    auto* pv = new QVBoxLayout(presetBox);
    m_preset = new QComboBox;
    m_preset->addItem(tr("(choose a preset)"));
    for (const std::string& name : presetNames())
        m_preset->addItem(sceneText(name), QString::fromStdString(name));
    m_preset->setToolTip(tr("Load one of the paper's four examples with the paper's parameters"));
    m_presetInfo = new QLabel;
    m_presetInfo->setWordWrap(true);
    pv->addWidget(m_preset);
    pv->addWidget(m_presetInfo);
    layout->addWidget(presetBox);

    auto* typed = new QGroupBox(tr("Typed path"));
    auto* form = new QFormLayout(typed);
    m_graph = new QRadioButton(tr("graph y(x)"));
    m_parametric = new QRadioButton(tr("parametric x(u), y(u)"));
    auto* group = new QButtonGroup(this);
    group->addButton(m_graph);
    group->addButton(m_parametric);
    auto* kinds = new QHBoxLayout;
    kinds->addWidget(m_graph);
    kinds->addWidget(m_parametric);
    kinds->addStretch(1); // each button as wide as its text, the room left after them
    form->addRow(kinds);
    m_y = new QLineEdit;
    m_y->setObjectName(QStringLiteral("graphEdit"));
    m_y->setToolTip(
        tr("y as a function of x [m], e.g. -sin(x) or 0.5*x + 1; press Enter to apply"));
    form->addRow(tr("y(x) ="), m_y);
    m_xu = new QLineEdit;
    m_xu->setToolTip(tr("x as a function of u [m], e.g. 2*cos(u)"));
    form->addRow(tr("x(u) ="), m_xu);
    m_yu = new QLineEdit;
    m_yu->setToolTip(tr("y as a function of u [m], e.g. 2*sin(u)"));
    form->addRow(tr("y(u) ="), m_yu);
    auto* range = new QHBoxLayout;
    m_from = new NumberField(tr("x from"));
    m_to = new NumberField(tr("x to"));
    for (NumberField* s : {m_from, m_to}) {
        s->setToolTip(tr("The range of x [m] (graph) or of u (parametric), traversed from the "
                         "first to the second; a number or an expression such as 2*pi; Enter "
                         "applies the path"));
        connect(s, &NumberField::messageChanged, this, &PathPanel::showError);
        range->addWidget(s);
    }
    m_rangeLabel = new QLabel(tr("x from, to"));
    form->addRow(m_rangeLabel, range);
    m_apply = new QPushButton(tr("&Apply path"));
    m_apply->setToolTip(tr("Tabulate the typed path (Enter in a field does the same)"));
    form->addRow(m_apply);
    m_error = new QLabel;
    m_error->setObjectName(QStringLiteral("pathError"));
    m_error->setWordWrap(true);
    m_error->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_error->setStyleSheet(QStringLiteral("color: #b00020;"));
    m_error->hide();
    form->addRow(m_error);
    layout->addWidget(typed);

    auto* drawn = new QGroupBox(tr("Drawn path"));
    auto* dv = new QFormLayout(drawn);
    m_draw = new QPushButton(tr("&Draw on the canvas"));
    m_draw->setCheckable(true);
    m_draw->setToolTip(
        tr("Press and drag on the canvas to draw a new path; it is sampled and smoothed"));
    m_corners = new QComboBox;
    // short names, so that a 1024 px window shows them whole; the whole story in the tooltips
    m_corners->addItem(tr("smooth (spline)"), int(CornerMode::Smooth));
    m_corners->setItemData(0, tr("smooth (spline through the points)"), Qt::ToolTipRole);
    m_corners->addItem(tr("pivot (turn in place)"), int(CornerMode::Pivot));
    m_corners->setItemData(
        1,
        tr("pivot (turn in place where the stroke turns by more than the corner angle, smooth "
           "between)"),
        Qt::ToolTipRole);
    m_corners->setToolTip(tr("How a drawn path's corners are followed"));
    auto* drawRow = new QHBoxLayout; // one row: the dock fits a 1280 x 800 screen unscrolled
    drawRow->addWidget(m_draw);
    drawRow->addWidget(m_corners, 1);
    dv->addRow(drawRow);
    m_smoothing = new NumberField(tr("Smoothing"));
    m_smoothing->setObjectName(QStringLiteral("drawSmoothing"));
    m_smoothing->setMinimum(0);
    m_smoothing->setZeroStep(1);
    m_smoothing->setValue(kDrawnSmoothing);
    m_smoothing->setToolTip(
        tr("Smooth corners: spline bandwidth in point spacings (0 passes through every point)"));
    m_cornerAngle = new NumberField(tr("Corner angle"));
    m_cornerAngle->setObjectName(QStringLiteral("drawCornerAngle"));
    m_cornerAngle->setMinimum(0);
    m_cornerAngle->setMaximum(180);
    m_cornerAngle->setZeroStep(1);
    m_cornerAngle->setUnit(QStringLiteral("\u00b0"));
    m_cornerAngle->setValue(kDefaultCornerAngleDeg);
    m_cornerAngle->setToolTip(
        tr("Pivot corners: the stroke pivots where it turns by more than this angle between its "
           "neighbouring points; smaller turns are smoothed (docs/user-guide.md, Drawing a path)"));
    // one row for both: the dock fits a 1280 x 800 screen unscrolled
    auto* shapeRow = new QHBoxLayout;
    for (NumberField* field : {m_smoothing, m_cornerAngle}) {
        auto* label = new QLabel(field->name());
        label->setBuddy(field);
        label->setToolTip(field->toolTip());
        shapeRow->addWidget(label);
        shapeRow->addWidget(field, 1);
    }
    dv->addRow(shapeRow);
    for (NumberField* field : {m_smoothing, m_cornerAngle})
        connect(field, &NumberField::messageChanged, this, &PathPanel::showError);
    m_polylineInfo = new QLabel;
    dv->addRow(m_polylineInfo);
    dv->setRowVisible(m_polylineInfo, false); // no empty line under a path that is not drawn
    m_drawnForm = dv;
    layout->addWidget(drawn);
    layout->addStretch(1);
    for (QComboBox* combo : findChildren<QComboBox*>()) {
        combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        combo->setMinimumContentsLength(10);
    }

    connect(m_preset, &QComboBox::activated, this, [this](int index) {
        if (index > 0)
            emit presetChosen(m_preset->itemData(index).toString());
    });
    connect(m_graph, &QRadioButton::toggled, this, &PathPanel::updateKind);
    for (QLineEdit* e : {m_y, m_xu, m_yu})
        connect(e, &QLineEdit::returnPressed, this, &PathPanel::applyTyped);
    connect(m_apply, &QPushButton::clicked, this, &PathPanel::applyTyped);
    connect(m_draw, &QPushButton::toggled, this, [this](bool on) {
        m_drawing = on;
        m_strokeDrawn = false;
        showDrawSettings();
        emit drawModeToggled(on);
    });
    // the user's choice is the next drawing's, and also changes the drawn path on show (in draw
    // mode, the stroke just drawn) at once, as one undo step
    auto optionsChanged = [this] {
        if (m_showing)
            return;
        m_newCorners = static_cast<CornerMode>(m_corners->currentData().toInt());
        m_newSmoothing = m_smoothing->value();
        m_newCornerAngle = m_cornerAngle->value();
        m_cornerAngle->setEnabled(m_newCorners == CornerMode::Pivot);
        const PathSource& p = m_scene.path;
        if ((!m_drawing || m_strokeDrawn) && p.kind == PathKind::Polyline &&
            (m_newCorners != p.corners || m_newSmoothing != p.smoothing ||
             m_newCornerAngle != p.cornerAngle))
            emit drawOptionsChanged(m_newCorners, m_newSmoothing, m_newCornerAngle);
    };
    connect(m_corners, &QComboBox::currentIndexChanged, this, optionsChanged);
    connect(m_smoothing, &NumberField::valueChanged, this, optionsChanged);
    connect(m_cornerAngle, &NumberField::valueChanged, this, optionsChanged);
    m_graph->setChecked(true);
    m_from->setValue(m_graphRange.first);
    m_to->setValue(m_graphRange.second);
    updateKind();
}

void PathPanel::showDrawSettings() {
    const PathSource& p = m_scene.path;
    const bool shown = (!m_drawing || m_strokeDrawn) && p.kind == PathKind::Polyline;
    m_showing = true;
    m_corners->setCurrentIndex(m_corners->findData(int(shown ? p.corners : m_newCorners)));
    m_smoothing->setValue(shown ? p.smoothing : m_newSmoothing);
    m_cornerAngle->setValue(shown ? p.cornerAngle : m_newCornerAngle);
    m_cornerAngle->setEnabled(m_corners->currentData().toInt() == int(CornerMode::Pivot));
    m_showing = false;
}

void PathPanel::keyPressEvent(QKeyEvent* e) {
    // a spin box passes Enter on to its parent: in the range fields it applies the typed path
    bool enter = e->key() == Qt::Key_Return || e->key() == Qt::Key_Enter;
    QWidget* focus = focusWidget();
    if (enter && (focus == m_from || focus == m_to)) {
        applyTyped();
        e->accept();
        return;
    }
    QWidget::keyPressEvent(e);
}

void PathPanel::updateKind() {
    bool graph = m_graph->isChecked();
    if (graph != m_rangeIsGraph) { // each kind's range comes back with it
        rangeOf(m_rangeIsGraph) = {m_from->value(), m_to->value()};
        m_rangeIsGraph = graph;
        m_from->setValue(rangeOf(graph).first);
        m_to->setValue(rangeOf(graph).second);
    }
    m_y->setEnabled(graph);
    m_xu->setEnabled(!graph);
    m_yu->setEnabled(!graph);
    m_rangeLabel->setText(graph ? tr("x from, to") : tr("u from, to"));
    m_from->setName(graph ? tr("x from") : tr("u from"));
    m_to->setName(graph ? tr("x to") : tr("u to"));
}

void PathPanel::setScene(const Scene& scene) {
    if (m_drawing && scene.path.kind == PathKind::Polyline &&
        scene.path.points != m_scene.path.points)
        m_strokeDrawn = true;
    m_scene = scene;
    const PathSource& p = scene.path;
    int preset = m_preset->findData(QString::fromStdString(scene.preset));
    m_preset->setCurrentIndex(preset > 0 ? preset : 0);
    m_presetInfo->setText(sceneText(presetDescription(scene.preset)));
    m_presetInfo->setVisible(!m_presetInfo->text().isEmpty()); // no empty line under the box
    showDrawSettings();
    if (p.kind != PathKind::Polyline) {
        const bool graph = p.kind == PathKind::Graph;
        rangeOf(graph) = {p.from, p.to};
        (graph ? m_graph : m_parametric)->setChecked(true);
        m_y->setText(QString::fromStdString(p.y));
        m_xu->setText(QString::fromStdString(p.xOfU));
        m_yu->setText(QString::fromStdString(p.yOfU));
        m_from->setValue(p.from);
        m_to->setValue(p.to);
        m_polylineInfo->clear();
    } else {
        m_polylineInfo->setText(
            tr("Current path: %1 drawn points, %2 corners")
                .arg(p.points.size())
                .arg(p.corners == CornerMode::Pivot ? tr("pivot") : tr("smooth")));
    }
    m_drawnForm->setRowVisible(m_polylineInfo, p.kind == PathKind::Polyline);
    updateKind();
}

void PathPanel::showError(const QString& message) {
    m_error->setText(message);
    m_error->setVisible(!message.isEmpty());
}

QString PathPanel::errorText() const {
    return m_error->isVisible() ? m_error->text() : QString();
}

void PathPanel::applyTyped() {
    PathSource source;
    source.kind = m_graph->isChecked() ? PathKind::Graph : PathKind::Parametric;
    if (source.kind == PathKind::Graph) {
        source.y = m_y->text().trimmed().toStdString();
    } else {
        source.xOfU = m_xu->text().trimmed().toStdString();
        source.yOfU = m_yu->text().trimmed().toStdString();
    }
    source.from = m_from->value();
    source.to = m_to->value();
    emit pathTyped(source);
}

} // namespace chaplygin::ui
