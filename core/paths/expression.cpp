#include "paths/expression.h"

#include "common/input_error.h"
#include "paths/expression_constants.h"

#include <ginac/ginac.h>
#include <muParser.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <mutex>
#include <new>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace chaplygin {
namespace {

constexpr std::size_t kMaxLength = 4000;
constexpr int kMaxDepth = 100;
constexpr std::size_t kMaxDerivativeLength = 15000; // muparser compiles up to 20000
constexpr double kMaxDerivativeNodes = 20000;       // an estimate, before differentiating

const std::set<std::string> kFunctions = {"sin",  "cos",  "tan", "asin", "acos", "atan", "sinh",
                                          "cosh", "tanh", "exp", "sqrt", "abs",  "ln",   "log"};

std::string at(const std::string& label, std::size_t index) {
    return label + ", position " + std::to_string(index + 1);
}

// reject everything outside the documented syntax before muparser sees it: this is what
// keeps out assignment (`x=5`), logic (`1/0&&2`), ternaries and non-ASCII text
void checkCharactersAndNames(const std::string& text, const std::string& variable,
                             const std::string& label) {
    if (text.size() > kMaxLength)
        throw InputError(label, "expression is " + std::to_string(text.size()) +
                                    " characters long; the limit is " + std::to_string(kMaxLength));
    int depth = 0;
    bool any = false;
    for (std::size_t i = 0; i < text.size();) {
        unsigned char c = static_cast<unsigned char>(text[i]);
        if (c >= 0x80)
            throw InputError(at(label, i),
                             "non-ASCII character; use the ASCII names (pi, sqrt, ...)");
        if (std::isspace(c)) {
            ++i;
            continue;
        }
        any = true;
        if (std::isalpha(c) || c == '_') {
            std::size_t j = i;
            while (j < text.size() &&
                   (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_'))
                ++j;
            std::string name = text.substr(i, j - i);
            if (name != variable && name != "pi" && name != "e" && !kFunctions.count(name)) {
                std::string hint = name.size() == 1 && !variable.empty()
                                       ? " (the variable here is " + variable + ")"
                                       : "";
                throw InputError(at(label, i), "unknown name '" + name + "'" + hint);
            }
            i = j;
            continue;
        }
        if (std::isdigit(c) || c == '.') {
            // a number, with an optional exponent such as 1e-3
            std::size_t j = i;
            while (j < text.size() &&
                   (std::isdigit(static_cast<unsigned char>(text[j])) || text[j] == '.'))
                ++j;
            if (j < text.size() && (text[j] == 'e' || text[j] == 'E') && j + 1 < text.size() &&
                (std::isdigit(static_cast<unsigned char>(text[j + 1])) ||
                 ((text[j + 1] == '-' || text[j + 1] == '+') && j + 2 < text.size() &&
                  std::isdigit(static_cast<unsigned char>(text[j + 2]))))) {
                j += 2;
                while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])))
                    ++j;
            }
            // a literal must be a normal double; this also keeps GiNaC from building 10^(10^11)
            std::string literal = text.substr(i, j - i);
            errno = 0;
            double value = std::strtod(literal.c_str(), nullptr);
            std::size_t exponent = literal.find_first_of("eE");
            std::size_t exponentDigits =
                exponent == std::string::npos
                    ? 0
                    : literal.size() - exponent - 1 -
                          (literal[exponent + 1] == '-' || literal[exponent + 1] == '+');
            if (errno == ERANGE || !std::isfinite(value) || exponentDigits > 3)
                throw InputError(at(label, i), "the number '" + literal.substr(0, 40) +
                                                   "' is out of range (|x| from 2.2e-308 to "
                                                   "1.8e308, at most 3 exponent digits)");
            i = j;
            continue;
        }
        if (c == '(') {
            if (++depth > kMaxDepth)
                throw InputError(at(label, i),
                                 "parentheses nested deeper than " + std::to_string(kMaxDepth));
        } else if (c == ')') {
            if (--depth < 0)
                throw InputError(at(label, i), "')' without a matching '('");
        } else if (!std::strchr("+-*/^", c)) {
            throw InputError(at(label, i), std::string("character '") + char(c) +
                                               "' is not allowed (use + - * / ^ and parentheses)");
        }
        ++i;
    }
    if (!any)
        throw InputError(label, "the expression is empty");
    if (depth > 0)
        throw InputError(at(label, text.size()), "missing ')'");
}

