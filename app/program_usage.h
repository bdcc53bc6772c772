#pragma once
#include <string>

namespace chaplygin::app {

/// The whole command line as --help prints it and the man page shows it (scripts/cmake/
/// man_page.cmake): the desktop window, the offscreen screenshot and the headless runs.
std::string programUsage();

/// "chaplygin-lab VERSION", as --version prints it.
std::string versionText();

/// What the first look at the arguments decides, before any window system is touched.
enum class ProgramMode { Help, Version, Headless, Screenshot, Desktop };

/// --help/-h and --version win wherever they stand; then --headless, then --screenshot; anything
/// else opens the desktop window.
ProgramMode programMode(int argc, char** argv);

} // namespace chaplygin::app
