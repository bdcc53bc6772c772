#include "paths/expression_constants.h"

#include "common/input_error.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>

namespace chaplygin {
namespace {

struct Unparsable {}; // a syntax error: muparser reports it with its own message

double apply(const std::string& f, double x) {
    if (f == "sin")
        return std::sin(x);
    if (f == "cos")
        return std::cos(x);
    if (f == "tan")
        return std::tan(x);
    if (f == "asin")
        return std::asin(x);
    if (f == "acos")
        return std::acos(x);
    if (f == "atan")
        return std::atan(x);
    if (f == "sinh")
        return std::sinh(x);
    if (f == "cosh")
        return std::cosh(x);
    if (f == "tanh")
        return std::tanh(x);
    if (f == "exp")
        return std::exp(x);
    if (f == "sqrt")
        return std::sqrt(x);
    if (f == "abs")
        return std::fabs(x);
    if (f == "ln" || f == "log")
        return std::log(x);
    throw Unparsable{};
}

// a sub-expression: constant (with its value) or depending on the variable
struct Value {
    bool constant = false;
    double v = 0;
    std::size_t pos = 0; // where it starts in the text
};

class ConstantFolder {
  public:
    ConstantFolder(const std::string& text, const std::string& variable, const std::string& label)
        : m_text(text), m_variable(variable), m_label(label) {}

    void run() {
        try {
            skipSpace();
            expression();
        } catch (const Unparsable&) {
        }
    }

  private:
    const std::string& m_text;
    const std::string& m_variable;
    const std::string& m_label;
    std::size_t m_i = 0;

    void skipSpace() {
        while (m_i < m_text.size() && std::isspace(static_cast<unsigned char>(m_text[m_i])))
            ++m_i;
    }
    bool accept(char c) {
        if (m_i < m_text.size() && m_text[m_i] == c) {
            ++m_i;
            skipSpace();
            return true;
        }
        return false;
    }

    // a constant that leaves double range from finite operands
    Value checked(Value r, double a, double b = 0) const {
        if (r.constant && std::isinf(r.v) && std::isfinite(a) && std::isfinite(b))
            throw InputError(m_label + ", position " + std::to_string(r.pos + 1),
                             "a constant overflows double precision (beyond 1.8e308)");
        return r;
    }

    Value expression() {
        Value l = term();
        while (true) {
            char op = m_i < m_text.size() ? m_text[m_i] : 0;
            if (op != '+' && op != '-')
                return l;
            accept(op);
            Value r = term();
            double a = l.v;
            l = checked({l.constant && r.constant, op == '+' ? l.v + r.v : l.v - r.v, l.pos}, a,
                        r.v);
        }
    }

    Value term() {
        Value l = unary();
        while (true) {
            char op = m_i < m_text.size() ? m_text[m_i] : 0;
            if (op != '*' && op != '/')
                return l;
            accept(op);
            Value r = unary();
            double a = l.v;
            bool constant = l.constant && r.constant;
            if (op == '/' && r.v == 0) // division by zero: GiNaC names it
                l = {false, 0, l.pos};
            else
                l = checked({constant, op == '*' ? l.v * r.v : l.v / r.v, l.pos}, a, r.v);
        }
    }

    Value unary() {
        std::size_t start = m_i;
        if (accept('-')) {
            Value v = unary();
            return {v.constant, -v.v, start};
        }
        if (accept('+')) {
            Value v = unary();
            v.pos = start;
            return v;
        }
        return power();
    }

    // a^b binds tighter than a unary minus on its left; the exponent may carry a sign
    Value power() {
        Value base = atom();
        if (!accept('^'))
            return base;
        Value exponent = unary();
        if (base.constant && base.v == 0 && exponent.v < 0) // a pole: GiNaC names it
            return {false, 0, base.pos};
        return checked({base.constant && exponent.constant, std::pow(base.v, exponent.v), base.pos},
                       base.v, exponent.v);
    }

    Value atom() {
        std::size_t start = m_i;
        if (m_i >= m_text.size())
            throw Unparsable{};
        unsigned char c = static_cast<unsigned char>(m_text[m_i]);
        if (accept('(')) {
            Value v = expression();
            if (!accept(')'))
                throw Unparsable{};
            v.pos = start;
            return v;
        }
        if (std::isdigit(c) || c == '.') {
            char* end = nullptr;
            double v = std::strtod(m_text.c_str() + m_i, &end);
            if (end == m_text.c_str() + m_i)
                throw Unparsable{};
            m_i = static_cast<std::size_t>(end - m_text.c_str());
            skipSpace();
            return {true, v, start};
        }
        if (!std::isalpha(c) && c != '_')
            throw Unparsable{};
        std::size_t j = m_i;
        while (j < m_text.size() &&
               (std::isalnum(static_cast<unsigned char>(m_text[j])) || m_text[j] == '_'))
            ++j;
        std::string name = m_text.substr(m_i, j - m_i);
        m_i = j;
        skipSpace();
        if (name == m_variable)
            return {false, 0, start};
        if (name == "pi")
            return {true, M_PI, start};
        if (name == "e")
            return {true, M_E, start};
        if (!accept('('))
            throw Unparsable{};
        Value a = expression();
        if (!accept(')'))
            throw Unparsable{};
        if ((name == "ln" || name == "log") && a.v == 0) // a pole: GiNaC names it
            return {false, 0, start};
        return checked({a.constant, apply(name, a.v), start}, a.v);
    }
};

} // namespace

void checkConstantSubexpressions(const std::string& text, const std::string& variable,
                                 const std::string& label) {
    ConstantFolder(text, variable, label).run();
}

} // namespace chaplygin
