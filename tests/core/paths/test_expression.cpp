// Typed expressions: exact derivatives, the documented syntax, and messages with positions.
#include "common/input_error.h"
#include "paths/expression.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace chaplygin;

namespace {

std::string errorOf(const std::string& text, const std::string& var = "x") {
    try {
        Expression::compile(text, var, "y(x)");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(Expression, ExactDerivativesUpToThird) {
    Expression e = Expression::compile("sin(2*x) + x^3*exp(-x) + ln(1 + x^2)", "x", "y(x)");
    for (double x : {-1.3, 0.0, 0.4, 2.2}) {
        Jet3 j = e.jet(x);
        double ex = std::exp(-x), q = 1 + x * x;
        EXPECT_NEAR(j.v, std::sin(2 * x) + x * x * x * ex + std::log(q), 1e-14);
        EXPECT_NEAR(j.d1, 2 * std::cos(2 * x) + (3 * x * x - x * x * x) * ex + 2 * x / q, 1e-13);
        EXPECT_NEAR(j.d2,
                    -4 * std::sin(2 * x) + (6 * x - 6 * x * x + x * x * x) * ex +
                        (2 - 2 * x * x) / (q * q),
                    1e-13);
        EXPECT_NEAR(j.d3,
                    -8 * std::cos(2 * x) + (6 - 18 * x + 9 * x * x - x * x * x) * ex +
                        (4 * x * x * x - 12 * x) / (q * q * q),
                    1e-12);
    }
}

TEST(Expression, AllDocumentedNamesWork) {
    Expression e = Expression::compile(
        "sin(x)+cos(x)+tan(x)+asin(x/2)+acos(x/"
        "2)+atan(x)+sinh(x)+cosh(x)+tanh(x)+exp(x)+sqrt(x)+abs(x)+ln(x)+log(x)+pi+e",
        "x", "y(x)");
    double x = 0.7;
    double expected = std::sin(x) + std::cos(x) + std::tan(x) + std::asin(x / 2) +
                      std::acos(x / 2) + std::atan(x) + std::sinh(x) + std::cosh(x) + std::tanh(x) +
                      std::exp(x) + std::sqrt(x) + std::abs(x) + 2 * std::log(x) + M_PI + M_E;
    EXPECT_NEAR(e.value(x), expected, 1e-13);
    // d/dx: derivative of abs is sign for real x
    EXPECT_NEAR(Expression::compile("abs(x)^3", "x", "f").jet(-2).d1, -12, 1e-13);
    EXPECT_NEAR(Expression::compile("-x^2", "x", "f").value(3), -9, 0);
    EXPECT_NEAR(Expression::compile("2*-x", "x", "f").jet(3).d1, -2, 0);
}

TEST(Expression, ErrorsNamePositionAndProblem) {
    EXPECT_NE(errorOf("sin(x").find("missing ')'"), std::string::npos) << errorOf("sin(x");
    EXPECT_NE(errorOf("sin(foo)").find("position 5: unknown name 'foo'"), std::string::npos)
        << errorOf("sin(foo)");
    EXPECT_NE(errorOf("2*u").find("position 3: unknown name 'u'"), std::string::npos)
        << errorOf("2*u");
    EXPECT_NE(errorOf("y=x=5").find("position 1: unknown name 'y'"), std::string::npos)
        << errorOf("y=x=5");
    EXPECT_NE(errorOf("x=5").find("'=' is not allowed"), std::string::npos) << errorOf("x=5");
    EXPECT_NE(errorOf("1/0&&2").find("position 4: character '&'"), std::string::npos)
        << errorOf("1/0&&2");
    EXPECT_NE(errorOf("x > 1 ? 1 : 0").find("character '>'"), std::string::npos);
    EXPECT_NE(errorOf("2\xCF\x80x").find("position 2: non-ASCII"), std::string::npos)
        << errorOf("2\xCF\x80x");
    EXPECT_NE(errorOf("").find("empty"), std::string::npos);
    EXPECT_NE(errorOf("   ").find("empty"), std::string::npos);
    EXPECT_NE(errorOf("x)").find("position 2: ')' without"), std::string::npos) << errorOf("x)");
    EXPECT_NE(errorOf("2^3^x").find("a^(b^c)"), std::string::npos) << errorOf("2^3^x");
    EXPECT_NE(errorOf("x**2").find("position"), std::string::npos) << errorOf("x**2");
    EXPECT_NE(errorOf("sin()").find("position"), std::string::npos) << errorOf("sin()");
    EXPECT_NE(errorOf("_pi*x").find("unknown name '_pi'"), std::string::npos) << errorOf("_pi*x");
    EXPECT_NE(errorOf(std::string(20000, '1')).find("20000 characters"), std::string::npos);
    // found by fuzz_expression: GiNaC throws while differentiating 0^e
    EXPECT_NE(errorOf("0^e+112").find("division by zero"), std::string::npos) << errorOf("0^e+112");
    // found by fuzz_expression: GiNaC would build 10^112222222222 digit by digit
    EXPECT_NE(
        errorOf("0e112222222222").find("position 1: the number '0e112222222222' is out of range"),
        std::string::npos)
        << errorOf("0e112222222222");
    EXPECT_NE(errorOf("x*1e-400").find("position 3"), std::string::npos) << errorOf("x*1e-400");
    EXPECT_NE(errorOf("1e309").find("out of range"), std::string::npos);
    std::string deep = std::string(150, '(') + "x" + std::string(150, ')');
    EXPECT_NE(errorOf(deep).find("nested deeper"), std::string::npos);
}
