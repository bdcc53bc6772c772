#pragma once

class QAction;
class QDockWidget;
class QMenu;

namespace chaplygin::ui {

class MainWindow;

/// Adds perturbed tracking to a window (docs/physics.md §9): the Perturbation dock (tabbed with
/// the parameters), View's toggles of the open-loop and closed-loop bodies, and the canvas's grab
/// and push, each edit one undo step. Called once, by the window, with the View menu it extends
/// (its toggles go after `showVakonomic`) and the parameters' dock it tabs with.
void installPerturbationControls(MainWindow* window, QMenu& viewMenu, QAction& showVakonomic,
                                 QDockWidget& parametersDock);

} // namespace chaplygin::ui
