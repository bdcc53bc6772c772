#pragma once
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace chaplygin::app {

/// The three ways the program runs; an option applies to one or more of them.
enum RunMode : unsigned { Window = 1u, Screenshot = 2u, Headless = 4u };

/// The sections of --help, in the order printed.
enum class OptionSection { Window, Screenshot, Scene, System, Output, General };

/// One command-line option: the one table from which the parsers read the arguments and --help
/// and the man page are written (app/program_usage.cpp).
struct OptionSpec {
    std::string_view name;     ///< "--preset"
    std::string_view argument; ///< what follows it ("line|circle|..."), empty for a flag
    std::string_view help;     ///< one or more lines, separated by '\n'
    unsigned modes;            ///< RunMode bits where it is accepted
    OptionSection section;
    bool repeatable = false; ///< may be given more than once (--param)
};

/// Every option, in the order --help lists them.
std::span<const OptionSpec> optionTable();

/// The entry for `name` accepted in `mode`, or null.
const OptionSpec* findOption(std::string_view name, RunMode mode);

/// The arguments of one run, read against the table: each option with its value.
class OptionValues {
  public:
    /// The value of an option given once, or nothing when it was not given.
    std::optional<std::string> value(std::string_view name) const;
    /// Every value of a repeatable option, in the order given.
    std::vector<std::string> values(std::string_view name) const;
    /// Whether the option (a flag or one with a value) was given.
    bool has(std::string_view name) const;
    /// Whether any option of `section` was given.
    bool hasAnyOf(OptionSection section) const;

  private:
    friend OptionValues readOptions(const std::vector<std::string>& args, RunMode mode);
    struct Given {
        const OptionSpec* spec;
        std::string value;
    };
    std::vector<Given> m_given;
    const OptionSpec& checked(std::string_view name) const;
};

/// Reads `args` for `mode`. Throws InputError naming the option when one is unknown or belongs to
/// another mode, lacks its value or is given twice (all but the repeatable ones).
OptionValues readOptions(const std::vector<std::string>& args, RunMode mode);

} // namespace chaplygin::app