// The end of the operand that starts at i: a number (with its exponent), a name with its
// argument list, or a parenthesised group; i itself if none starts there.
std::size_t operandEnd(const std::string& s, std::size_t i) {
    auto skipGroup = [&](std::size_t k) { // s[k] == '(': past its matching ')'
        for (int depth = 0; k < s.size(); ++k) {
            depth += s[k] == '(' ? 1 : (s[k] == ')' ? -1 : 0);
            if (depth == 0)
                return k + 1;
        }
        return s.size();
    };
    std::size_t k = i;
    if (k < s.size() && (std::isdigit(static_cast<unsigned char>(s[k])) || s[k] == '.')) {
        while (k < s.size() && (std::isdigit(static_cast<unsigned char>(s[k])) || s[k] == '.'))
            ++k;
        std::size_t e = k;
        if (e < s.size() && (s[e] == 'e' || s[e] == 'E')) {
            ++e;
            if (e < s.size() && (s[e] == '+' || s[e] == '-'))
                ++e;
            if (e < s.size() && std::isdigit(static_cast<unsigned char>(s[e]))) {
                while (e < s.size() && std::isdigit(static_cast<unsigned char>(s[e])))
                    ++e;
                k = e;
            }
        }
        return k;
    }
    if (k < s.size() && std::isalpha(static_cast<unsigned char>(s[k]))) {
        while (k < s.size() && std::isalnum(static_cast<unsigned char>(s[k])))
            ++k;
        std::size_t j = k;
        while (j < s.size() && s[j] == ' ')
            ++j;
        return j < s.size() && s[j] == '(' ? skipGroup(j) : k;
    }
    return k < s.size() && s[k] == '(' ? skipGroup(k) : k;
}

// A sign after '^' applies to the operand that follows it only, as in the value's parser
// (muparser): x^-1+2 is x^(-1)+2. GiNaC's parser lets such a sign take the rest of the
// expression (x^(-1+2)), so the sign and its operand are put in parentheses for it.
std::string signedExponentsGrouped(const std::string& s) {
    std::string out;
    for (std::size_t i = 0; i < s.size();) {
        out += s[i];
        if (s[i++] != '^')
            continue;
        std::size_t j = i;
        while (j < s.size() && (s[j] == ' ' || s[j] == '+' || s[j] == '-'))
            ++j;
        if (j == i || s.find_first_of("+-", i) >= j)
            continue; // no sign
        const std::size_t end = operandEnd(s, j);
        if (end == j)
            continue; // no operand: GiNaC reports the syntax error
        out += '(' + s.substr(i, j - i) + signedExponentsGrouped(s.substr(j, end - j)) + ')';
        i = end;
    }
    return out;
}

// `ln` is GiNaC's `log`; `pi` and `e` are constants. Numbers become floating point, so that
// GiNaC never evaluates an exact power such as 2^(10^9) digit by digit.
std::string toGinacSyntax(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        if (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.') {
            std::size_t j = i;
            bool fractional = false;
            while (j < text.size() &&
                   (std::isdigit(static_cast<unsigned char>(text[j])) || text[j] == '.')) {
                fractional = fractional || text[j] == '.';
                ++j;
            }
            std::string number = text.substr(i, j - i);
            if (number.front() == '.')
                number = "0" + number;
            if (number.back() == '.')
                number += '0';
            if (!fractional)
                number += ".0";
            out += number;
            i = j;
            // an exponent (1e-3) is copied as it is: the mantissa is already floating point
            if (i < text.size() && (text[i] == 'e' || text[i] == 'E') && i + 1 < text.size() &&
                (std::isdigit(static_cast<unsigned char>(text[i + 1])) || text[i + 1] == '-' ||
                 text[i + 1] == '+')) {
                out += text[i++];
                out += text[i++];
                while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])))
                    out += text[i++];
            }
        } else if (std::isalpha(static_cast<unsigned char>(text[i]))) {
            std::size_t j = i;
            while (j < text.size() && std::isalnum(static_cast<unsigned char>(text[j])))
                ++j;
            std::string name = text.substr(i, j - i);
            out += name == "ln" ? "log" : name;
            i = j;
        } else {
            out += text[i++];
        }
    }
    return out;
}

