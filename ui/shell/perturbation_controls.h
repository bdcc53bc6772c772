#pragma once

namespace chaplygin::ui {

class MainWindow;

/// Adds perturbed tracking to a window (docs/physics.md §9): the Perturbation dock (tabbed with
/// the parameters), View's toggles of the open-loop and closed-loop bodies, and the canvas's grab
/// and push, each edit one undo step. Called once, by the window.
void installPerturbationControls(MainWindow* window);

} // namespace chaplygin::ui
