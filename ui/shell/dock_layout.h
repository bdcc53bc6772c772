#pragma once
#include <QByteArray>
#include <QObject>

class QDockWidget;
class QMainWindow;
class QWidget;

namespace chaplygin::ui {

/// The panels the main window shows in docks.
struct DockPanels {
    QWidget* path;
    QWidget* parameters;
    QWidget* plots;
    QWidget* methods;
    QWidget* sweep;
    QWidget* accuracy;
};

/// The main window's docks; their object names are pathDock, parametersDock, plotsDock,
/// methodsDock, sweepDock and accuracyDock (the window's saved state refers to them).
struct Docks {
    QDockWidget* path = nullptr;
    QDockWidget* parameters = nullptr;
    QDockWidget* plots = nullptr;
    QDockWidget* methods = nullptr;
    QDockWidget* sweep = nullptr;
    QDockWidget* accuracy = nullptr;
};

/// Path and parameters tabbed on the left and the accuracy on the right, each scrolling its
/// panel; plots, methods and sweep tabbed at the bottom; the path and plots tabs in front.
Docks placeDocks(QMainWindow* window, const DockPanels& panels);

/// Gives the canvas most of the window: the plots a third of the height (a quarter, at least
/// 200 px, below 900 px), the left docks a quarter of the width (at least 360 px). Below 1200 px
/// the right-hand docks (accuracy, notes, equations) join the left tabs after the parameters, so
/// the canvas keeps its width (docs/user-guide.md, The window); returnRightDocks takes them back.
/// The tabs of tabbed docks keep their whole titles and scroll when they do not fit.
void balanceDocks(QMainWindow* window, const Docks& docks);

/// The docks balanceDocks moved to the left, back on the right where they are still on the left
/// (not floating, not moved elsewhere since), tabbed in their order with the first in front; the
/// left keeps the tab it showed (the path's when that one left).
void returnRightDocks(QMainWindow* window, const Docks& docks);

/// Keeps a window's docks balanced (balanceDocks): once when the window is first shown, when
/// asked to (before that the docks have no geometry to resize), and whenever the window is
/// narrowed below 1200 px while it runs; widened again past 1200 px, the right-hand docks go back
/// (returnRightDocks). The Methods and Sweep tabs enlarge the bottom docks (methodsDockHeight,
/// sweepDockHeight); every dock tab bar the window makes shows whole titles;
/// going back to the Plots tab gives the plots the height they had (or a balanced one after a start
/// that restored an enlarged layout). The first show brings the plots in front of a restored
/// layout's Sweep or Methods tab, which start empty.
class DockBalancer : public QObject {
    Q_OBJECT
  public:
    /// defaultLayout: the window's saveState() as placeDocks left it (View > Reset layout).
    DockBalancer(QMainWindow* window, const Docks& docks, bool balanceWhenShown,
                 const QByteArray& defaultLayout);
    bool eventFilter(QObject* watched, QEvent* event) override;

  public slots:
    /// View > Reset layout: the docks where a first start puts them, balanced.
    void resetLayout();

  private:
    void balanceLater();
    void plotsShown(bool visible);
    void growWhenShown(QDockWidget* dock, int (*height)(int windowHeight));

    QMainWindow* m_window;
    Docks m_docks;
    bool m_balanceWhenShown;
    QByteArray m_defaultLayout;
    bool m_shown = false;  // the window has been shown once
    bool m_behind = false; // the plots are open behind another bottom tab
    int m_plotsHeight = 0; // their height when another bottom tab came to the front
};

/// The plots' height balanceDocks gives a window of this height [px].
int balancedPlotsHeight(int windowHeight);
/// The Methods dock's height in front (its diagram's legends need about half the window) [px].
int methodsDockHeight(int windowHeight);
/// The Sweep dock's height in front [px].
int sweepDockHeight(int windowHeight);

/// Shows and raises dock; a minimumHeight > 0 makes it at least that tall.
void bringDockForward(QMainWindow* window, QDockWidget* dock, int minimumHeight = 0);

} // namespace chaplygin::ui