// what GiNaC throws while parsing or differentiating, as a message about the expression
[[noreturn]] void throwGinacError(const std::exception& e, const std::string& label) {
    std::string msg = e.what();
    if (msg.find("power should have exactly 2 operands") != std::string::npos)
        throw InputError(label, "chained powers a^b^c are ambiguous: write a^(b^c) or (a^b)^c");
    if (msg.find("division by zero") != std::string::npos)
        throw InputError(label, "division by zero in a constant part of the expression");
    // CLN computes constants exactly; a huge one (a long float literal summed with large powers)
    // asks for more memory than there is, and the allocation fails
    if (dynamic_cast<const std::bad_alloc*>(&e) ||
        msg.find("Out of virtual memory") != std::string::npos)
        throw InputError(label, "a constant part is too large to compute exactly (it needs more "
                                "memory than there is): shorten long numbers and huge powers");
    throw InputError(label, "cannot be differentiated: " + msg.substr(0, msg.find('\n')));
}

// GiNaC prints floats beyond double range as 1.0E400: three or more exponent digits
bool hasHugeExponent(const std::string& printed) {
    for (std::size_t i = printed.find('E'); i != std::string::npos; i = printed.find('E', i + 1)) {
        std::size_t j = i + 1;
        while (j < printed.size() && std::isdigit(static_cast<unsigned char>(printed[j])))
            ++j;
        if (j - i - 1 >= 3)
            return true;
    }
    return false;
}

// the tree size of e (shared sub-expressions counted each time, as printed) and an estimate of
// its derivative's: the product rule copies all other factors once per factor, the chain rule
// copies the argument. Visits at most `budget` nodes, so it is cheap whatever e is.
struct TreeSize {
    double size = 0, derivative = 0;
};

TreeSize treeSize(const GiNaC::ex& e, double& budget) {
    if (--budget < 0)
        return {INFINITY, INFINITY};
    if (e.nops() == 0)
        return {1, 1};
    std::vector<TreeSize> ops;
    double size = 1, derivatives = 0;
    for (std::size_t i = 0; i < e.nops(); ++i) {
        ops.push_back(treeSize(e.op(i), budget));
        size += ops.back().size;
        derivatives += ops.back().derivative;
    }
    if (!std::isfinite(size))
        return {INFINITY, INFINITY};
    double k = double(ops.size());
    if (GiNaC::is_a<GiNaC::add>(e))
        return {size, 1 + derivatives};
    if (GiNaC::is_a<GiNaC::mul>(e))
        return {size, 1 + k + (k - 1) * (size - 1) + derivatives};
    // powers, functions: the operands' copies and their derivatives, a few nodes more
    return {size, 3 * size + derivatives + 8};
}

// e in muparser's syntax, with the terms of every sum and the factors of every product sorted by
// their text: GiNaC keeps them in an order of hash values seeded from addresses, and its own
// printing would make the summation order, and so the last bits of a derivative's value, change
// from run to run (docs/numerics.md §11). Otherwise as GiNaC prints: a product's numeric
// coefficient first, sqrt for the power 1/2, rationals and floats in parentheses where a product
// or a power holds them.
enum class Precedence { Sum, Product, Power };

std::string muparserText(const GiNaC::ex& e, Precedence within);

std::string defaultText(const GiNaC::ex& e) {
    std::ostringstream out;
    out << e;
    return out.str();
}

