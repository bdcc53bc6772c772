// chaplygin-lab: the desktop application, or with --headless the batch command line.
#include "common/memory_reuse.h"
#include "desktop_entry.h"
#include "headless_run.h"

#include <cstring>

int main(int argc, char** argv) {
    chaplygin::keepFreedMemoryForReuse();
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--headless") == 0)
            return chaplygin::app::runHeadless(argc, argv);
        if (std::strcmp(argv[i], "--screenshot") == 0)
            return chaplygin::ui::runScreenshot(argc, argv);
    }
    return chaplygin::ui::runDesktop(argc, argv);
}
