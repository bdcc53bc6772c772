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
#include <QTextBrowser>
#include <QTextDocument>
#include <QToolBar>

#include <algorithm>
#include <cmath>
#include <memory>

namespace chaplygin::ui {

namespace {
const QString kScaleKey = QStringLiteral("presentation/scale");
// a text dock's width or height beyond its text: the panel's and the view's margins and frames
constexpr int kTextChrome = 40;
// from this window width [px] the note goes under the canvas, beside the plots
constexpr int kNoteBelowWidth = 1600;
} // namespace

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
        fitDocks(); // the note's lines in the new font
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
    // the next scene's note, once it is laid out
    QMetaObject::invokeMethod(this, &PresentationMode::fitDocks, Qt::QueuedConnection);
}

void PresentationMode::fitDocks() {
    if (!m_active)
        return;
    const int width = m_window->width(), height = m_window->height();
    // a dock shown with the scene (its note) goes under the canvas, beside the plots: as a column
    // beside the canvas it took the canvas's width (180 px, the note needed scrolling, or more
    // than a quarter of a 1024 px projector). It is as wide as lines of about 66 characters, wider
    // when a long note would not fit, within a quarter of the width up to 1280 px and two fifths
    // from 1920 px; the bottom docks as tall as the note, within a third of the height
    const double share = 0.25 + 0.15 * std::clamp((width - 1280) / 640.0, 0.0, 1.0);
    const int most = int(width * share), tallest = height / 3;
    int bottom = std::max(height / 4, 240);
    QList<QDockWidget*> shown;
    if (auto* plots = qobject_cast<QDockWidget*>(m_plots->parentWidget());
        plots && plots->isVisible() && !plots->isFloating())
        shown << plots;
    // below 1600 px the plots need the bottom's width: the note stays beside the canvas
    const bool below = width >= kNoteBelowWidth;
    for (const Conditional& c : m_conditional) {
        if (c.dock->isFloating())
            continue;
        const Qt::DockWidgetArea area = m_window->dockWidgetArea(c.dock);
        if (!below) {
            if (area == Qt::BottomDockWidgetArea)
                m_window->addDockWidget(Qt::RightDockWidgetArea, c.dock);
            c.dock->setMaximumWidth(width / 4);
            c.dock->setMinimumWidth(0);
            continue;
        }
        if (area != Qt::BottomDockWidgetArea)
            m_window->addDockWidget(Qt::BottomDockWidgetArea, c.dock, Qt::Horizontal);
        int w = std::min(most, readableWidth(*c.dock));
        while (w < most && textHeight(*c.dock, w) > tallest)
            w = std::min(most, w + 20);
        // bounds, which hold whenever it is laid out (resizeDocks leaves a tabbed dock alone)
        c.dock->setMaximumWidth(most);
        c.dock->setMinimumWidth(w);
        if (c.dock->isVisible()) {
            bottom = std::max(bottom, std::min(tallest, textHeight(*c.dock, w)));
            shown << c.dock;
        }
    }
    if (!shown.isEmpty())
        m_window->resizeDocks(shown, QList<int>(shown.size(), bottom), Qt::Vertical);
}

int PresentationMode::readableWidth(const QWidget& dock) {
    // a line of prose of 66 characters in the dock's font, its margins and a scroll bar
    static const QString line =
        QStringLiteral("the knife's heading turns smoothly while the sleigh slows to a stop");
    return QFontMetrics(dock.font()).horizontalAdvance(line) * 66 / int(line.size()) + kTextChrome +
           dock.style()->pixelMetric(QStyle::PM_ScrollBarExtent);
}

int PresentationMode::textHeight(const QWidget& dock, int width) {
    const auto* view = dock.findChild<QTextBrowser*>();
    if (!view)
        return 0;
    // what the dock adds around the text: measured once it is laid out
    int aroundWidth = kTextChrome + dock.style()->pixelMetric(QStyle::PM_ScrollBarExtent);
    int aroundHeight = kTextChrome + QFontMetrics(dock.font()).height();
    if (view->isVisible() && view->viewport()->width() > 0) {
        aroundWidth = std::max(aroundWidth, dock.width() - view->viewport()->width());
        aroundHeight = std::max(aroundHeight, dock.height() - view->viewport()->height());
    }
    std::unique_ptr<QTextDocument> text(view->document()->clone());
    text->setDefaultFont(view->document()->defaultFont());
    text->setTextWidth(width - aroundWidth);
    // and half a line to spare: the view lays its text out a pixel or two apart from the clone
    return int(std::ceil(text->size().height())) + aroundHeight +
           QFontMetrics(text->defaultFont()).lineSpacing() / 2;
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
        for (const Conditional& c : m_conditional) {
            c.dock->setMaximumWidth(QWIDGETSIZE_MAX);
            c.dock->setMinimumWidth(0);
        }
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
