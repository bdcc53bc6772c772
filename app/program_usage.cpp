#include "program_usage.h"

#include "headless_options.h"
#include "version.h"

#include <cstring>

namespace chaplygin::app {

std::string programUsage() {
    return std::string(R"(Usage: chaplygin-lab [FILE | scene options] [--presentation]
       chaplygin-lab --screenshot FILE.png [screenshot options] [scene options]
       chaplygin-lab --headless [scene options] [output options]
       chaplygin-lab --help | --version
Desktop window:
  FILE                                        a scene file to open (JSON, as File > Save writes it)
  --presentation                              start in presentation mode (full screen, large type)
Screenshot (the window rendered offscreen, no display needed):
  --screenshot FILE.png                       write the window to FILE.png and exit
  --size WxH                                  the window's size (default 1280x800)
  --at T                                      the moment shown [s] (default 0)
  --panel path|parameters|methods|sweep|notes|equations
                                              the dock raised (methods computes the
                                              work-precision diagram; sweep runs --sweep)
  --presentation                              presentation mode at that size
  --language en|pt_BR                         that catalogue instead of the system's
General:
  -h, --help                                  print this text and exit
  --version                                   print the version and exit
)") + headlessUsage();
}

std::string versionText() {
    return std::string("chaplygin-lab ") + CHAPLYGIN_LAB_VERSION + "\n";
}

ProgramMode programMode(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0)
            return ProgramMode::Help;
        if (std::strcmp(argv[i], "--version") == 0)
            return ProgramMode::Version;
    }
    for (int i = 1; i < argc; ++i)
        if (std::strcmp(argv[i], "--headless") == 0)
            return ProgramMode::Headless;
    for (int i = 1; i < argc; ++i)
        if (std::strcmp(argv[i], "--screenshot") == 0)
            return ProgramMode::Screenshot;
    return ProgramMode::Desktop;
}

} // namespace chaplygin::app
