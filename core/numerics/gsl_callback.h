#pragma once
// The one adapter of GSL's C callbacks to C++ callables and OdeProblems (the only void*), and
// GSL's error handler switched off, and a special function's result checked.
#include "numerics/ode_problem.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_sf_result.h>

#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>

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

/// An exception thrown by the problem does not unwind through GSL's C frames: it is kept, GSL is
/// told the function failed, and the caller rethrows it once GSL has returned.
struct OdeAdapter {
    const OdeProblem* problem;
    OdeWork* work;
    std::exception_ptr error = nullptr;
    static int rhs(double t, const double y[], double f[], void* self) {
        auto* a = static_cast<OdeAdapter*>(self);
        ++a->work->rhsEvals;
        try {
            a->problem->rhs(t, y, f);
        } catch (...) {
            a->error = std::current_exception();
            return GSL_EBADFUNC;
        }
        return GSL_SUCCESS;
    }
    static int jacobian(double t, const double y[], double* dfdy, double dfdt[], void* self) {
        auto* a = static_cast<OdeAdapter*>(self);
        ++a->work->jacobianEvals;
        try {
            a->problem->jacobian(t, y, dfdy, dfdt);
        } catch (...) {
            a->error = std::current_exception();
            return GSL_EBADFUNC;
        }
        return GSL_SUCCESS;
    }
    /// After a GSL call that failed: the problem's own exception, if it threw one.
    void rethrowProblemError() {
        if (error)
            std::rethrow_exception(std::exchange(error, nullptr));
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

/// The value of a GSL special function's result, read after its status: throws
/// std::runtime_error naming `what` when the call failed or gave a non-finite value.
inline double checkedResult(int status, const gsl_sf_result& r, const char* what) {
    const double value = r.val;
    if (status != GSL_SUCCESS || !std::isfinite(value))
        throw std::runtime_error(std::string("internal error: GSL ") + what + " failed (" +
                                 gsl_strerror(status) + ")");
    return value;
}

} // namespace chaplygin::gsl
