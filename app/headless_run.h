#pragma once

namespace chaplygin::app {

/// The headless command line (README, Headless examples). Returns 0 on success, 2 on bad input
/// (a message on stderr names the option or the place), 1 on an internal failure.
int runHeadless(int argc, char** argv);

} // namespace chaplygin::app
