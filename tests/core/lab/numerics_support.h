#pragma once
#include "lab/method_registry.h"
#include "lab/quadrature_time_law.h"
#include "scene/presets.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace chaplygin::test {

inline std::vector<double> evenTimes(double end, int count = 100) {
    std::vector<double> t(count);
    for (int i = 0; i < count; ++i)
        t[i] = i + 1 == count ? end : end * i / (count - 1);
    return t;
}

inline Scene sceneWith(const std::string& preset, double tEnd) {
    Scene s = presetScene(preset);
    s.tEnd = tEnd;
    return s;
}

inline const Method& methodNamed(const std::vector<Method>& methods, MotionProblem problem,
                                 const std::string& name) {
    for (const Method& m : methods)
        if (m.problem == problem && m.name == name)
            return m;
    throw std::runtime_error("no method " + name);
}

/// Controlled reference: GSL QAG (Gauss-Kronrod 61) + Newton at 1e-14.
inline MethodOutput controlledReference(const MethodCase& c, const std::vector<double>& times) {
    QuadratureTimeLaw law(*c.curve, c.params, 1e-14, 61);
    MethodOutput o;
    for (double u : law.invert(times, o.work)) {
        CurvePoint p = c.curve->eval(u);
        o.x.push_back(p.x);
        o.y.push_back(p.y);
    }
    return o;
}

inline double maxDistance(const MethodOutput& a, const MethodOutput& b) {
    double err = 0;
    for (std::size_t i = 0; i < a.x.size(); ++i)
        err = std::max(err, std::hypot(a.x[i] - b.x[i], a.y[i] - b.y[i]));
    return err;
}

} // namespace chaplygin::test
