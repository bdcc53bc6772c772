#pragma once

class QDockWidget;
class QMenu;

namespace chaplygin::ui {

class MainWindow;

/// Edit > Measure: the canvas's Measure tool (ruler, protractor, probe; docs/user-guide.md,
/// Measuring) in the Edit menu, on the time line's toolbar and on a key (Ctrl+Shift+M; M on the
/// canvas). Called once, by the window, with its Edit menu.
void installMeasureAction(MainWindow* window, QMenu& editMenu);

/// View > Values: the Values dock (every CSV column at the shown time, and Copy), tabbed with the
/// Accuracy dock and hidden until asked for. Called once, by the window, with the View menu it
/// extends.
void installValuesDock(MainWindow* window, QMenu& viewMenu, QDockWidget& accuracyDock);

} // namespace chaplygin::ui
