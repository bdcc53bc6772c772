#pragma once
// The one adapter of GSL's C callbacks to C++ callables and OdeProblems (the only void*), and
// GSL's error handler switched off.
#include "numerics/ode_problem.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>

namespace chaplygin::gsl {

/// The single GSL callback adapter: the only place where void* appears. It forwards GSL's C
/// callbacks to a C++ callable (gsl_function) or an OdeProblem (gsl_odeiv2_system), counting
/// the calls.
template <class F> struct FunctionAdapter {
    F* f;
    long* calls;
    static double call(double x, void* self) {
        auto* a = static_cast<FunctionAdapter*>(self);
        ++*a->calls;
        return (*a->f)(x);
    }
    gsl_function function() { return gsl_function{&FunctionAdapter::call, this}; }
};

struct OdeAdapter {
    const OdeProblem* problem;
    OdeWork* work;
    static int rhs(double t, const double y[], double f[], void* self) {
        auto* a = static_cast<OdeAdapter*>(self);
        ++a->work->rhsEvals;
        a->problem->rhs(t, y, f);
        return GSL_SUCCESS;
    }
    static int jacobian(double t, const double y[], double* dfdy, double dfdt[], void* self) {
        auto* a = static_cast<OdeAdapter*>(self);
        ++a->work->jacobianEvals;
        a->problem->jacobian(t, y, dfdy, dfdt);
        return GSL_SUCCESS;
    }
};

/// GSL's default error handler aborts the process. It is switched off once, process-wide, on
/// first use, and every GSL call here checks its return code instead. A scoped save and restore
/// would race between threads (the GUI runs sweeps in a worker).
inline void ensureErrorHandlerOff() {
    static const bool off = [] {
        gsl_set_error_handler_off();
        return true;
    }();
    (void)off;
}

} // namespace chaplygin::gsl
