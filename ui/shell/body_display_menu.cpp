#include "shell/body_display_menu.h"

#include <QActionGroup>

#include <cmath>

namespace chaplygin::ui {

namespace {
constexpr double kTrailWidths[] = {1, 2, 4, 6};
constexpr double kOpacities[] = {0.3, 0.6, 0.8, 1.0};
} // namespace

BodyDisplayMenu::BodyDisplayMenu(QWidget* parent) : QMenu(tr("&Bodies"), parent) {
    m_display = new QActionGroup(this);
    const std::pair<BodyDisplay, QString> modes[] = {
        {BodyDisplay::Automatic, tr("&Automatic: to scale unless the body hides the path")},
        {BodyDisplay::ToScale, tr("To &scale")},
        {BodyDisplay::Outline, tr("&Outline only")},
        {BodyDisplay::Marker, tr("Small &marker (knife and centre of mass)")}};
    for (const auto& [mode, text] : modes) {
        QAction* a = addAction(text);
        a->setCheckable(true);
        a->setData(int(mode));
        m_display->addAction(a);
    }
    m_display->actions()[0]->setShortcut(QKeySequence(tr("Ctrl+Shift+0")));
    m_display->actions()[1]->setShortcut(QKeySequence(tr("Ctrl+Shift+1")));
    m_display->actions()[2]->setShortcut(QKeySequence(tr("Ctrl+Shift+2")));
    m_display->actions()[3]->setShortcut(QKeySequence(tr("Ctrl+Shift+3")));
    addSeparator();
    QMenu* trail = addMenu(tr("&Trail width"));
    m_trail = new QActionGroup(this);
    for (double w : kTrailWidths) {
        QAction* a = trail->addAction(tr("%1 px").arg(w));
        a->setCheckable(true);
        a->setData(w);
        m_trail->addAction(a);
    }
    QMenu* opacity = addMenu(tr("Body &opacity"));
    m_opacity = new QActionGroup(this);
    for (double o : kOpacities) {
        QAction* a = opacity->addAction(tr("%1 %").arg(std::lround(100 * o)));
        a->setCheckable(true);
        a->setData(o);
        m_opacity->addAction(a);
    }
    addSeparator();
    // the disk's and the carriage's rolling angles, turning in a corner of the canvas
    m_wheelInset = addAction(tr("Side view of the &wheels"));
    m_wheelInset->setCheckable(true);
    m_wheelInset->setShortcut(QKeySequence(tr("Ctrl+Shift+4")));
    m_wheelInset->setToolTip(tr("A side view of the disk's or the carriage's wheels in a corner "
                                "of the canvas, their spokes turning by the rolling angle"));
    connect(m_wheelInset, &QAction::triggered, this, [this](bool on) {
        m_style.wheelInset = on;
        emit styleChosen(m_style);
    });
    connect(m_display, &QActionGroup::triggered, this, [this](QAction* a) {
        m_style.body = static_cast<BodyDisplay>(a->data().toInt());
        emit styleChosen(m_style);
    });
    connect(m_trail, &QActionGroup::triggered, this, [this](QAction* a) {
        m_style.trailWidth = a->data().toDouble();
        emit styleChosen(m_style);
    });
    connect(m_opacity, &QActionGroup::triggered, this, [this](QAction* a) {
        m_style.bodyOpacity = a->data().toDouble();
        emit styleChosen(m_style);
    });
    setCanvasStyle(m_style);
}

QAction* BodyDisplayMenu::displayAction(BodyDisplay display) const {
    for (QAction* a : m_display->actions())
        if (a->data().toInt() == int(display))
            return a;
    return nullptr;
}

void BodyDisplayMenu::setCanvasStyle(const CanvasStyle& style) {
    m_style = style;
    if (QAction* a = displayAction(style.body))
        a->setChecked(true);
    // the nearest listed value is checked
    auto checkNearest = [](QActionGroup* group, double value) {
        QAction* best = nullptr;
        for (QAction* a : group->actions())
            if (!best ||
                std::abs(a->data().toDouble() - value) < std::abs(best->data().toDouble() - value))
                best = a;
        if (best)
            best->setChecked(true);
    };
    m_wheelInset->setChecked(style.wheelInset);
    checkNearest(m_trail, style.trailWidth);
    checkNearest(m_opacity, style.bodyOpacity);
}

} // namespace chaplygin::ui
