#include "shell/dock_layout.h"

#include <QAction>
#include <QCoreApplication>
#include <QDockWidget>
#include <QMainWindow>
#include <QResizeEvent>
#include <QScrollArea>
#include <QTabBar>

#include <algorithm>

namespace chaplygin::ui {

// the translation context of the dock titles
class DockLayout {
    Q_DECLARE_TR_FUNCTIONS(chaplygin::ui::DockLayout)
};

namespace {

// narrower windows tab the right-hand docks on the left
constexpr int kNarrow = 1200;
// the dynamic property of a dock balanceDocks moved to the left
constexpr const char* kMovedLeft = "movedLeftWhenNarrow";

QDockWidget* makeDock(const QString& title, const QString& name, QWidget* content,
                      QMainWindow* parent) {
    auto* dock = new QDockWidget(title, parent);
    dock->setObjectName(name);
    dock->setWidget(content);
    return dock;
}

// a panel taller than the dock scrolls vertically, never sideways
QDockWidget* makeScrollingDock(const QString& title, const QString& name, QWidget* content,
                               QMainWindow* parent) {
    auto* scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(content);
    return makeDock(title, name, scroll, parent);
}

// a tab bar of docks tabbed together shows whole titles and scrolls when they do not fit: six
// tabs on the left of a 1024 px window would otherwise read "P…", "N…", "E…"
void keepTitlesWhole(QTabBar* bar) {
    bar->setElideMode(Qt::ElideNone);
    bar->setUsesScrollButtons(true);
}

} // namespace

Docks placeDocks(QMainWindow* window, const DockPanels& panels) {
    Docks d;
    d.path =
        makeScrollingDock(DockLayout::tr("Path"), QStringLiteral("pathDock"), panels.path, window);
    d.parameters = makeScrollingDock(DockLayout::tr("System and parameters"),
                                     QStringLiteral("parametersDock"), panels.parameters, window);
    d.plots = makeDock(DockLayout::tr("Plots"), QStringLiteral("plotsDock"), panels.plots, window);
    d.methods =
        makeDock(DockLayout::tr("Methods"), QStringLiteral("methodsDock"), panels.methods, window);
    d.sweep = makeDock(DockLayout::tr("Sweep"), QStringLiteral("sweepDock"), panels.sweep, window);
    d.accuracy = makeScrollingDock(DockLayout::tr("Accuracy"), QStringLiteral("accuracyDock"),
                                   panels.accuracy, window);
    window->addDockWidget(Qt::LeftDockWidgetArea, d.path);
    window->addDockWidget(Qt::LeftDockWidgetArea, d.parameters);
    window->tabifyDockWidget(d.path, d.parameters);
    d.path->raise();
    window->addDockWidget(Qt::BottomDockWidgetArea, d.plots);
    window->addDockWidget(Qt::BottomDockWidgetArea, d.methods);
    window->tabifyDockWidget(d.plots, d.methods);
    window->addDockWidget(Qt::BottomDockWidgetArea, d.sweep);
    window->tabifyDockWidget(d.methods, d.sweep);
    d.plots->raise();
    window->addDockWidget(Qt::RightDockWidgetArea, d.accuracy);
    d.accuracy->setMinimumWidth(240);
    d.path->setMinimumWidth(360);
    d.parameters->setMinimumWidth(360);
    return d;
}

void balanceDocks(QMainWindow* window, const Docks& docks) {
    for (QTabBar* bar : window->findChildren<QTabBar*>(Qt::FindDirectChildrenOnly))
        keepTitlesWhole(bar);
    const int width = window->width(), height = window->height();
    if (width < kNarrow) {
        QDockWidget* last = docks.parameters;
        for (QDockWidget* dock : window->findChildren<QDockWidget*>()) {
            if (window->dockWidgetArea(dock) != Qt::RightDockWidgetArea || dock->isFloating())
                continue;
            window->addDockWidget(Qt::LeftDockWidgetArea, dock);
            window->tabifyDockWidget(last, dock);
            dock->setProperty(kMovedLeft, true);
            last = dock;
        }
        if (last != docks.parameters)
            docks.path->raise();
    }
    window->resizeDocks({docks.plots}, {balancedPlotsHeight(height)}, Qt::Vertical);
    window->resizeDocks({docks.path}, {std::max(360, width / 4)}, Qt::Horizontal);
}

void returnRightDocks(QMainWindow* window, const Docks& docks) {
    const QList<QDockWidget*> all = window->findChildren<QDockWidget*>();
    QList<QDockWidget*> moving;
    for (QDockWidget* dock : all) {
        if (!dock->property(kMovedLeft).toBool())
            continue;
        dock->setProperty(kMovedLeft, false);
        if (window->dockWidgetArea(dock) == Qt::LeftDockWidgetArea && !dock->isFloating())
            moving << dock;
    }
    if (moving.isEmpty())
        return;
    // the left tab in front stays in front, unless it is one of those leaving
    QDockWidget* front = docks.path;
    for (QDockWidget* dock : all)
        if (window->dockWidgetArea(dock) == Qt::LeftDockWidgetArea && !dock->isFloating() &&
            dock->isVisible() && !dock->visibleRegion().isEmpty() && !moving.contains(dock))
            front = dock;
    for (QDockWidget* dock : moving) {
        window->addDockWidget(Qt::RightDockWidgetArea, dock);
        if (dock != moving.first())
            window->tabifyDockWidget(moving.first(), dock);
    }
    moving.first()->raise();
    front->raise();
}

int balancedPlotsHeight(int windowHeight) {
    return windowHeight < 900 ? std::max(200, windowHeight / 4) : windowHeight / 3;
}

int methodsDockHeight(int windowHeight) {
    return std::max(360, windowHeight * 9 / 20);
}

int sweepDockHeight(int windowHeight) {
    return std::max(300, windowHeight * 2 / 5);
}

DockBalancer::DockBalancer(QMainWindow* window, const Docks& docks, bool balanceWhenShown,
                           const QByteArray& defaultLayout)
    : QObject(window), m_window(window), m_docks(docks), m_balanceWhenShown(balanceWhenShown),
      m_defaultLayout(defaultLayout) {
    window->installEventFilter(this);
    connect(docks.plots, &QDockWidget::visibilityChanged, this, &DockBalancer::plotsShown);
    growWhenShown(docks.methods, methodsDockHeight);
    growWhenShown(docks.sweep, sweepDockHeight);
}

// a bottom tab brought to the front (its tab clicked, its menu entry) gets its height
void DockBalancer::growWhenShown(QDockWidget* dock, int (*height)(int windowHeight)) {
    connect(dock, &QDockWidget::visibilityChanged, this, [this, dock, height](bool visible) {
        if (!visible || !m_window->isVisible() || dock->isFloating() ||
            m_window->dockWidgetArea(dock) != Qt::BottomDockWidgetArea)
            return;
        // after the tab switch has laid out the dock
        QMetaObject::invokeMethod(
            this,
            [this, dock, height] {
                const int target = height(m_window->height());
                if (dock->isVisible() && dock->height() < target - 4)
                    m_window->resizeDocks({dock}, {target}, Qt::Vertical);
            },
            Qt::QueuedConnection);
    });
}

void DockBalancer::plotsShown(bool visible) {
    const bool open = m_docks.plots->toggleViewAction()->isChecked();
    if (!visible) {
        // another tab (Methods, Sweep) came to the front, or the dock was closed
        m_behind = open;
        m_plotsHeight = open && m_window->isVisible() ? m_docks.plots->height() : 0;
        return;
    }
    if (!m_behind)
        return;
    m_behind = false;
    const int target = m_plotsHeight > 0 ? m_plotsHeight : balancedPlotsHeight(m_window->height());
    m_plotsHeight = 0;
    if (m_docks.plots->isFloating() ||
        m_window->dockWidgetArea(m_docks.plots) != Qt::BottomDockWidgetArea)
        return;
    // after the tab switch has laid out the dock
    QMetaObject::invokeMethod(
        this,
        [this, target] {
            if (m_docks.plots->isVisible() && m_docks.plots->height() > target + 8)
                m_window->resizeDocks({m_docks.plots}, {target}, Qt::Vertical);
        },
        Qt::QueuedConnection);
}

void DockBalancer::resetLayout() {
    for (QDockWidget* dock : m_window->findChildren<QDockWidget*>())
        dock->setFloating(false);
    m_window->restoreState(m_defaultLayout);
    m_plotsHeight = 0;
    m_behind = false;
    balanceLater();
}

bool DockBalancer::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_window && event->type() == QEvent::Show) {
        // a restored layout may start with another tab in front of the plots: the plots come
        // forward on the first show (the Sweep and Methods docks start empty)
        QMetaObject::invokeMethod(
            this,
            [this, first = !m_shown] {
                if (first && m_docks.plots->toggleViewAction()->isChecked())
                    m_docks.plots->raise();
                m_behind = m_behind || (m_docks.plots->toggleViewAction()->isChecked() &&
                                        !m_docks.plots->isVisible());
            },
            Qt::QueuedConnection);
        m_shown = true;
        if (m_balanceWhenShown) {
            m_balanceWhenShown = false;
            balanceLater();
        }
    } else if (watched == m_window && event->type() == QEvent::ChildPolished) {
        // the window makes a tab bar for docks when they are first tabbed together
        if (auto* bar = qobject_cast<QTabBar*>(static_cast<QChildEvent*>(event)->child()))
            keepTitlesWhole(bar);
    } else if (watched == m_window && event->type() == QEvent::Resize) {
        auto* resize = static_cast<QResizeEvent*>(event);
        if (resize->oldSize().width() >= kNarrow && resize->size().width() < kNarrow)
            balanceLater();
        else if (resize->oldSize().width() < kNarrow && resize->size().width() >= kNarrow)
            QMetaObject::invokeMethod(
                this, [this] { returnRightDocks(m_window, m_docks); }, Qt::QueuedConnection);
    }
    return false;
}

// after the event, once the window's layout has its new geometry
void DockBalancer::balanceLater() {
    QMetaObject::invokeMethod(
        this, [this] { balanceDocks(m_window, m_docks); }, Qt::QueuedConnection);
}

void bringDockForward(QMainWindow* window, QDockWidget* dock, int minimumHeight) {
    dock->show();
    dock->raise();
    if (minimumHeight > 0)
        window->resizeDocks({dock}, {minimumHeight}, Qt::Vertical);
}

} // namespace chaplygin::ui
