#pragma once

namespace chaplygin::ui {

/// Starts the desktop application (QApplication, main window, event loop).
int runDesktop(int argc, char** argv);

/// --screenshot FILE.png [scene options] --at T --size WxH: renders the main window at time T
/// offscreen, writes the PNG, returns the exit status (0, 1 or 2 as in headless mode).
int runScreenshot(int argc, char** argv);

} // namespace chaplygin::ui