std::string numericText(const GiNaC::numeric& n, Precedence within) {
    const std::string text = defaultText(n);
    const bool plain = n.is_integer() && n.is_nonneg_integer();
    return plain || (within == Precedence::Sum && n.is_integer()) ? text : "(" + text + ")";
}

std::string sortedJoin(std::vector<std::string> parts, const char* separator) {
    std::sort(parts.begin(), parts.end());
    std::string out;
    for (const std::string& part : parts) {
        if (!out.empty() && !(separator[0] == '+' && part.front() == '-'))
            out += separator;
        out += part;
    }
    return out;
}

std::string muparserText(const GiNaC::ex& e, Precedence within) {
    using namespace GiNaC;
    if (is_a<add>(e)) {
        std::vector<std::string> terms;
        for (std::size_t i = 0; i < e.nops(); ++i)
            terms.push_back(muparserText(e.op(i), Precedence::Sum));
        const std::string sum = sortedJoin(std::move(terms), "+");
        return within == Precedence::Sum ? sum : "(" + sum + ")";
    }
    if (is_a<mul>(e)) {
        // the numeric coefficient first, as GiNaC prints it: -x, 3*x, (1/3)*x
        numeric coefficient = 1;
        std::vector<std::string> factors;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            if (is_a<numeric>(e.op(i)))
                coefficient *= ex_to<numeric>(e.op(i));
            else
                factors.push_back(muparserText(e.op(i), Precedence::Product));
        }
        std::string product = sortedJoin(std::move(factors), "*");
        if (coefficient.is_equal(-1))
            product = "-" + product;
        else if (!coefficient.is_equal(1))
            product = (coefficient.is_negative() && coefficient.is_integer()
                           ? defaultText(coefficient)
                           : numericText(coefficient, Precedence::Product)) +
                      "*" + product;
        const bool bare =
            within == Precedence::Sum || (within == Precedence::Product && product.front() != '-');
        return bare ? product : "(" + product + ")";
    }
    if (is_a<power>(e)) {
        const ex base = e.op(0), exponent = e.op(1);
        if (exponent.is_equal(numeric(1, 2)))
            return "sqrt(" + muparserText(base, Precedence::Sum) + ")";
        std::string text = muparserText(base, Precedence::Power) + "^";
        if (is_a<numeric>(exponent) && ex_to<numeric>(exponent).is_pos_integer())
            text += defaultText(exponent);
        else
            text += "(" + muparserText(exponent, Precedence::Sum) + ")";
        return within == Precedence::Power ? "(" + text + ")" : text;
    }
    if (is_a<numeric>(e))
        return numericText(ex_to<numeric>(e), within);
    if (is_a<function>(e)) {
        std::string text = ex_to<function>(e).get_name() + "(";
        for (std::size_t i = 0; i < e.nops(); ++i)
            text += (i > 0 ? "," : "") + muparserText(e.op(i), Precedence::Sum);
        return text + ")";
    }
    // a symbol or a constant (Pi)
    return defaultText(e);
}

void defineCommon(mu::Parser& p) {
    p.DefineConst("pi", M_PI);
    p.DefineConst("e", M_E);
    p.DefineConst("Pi", M_PI);
    p.DefineFun("log", static_cast<double (*)(double)>(std::log));
    p.DefineFun("ln", static_cast<double (*)(double)>(std::log));
}

} // namespace

struct Expression::Impl {
    std::string text;
    mutable double var = 0;
    mutable std::mutex mutex;
    std::array<mu::Parser, 4> parsers; // value, d/dv, d2/dv2, d3/dv3
};

