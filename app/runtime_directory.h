#pragma once

namespace chaplygin::app {

/// Qt wants a private runtime directory, even on the offscreen platform. When XDG_RUNTIME_DIR is
/// unset, this creates <tmp>/chaplygin-lab-runtime-<uid> (mode 0700) and points the variable at it.
void ensureRuntimeDirectory();

} // namespace chaplygin::app
