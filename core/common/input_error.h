#pragma once
// InputError, the one kind of user-facing failure, which names its place, and formatNumber for
// messages.
#include <stdexcept>
#include <string>

namespace chaplygin {

/// Bad user input: an expression, a parameter, a range, a file. `where()` names the place
/// (an option, a parameter, a character position, an x or u on the path); what() is the full
/// message "where: what".
class InputError : public std::runtime_error {
  public:
    InputError(std::string where, const std::string& what)
        : std::runtime_error(where.empty() ? what : where + ": " + what),
          m_where(std::move(where)) {}
    const std::string& where() const { return m_where; }

  private:
    std::string m_where;
};

/// Formats a double for messages: shortest form that round-trips.
std::string formatNumber(double v);

} // namespace chaplygin
