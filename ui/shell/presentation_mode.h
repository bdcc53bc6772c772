#pragma once
#include "canvas/canvas_style.h"

#include <QByteArray>
#include <QFont>
#include <QList>
#include <QObject>
#include <QSize>

class QAction;
class QDockWidget;
class QMainWindow;
class QMenu;
class QWidget;
class QToolBar;

namespace chaplygin::ui {

class PlotsPanel;
class SceneCanvas;

/// Presentation mode for a lecture room: full screen, fonts and line widths scaled (a setting,
/// 1.6 by default), a high-contrast palette that stays distinguishable in greyscale, the docks
/// a demo does not need hidden, a large time read-out. F11 or the toolbar button toggles it, Esc
/// leaves it; leaving restores the window as it was.
class PresentationMode : public QObject {
    Q_OBJECT
  public:
    static constexpr double kDefaultScale = 1.6;

    /// hidden: the docks hidden while presenting (shown again on leaving if they were shown).
    PresentationMode(QMainWindow* window, SceneCanvas* canvas, PlotsPanel* plots,
                     QList<QDockWidget*> hidden, QList<QToolBar*> toolBars);

    bool isActive() const { return m_active; }
    /// The scale of fonts and line widths while presenting (QSettings "presentation/scale").
    double scale() const { return m_scale; }
    void setScale(double factor);
    /// A "Presentation scale" menu whose checked entry follows scale().
    QMenu* makeScaleMenu(QWidget* parent);
    /// Whether entering goes full screen (off for screenshots, which have a fixed size).
    void setFullScreen(bool on) { m_fullScreen = on; }
    /// One more dock that a demo does not need (hidden while presenting).
    void addHiddenDock(QDockWidget* dock) { m_hidden << dock; }

    /// The user's canvas style outside presentation mode (body display, trail, opacity).
    const CanvasStyle& baseStyle() const { return m_base; }
    void setBaseStyle(const CanvasStyle& style);
    /// The style the canvas and plots get now.
    CanvasStyle currentStyle() const;

    QAction* toggleAction() const { return m_toggle; }
    QAction* leaveAction() const { return m_leave; }

  public slots:
    void setActive(bool on);
    void toggle() { setActive(!m_active); }

  signals:
    void activeChanged(bool active);

  private:
    void applyStyle();

    QMainWindow* m_window;
    SceneCanvas* m_canvas;
    PlotsPanel* m_plots;
    QList<QDockWidget*> m_hidden;
    QList<QToolBar*> m_toolBars;
    QAction* m_toggle;
    QAction* m_leave;
    CanvasStyle m_base;
    double m_scale = kDefaultScale;
    bool m_active = false;
    bool m_fullScreen = true;
    // restored on leaving
    QByteArray m_savedState;
    Qt::WindowStates m_savedWindowState;
    QFont m_savedFont;
    QList<QDockWidget*> m_wasVisible;
    bool m_statusWasVisible = true;
    QSize m_savedIconSize;
};

} // namespace chaplygin::ui
