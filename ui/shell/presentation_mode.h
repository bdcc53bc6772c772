#pragma once
#include "canvas/canvas_style.h"

#include <QByteArray>
#include <QFont>
#include <QList>
#include <QObject>
#include <QSize>

#include <functional>

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
/// a demo does not need hidden (and empty ones, such as a Notes dock without a note), the plots
/// a quarter of the height, a large time read-out. F11 or the toolbar button toggles it, Esc
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
    /// A dock shown while presenting only when `needed` says so (the Notes dock when the scene
    /// has a note); asked again by updateDocks.
    void addDockWhile(QDockWidget* dock, std::function<bool()> needed);

    /// The user's canvas style outside presentation mode (body display, trail, opacity).
    const CanvasStyle& baseStyle() const { return m_base; }
    void setBaseStyle(const CanvasStyle& style);
    /// The style the canvas and plots get now.
    CanvasStyle currentStyle() const;

    QAction* toggleAction() const { return m_toggle; }
    QAction* leaveAction() const { return m_leave; }

    bool eventFilter(QObject* watched, QEvent* event) override;

  public slots:
    void setActive(bool on);
    void toggle() { setActive(!m_active); }
    /// While presenting: hides again the docks a demo does not need and shows a conditional
    /// dock only when needed (after a scene changed, e.g. Page Down in the gallery).
    void updateDocks();

  signals:
    void activeChanged(bool active);

  private:
    void applyStyle();
    /// The plots a quarter of the height (at least 240 px) and, from 1600 px wide, a dock shown
    /// with the scene (the note) beside them, as wide as lines of about 66 characters (at most
    /// two fifths of the width at 1920 px) and the bottom as tall as the note (at most a third
    /// of the height); narrower, the note beside the canvas at most a quarter of the width, so
    /// that the canvas keeps most of the screen and the plots their width.
    void fitDocks();
    /// The width of a dock that shows prose in lines of about 66 characters [px].
    static int readableWidth(const QWidget& dock);
    /// The height a dock's text browser needs at this dock width, its title bar included [px].
    static int textHeight(const QWidget& dock, int width);
    struct Conditional {
        QDockWidget* dock;
        std::function<bool()> needed;
    };
    QList<Conditional> m_conditional;

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
