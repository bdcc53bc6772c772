// libFuzzer target: the expression front end (and the number fields' evaluateNumber), the path
// tabulation behind it and the cusp search. Any input must end in a compiled expression or an
// InputError: never a crash, a hang or UB.
#include "common/input_error.h"
#include "paths/cusp_finder.h"
#include "paths/expression.h"
#include "paths/expression_curve.h"
#include "paths/path.h"

#include <cmath>
#include <cstdint>
#include <string>

namespace {
// The sanitizer build runs the tabulation ~30x slower than a release build: a tenth of the table's
// budget keeps the costliest accepted input under the 10 s timeout while every refusal and
// fallback is still reached (docs/robustness.md).
constexpr std::size_t kHalvingBudget = chaplygin::PathTable::kHalvingBudget / 10;
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);
    try {
        // the number fields' reading of the same text: a finite double or an InputError
        if (!std::isfinite(chaplygin::evaluateNumber(text, "m")))
            __builtin_trap();
    } catch (const chaplygin::InputError&) {
    }
    try {
        chaplygin::Expression e = chaplygin::Expression::compile(text, "x", "y(x)");
        for (double x : {-1.5, 0.0, 0.25, 2.0}) {
            chaplygin::Jet3 j = e.jet(x);
            (void)j;
        }
        try {
            // the same expression as y(u) beside x = u^2, whose x' vanishes at u = 0
            chaplygin::ParametricCurve c(chaplygin::Expression::compile("x^2", "x", "x(u)"), e, -1,
                                         1);
            for (const chaplygin::Cusp& cusp : chaplygin::findCusps(c))
                if (!(cusp.u > -1 && cusp.u < 1) || !std::isfinite(cusp.turnRate))
                    __builtin_trap();
        } catch (const chaplygin::InputError&) {
        }
        chaplygin::PathSource p;
        p.kind = chaplygin::PathKind::Graph;
        p.y = text;
        p.from = -1;
        p.to = 1;
        auto path = chaplygin::buildPath(p, kHalvingBudget);
        if (!std::isfinite(path->length()))
            __builtin_trap();
    } catch (const chaplygin::InputError&) {
    }
    return 0;
}
