#include "shell/presentation_mode.h"

#include "canvas/scene_canvas.h"
#include "plots/plots_panel.h"

#include <QAction>
#include <QDockWidget>
#include <QEvent>
#include <QMainWindow>
#include <QMenu>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>

#include <algorithm>
#include <cmath>

namespace chaplygin::ui {

namespace {
const QString kScaleKey = QStringLiteral("presentation/scale");
}

PresentationMode::PresentationMode(QMainWindow* window, SceneCanvas* canvas, PlotsPanel* plots,
                                   QList<QDockWidget*> hidden, QList<QToolBar*> toolBars)
    : QObject(window), m_window(window), m_canvas(canvas), m_plots(plots),
      m_hidden(std::move(hidden)), m_toolBars(std::move(toolBars)) {
    m_toggle = new QAction(window->style()->standardIcon(QStyle::SP_TitleBarMaxButton),
                           tr("&Presentation mode"), window);
    m_toggle->setObjectName(QStringLiteral("presentationAction"));
    m_toggle->setCheckable(true);
    m_toggle->setShortcut(Qt::Key_F11);
    m_toggle->setToolTip(tr("Presentation mode: full screen, large fonts and lines, high "
                            "contrast (F11; Esc leaves)"));
    m_leave = new QAction(tr("Leave presentation mode"), window);
    m_leave->setShortcut(Qt::Key_Escape);
    m_leave->setEnabled(false);
    window->addAction(m_leave);
    connect(m_toggle, &QAction::toggled, this, &PresentationMode::setActive);
    connect(m_leave, &QAction::triggered, this, [this] { setActive(false); });
    m_scale = std::clamp(QSettings().value(kScaleKey, kDefaultScale).toDouble(), 1.0, 3.0);
    if (!std::isfinite(m_scale))
        m_scale = kDefaultScale;
}

void PresentationMode::setScale(double factor) {
    if (!std::isfinite(factor))
        return;
    m_scale = std::clamp(factor, 1.0, 3.0);
    QSettings().setValue(kScaleKey, m_scale);
    if (m_active) {
        QFont f = m_savedFont;
        f.setPointSizeF(m_savedFont.pointSizeF() * m_scale);
        m_window->setFont(f);
        applyStyle();
    }
}

QMenu* PresentationMode::makeScaleMenu(QWidget* parent) {
    auto* menu = new QMenu(tr("Presentation &scale"), parent);
    for (double f : {1.4, 1.6, 2.0, 2.5}) {
        QAction* a =
            menu->addAction(QStringLiteral("\u00d7%1").arg(f), this, [this, f] { setScale(f); });
        a->setCheckable(true);
        a->setChecked(std::abs(m_scale - f) < 1e-9);
        connect(menu, &QMenu::aboutToShow, a,
                [this, a, f] { a->setChecked(std::abs(m_scale - f) < 1e-9); });
    }
    return menu;
}

void PresentationMode::setBaseStyle(const CanvasStyle& style) {
    m_base = style.sanitized();
    applyStyle();
}

CanvasStyle PresentationMode::currentStyle() const {
    return m_active ? m_base.presentation(m_scale) : m_base;
}

void PresentationMode::applyStyle() {
    m_canvas->setCanvasStyle(currentStyle());
    m_plots->setLook(currentStyle());
}

void PresentationMode::addDockWhile(QDockWidget* dock, std::function<bool()> needed) {
    m_conditional << Conditional{dock, std::move(needed)};
}

void PresentationMode::updateDocks() {
    if (!m_active)
        return;
    for (QDockWidget* dock : m_hidden)
        dock->hide();
    for (const Conditional& c : m_conditional)
        c.dock->setVisible(c.needed());
}

void PresentationMode::fitDocks() {
    if (!m_active)
        return;
    if (auto* plots = qobject_cast<QDockWidget*>(m_plots->parentWidget());
        plots && plots->isVisible())
        m_window->resizeDocks({plots}, {std::max(m_window->height() / 4, 240)}, Qt::Vertical);
    // a dock kept beside the canvas (the scene's note) takes at most a quarter of the width:
    // on a 1024 px projector it took over a third (a bound, which holds whenever it is laid out)
    for (const Conditional& c : m_conditional) {
        const Qt::DockWidgetArea area = m_window->dockWidgetArea(c.dock);
        if (area == Qt::LeftDockWidgetArea || area == Qt::RightDockWidgetArea)
            c.dock->setMaximumWidth(m_window->width() / 4);
    }
}

bool PresentationMode::eventFilter(QObject* watched, QEvent* event) {
    // going full screen resizes the window later: the plots are shrunk again then
    if (watched == m_window && event->type() == QEvent::Resize && m_active)
        QMetaObject::invokeMethod(this, &PresentationMode::fitDocks, Qt::QueuedConnection);
    return false;
}

void PresentationMode::setActive(bool on) {
    if (on == m_active)
        return;
    m_active = on;
    if (on) {
        m_savedState = m_window->saveState();
        m_savedWindowState = m_window->windowState();
        m_savedFont = m_window->font();
        m_wasVisible.clear();
        for (QDockWidget* dock : m_hidden)
            if (dock->isVisible())
                m_wasVisible << dock;
        for (const Conditional& c : m_conditional)
            if (c.dock->isVisible())
                m_wasVisible << c.dock;
        m_statusWasVisible = m_window->statusBar()->isVisible();
        m_window->statusBar()->hide();
        QFont f = m_savedFont;
        f.setPointSizeF(m_savedFont.pointSizeF() * m_scale);
        m_window->setFont(f);
        if (!m_toolBars.isEmpty()) {
            m_savedIconSize = m_toolBars.first()->iconSize();
            for (QToolBar* bar : m_toolBars)
                bar->setIconSize(m_savedIconSize * m_scale);
        }
        if (m_fullScreen)
            m_window->setWindowState(m_window->windowState() | Qt::WindowFullScreen);
        updateDocks();
        fitDocks();
        m_window->installEventFilter(this);
    } else {
        m_window->removeEventFilter(this);
        m_window->setFont(m_savedFont);
        for (QToolBar* bar : m_toolBars)
            bar->setIconSize(m_savedIconSize);
        m_window->setWindowState(m_savedWindowState);
        for (const Conditional& c : m_conditional)
            c.dock->setMaximumWidth(QWIDGETSIZE_MAX);
        m_window->restoreState(m_savedState);
        for (QDockWidget* dock : m_wasVisible)
            dock->show();
        m_window->statusBar()->setVisible(m_statusWasVisible);
    }
    m_leave->setEnabled(on);
    m_toggle->setChecked(on);
    applyStyle();
    // a followed body stays followed; otherwise the same kind of fit for the new size
    if (!m_canvas->followsBody())
        m_canvas->fitsEverything() ? m_canvas->fitEverything() : m_canvas->fitScene();
    emit activeChanged(on);
}

} // namespace chaplygin::ui
