#pragma once
// Typed expressions in one variable with exact derivatives (muparser values, GiNaC derivatives).
#include <memory>
#include <string>

namespace chaplygin {

/// A function value with its first three derivatives, all exact (no finite differences).
struct Jet3 {
    double v = 0, d1 = 0, d2 = 0, d3 = 0;
};

/// A typed real expression in one variable. Syntax: + - * / ^, parentheses, numbers,
/// sin cos tan asin acos atan sinh cosh tanh exp sqrt abs ln log (both natural), pi, e.
/// Values come from muparser bytecode; the derivatives are differentiated symbolically by GiNaC
/// once, then compiled to muparser as well. Thread-safe evaluation; cheap to copy (shared).
class Expression {
  public:
    /// Throws InputError whose where() is "<label>, position N" (1-based character position).
    /// Compiles are serialized process-wide (GiNaC is not thread-safe); any thread may call it.
    static Expression compile(const std::string& text, const std::string& variable,
                              const std::string& label);

    double value(double at) const;
    Jet3 jet(double at) const;
    const std::string& text() const;

  private:
    struct Impl;
    std::shared_ptr<const Impl> m_impl;
};

/// A typed number in the same syntax without a variable ("2*pi", "1e6", "sqrt(2)"), evaluated
/// once by muparser in double precision: a plain decimal reads as strtod reads it. Throws
/// InputError whose where() is label or "<label>, position N" for a syntax error, and one that
/// says so for a result that is not finite (1/0, 10^400).
double evaluateNumber(const std::string& text, const std::string& label);

} // namespace chaplygin
