#pragma once
// Classical fourth-order Runge-Kutta for the tests' independent references: a state of named
// doubles, a fixed step, none of the program's code.
#include <array>
#include <cstddef>
#include <vector>

namespace chaplygin::reference {

/// y' = rate(y) by classical RK4 in n equal steps to time t, for a state whose fields are the
/// doubles named in `fields`: the n + 1 states, the first y.
template <class State, std::size_t N, class Rate>
std::vector<State> classicalRk4(State y, const std::array<double State::*, N>& fields, Rate rate,
                                double t, int n) {
    // s + h d, field by field
    auto step = [&](const State& s, const State& d, double h) {
        State out = s;
        for (double State::*f : fields)
            out.*f = s.*f + h * (d.*f);
        return out;
    };
    std::vector<State> out{y};
    const double h = t / n;
    for (int i = 0; i < n; ++i) {
        const State k1 = rate(y), k2 = rate(step(y, k1, h / 2)), k3 = rate(step(y, k2, h / 2)),
                    k4 = rate(step(y, k3, h));
        for (double State::*f : fields)
            y.*f += h / 6 * (k1.*f + 2 * k2.*f + 2 * k3.*f + k4.*f);
        out.push_back(y);
    }
    return out;
}

} // namespace chaplygin::reference