Expression Expression::compile(const std::string& text, const std::string& variable,
                               const std::string& label) {
    // GiNaC's reference counts and tables are not thread-safe: one compile at a time
    static std::mutex compileMutex;
    std::lock_guard compileLock(compileMutex);
    checkCharactersAndNames(text, variable, label);
    auto impl = std::make_shared<Impl>();
    impl->text = text;

    // value: muparser on the user's text, which gives syntax errors with their position
    mu::Parser& p0 = impl->parsers[0];
    defineCommon(p0);
    p0.DefineVar(variable, &impl->var);
    try {
        p0.SetExpr(text);
        p0.Eval();
    } catch (const mu::Parser::exception_type& e) {
        throw InputError(at(label, static_cast<std::size_t>(std::max(0, e.GetPos()))), e.GetMsg());
    }
    // constants are evaluated in double first: GiNaC would represent 2^(10^10) exactly
    checkConstantSubexpressions(text, variable, label);

    // derivatives: GiNaC, printed back into muparser syntax
    GiNaC::realsymbol sym(variable);
    GiNaC::symtab table;
    table[variable] = sym;
    table["pi"] = GiNaC::Pi;
    table["e"] = GiNaC::exp(GiNaC::ex(1));
    GiNaC::parser reader(table);
    reader.strict = true;
    GiNaC::ex f;
    try {
        f = reader(signedExponentsGrouped(toGinacSyntax(text)));
    } catch (const std::exception& e) {
        throwGinacError(e, label);
    }
    for (int k = 1; k <= 3; ++k) {
        // refuse before GiNaC builds and prints a derivative of millions of terms
        double budget = kMaxDerivativeNodes;
        TreeSize estimate = treeSize(f, budget);
        if (!(estimate.derivative <= kMaxDerivativeNodes))
            throw InputError(label, "too complex to differentiate: derivative " +
                                        std::to_string(k) + " would have more than " +
                                        std::to_string(int(kMaxDerivativeNodes)) + " terms");
        try {
            f = f.diff(sym); // GiNaC evaluates constants here too, e.g. 0^e when differentiated
        } catch (const std::exception& e) {
            throwGinacError(e, label);
        }
        std::ostringstream printed;
        printed << muparserText(f, Precedence::Sum);
        if (printed.str().size() > kMaxDerivativeLength)
            throw InputError(
                label, "too complex to differentiate: derivative " + std::to_string(k) + " has " +
                           std::to_string(printed.str().size()) + " characters (the limit is " +
                           std::to_string(kMaxDerivativeLength) + ")");
        mu::Parser& pk = impl->parsers[k];
        defineCommon(pk);
        pk.DefineVar(variable, &impl->var);
        try {
            pk.SetExpr(printed.str());
            pk.Eval();
        } catch (const mu::Parser::exception_type&) {
            if (hasHugeExponent(printed.str()))
                throw InputError(label, "a constant overflows double precision (beyond 1.8e308)");
            throw InputError(label, "derivative " + std::to_string(k) +
                                        " is not a real expression (" +
                                        printed.str().substr(0, 80) + ")");
        }
    }
    Expression e;
    e.m_impl = impl;
    return e;
}

double Expression::value(double at) const {
    std::lock_guard lock(m_impl->mutex);
    m_impl->var = at;
    return m_impl->parsers[0].Eval();
}

Jet3 Expression::jet(double at) const {
    std::lock_guard lock(m_impl->mutex);
    m_impl->var = at;
    Jet3 j;
    j.v = m_impl->parsers[0].Eval();
    j.d1 = m_impl->parsers[1].Eval();
    j.d2 = m_impl->parsers[2].Eval();
    j.d3 = m_impl->parsers[3].Eval();
    return j;
}

const std::string& Expression::text() const {
    return m_impl->text;
}

double evaluateNumber(const std::string& text, const std::string& label) {
    checkCharactersAndNames(text, std::string(), label); // no variable: every name is a constant
    mu::Parser parser;
    defineCommon(parser);
    double value = 0;
    try {
        parser.SetExpr(text);
        value = parser.Eval();
    } catch (const mu::Parser::exception_type& e) {
        throw InputError(at(label, static_cast<std::size_t>(std::max(0, e.GetPos()))), e.GetMsg());
    }
    if (!std::isfinite(value))
        throw InputError(label, "'" + text.substr(0, 40) + "' is not a finite number");
    return value;
}

} // namespace chaplygin
