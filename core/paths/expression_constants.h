#pragma once
// Internal to paths/ (expression.cpp): the check of a typed expression's constant parts before
// GiNaC sees it.
#include <string>

namespace chaplygin {

/// Cheap checks on a typed expression before any symbolic work: parses it with the
/// precedence of muparser, evaluates every constant sub-expression in double precision and
/// throws InputError("<label>, position N") at the first one that overflows (such as
/// 2^(10^10)), so that GiNaC never meets a number it would take gigabytes to represent.
/// It also bounds the size of the parse tree. Syntax errors are left to the compiler proper.
void checkConstantSubexpressions(const std::string& text, const std::string& variable,
                                 const std::string& label);

} // namespace chaplygin
