// chaplygin-lab: the desktop application, or with --headless the batch command line.
#include "common/memory_reuse.h"
#include "desktop_entry.h"
#include "headless_run.h"
#include "program_usage.h"

#include <cstdio>

int main(int argc, char** argv) {
    chaplygin::keepFreedMemoryForReuse();
    using chaplygin::app::ProgramMode;
    switch (chaplygin::app::programMode(argc, argv)) {
    case ProgramMode::Help:
        std::fputs(chaplygin::app::programUsage().c_str(), stdout);
        return 0;
    case ProgramMode::Version:
        std::fputs(chaplygin::app::versionText().c_str(), stdout);
        return 0;
    case ProgramMode::Headless:
        return chaplygin::app::runHeadless(argc, argv);
    case ProgramMode::Screenshot:
        return chaplygin::ui::runScreenshot(argc, argv);
    case ProgramMode::Desktop:
        break;
    }
    return chaplygin::ui::runDesktop(argc, argv);
}
