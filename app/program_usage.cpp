#include "program_usage.h"

#include "option_table.h"
#include "version.h"

#include <cstring>
#include <string_view>
#include <vector>

namespace chaplygin::app {

namespace {

constexpr std::size_t kHelpColumn = 46; // where the options' explanations start
constexpr std::size_t kWidth = 98;      // and where they end

const char* sectionTitle(OptionSection section) {
    switch (section) {
    case OptionSection::Window:
        return "Desktop window:\n"
               "  FILE                                        a scene file to open (JSON, as File "
               "> "
               "Save writes it)\n";
    case OptionSection::Screenshot:
        return "Screenshot (the window rendered offscreen, no display needed):\n";
    case OptionSection::Scene:
        return "Scene (one of, for the window, the screenshot and the headless run):\n";
    case OptionSection::System:
        return "System and motion:\n";
    case OptionSection::Output:
        return "Headless run:\n";
    case OptionSection::General:
        return "General:\n";
    }
    return "";
}

// the explanation as one paragraph, wrapped at spaces to fit from kHelpColumn to kWidth
std::vector<std::string> helpLines(std::string_view help) {
    std::vector<std::string> lines;
    std::string line;
    std::size_t start = 0;
    while (start < help.size()) {
        std::size_t end = help.find_first_of(" \n", start);
        if (end == std::string_view::npos)
            end = help.size();
        std::string_view word = help.substr(start, end - start);
        if (!line.empty() && line.size() + 1 + word.size() > kWidth - kHelpColumn) {
            lines.push_back(line);
            line.clear();
        }
        if (!word.empty())
            line.append(line.empty() ? "" : " ").append(word);
        start = end + 1;
    }
    if (!line.empty())
        lines.push_back(line);
    return lines;
}

// "  --name ARGUMENT" and the explanation from kHelpColumn on
std::string optionLines(const OptionSpec& spec) {
    std::string out = "  ";
    out.append(spec.name);
    if (!spec.argument.empty())
        out.append(" ").append(spec.argument);
    bool first = true;
    for (const std::string& line : helpLines(spec.help)) {
        if (first && out.size() + 1 < kHelpColumn)
            out.append(kHelpColumn - out.size(), ' ');
        else
            out.append("\n").append(kHelpColumn, ' ');
        out.append(line);
        first = false;
    }
    return out + "\n";
}

} // namespace

std::string programUsage() {
    std::string usage =
        "Usage: chaplygin-lab [FILE | LINK | scene options] [--presentation]\n"
        "       chaplygin-lab --screenshot FILE.png [screenshot options] [scene options]\n"
        "       chaplygin-lab --headless [scene options] [output options]\n"
        "       chaplygin-lab --help | --version\n";
    for (OptionSection section :
         {OptionSection::Window, OptionSection::Screenshot, OptionSection::Scene,
          OptionSection::System, OptionSection::Output, OptionSection::General}) {
        usage += sectionTitle(section);
        for (const OptionSpec& spec : optionTable())
            if (spec.section == section)
                usage += optionLines(spec);
    }
    return usage +
           "Expressions: + - * / ^ ( ), sin cos tan asin acos atan sinh cosh tanh exp sqrt abs "
           "ln log, pi, e.\n"
           "Exit status: 0 success, 2 bad input (the message names the option or the place), 1 "
           "internal failure.\n";
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
