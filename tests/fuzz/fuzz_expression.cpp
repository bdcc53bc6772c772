// libFuzzer target: the expression front end and the path tabulation behind it.
// Any input must end in a compiled expression or an InputError: never a crash, a hang or UB.
#include "common/input_error.h"
#include "paths/expression.h"
#include "paths/path.h"

#include <cmath>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);
    try {
        chaplygin::Expression e = chaplygin::Expression::compile(text, "x", "y(x)");
        for (double x : {-1.5, 0.0, 0.25, 2.0}) {
            chaplygin::Jet3 j = e.jet(x);
            (void)j;
        }
        chaplygin::PathSource p;
        p.kind = chaplygin::PathKind::Graph;
        p.y = text;
        p.from = -1;
        p.to = 1;
        auto path = chaplygin::buildPath(p);
        if (!std::isfinite(path->length()))
            __builtin_trap();
    } catch (const chaplygin::InputError&) {
    }
    return 0;
}
