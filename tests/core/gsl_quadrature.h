#pragma once
// GSL's adaptive quadrature, the independent reference for integrals in the core tests.
#include <gsl/gsl_integration.h>

#include <cstddef>
#include <functional>

namespace chaplygin::test {

enum class GslRule {
    GaussKronrod21, ///< gsl_integration_qag with the 21-point rule
    GaussKronrod61, ///< gsl_integration_qag with the 61-point rule
    Extrapolating,  ///< gsl_integration_qags (handles integrable end-point singularities)
};

/// \int_a^b f to GSL's tolerances epsabs and epsrel, with at most `limit` subintervals.
inline double gslIntegral(const std::function<double(double)>& f, double a, double b, double epsabs,
                          double epsrel, GslRule rule, std::size_t limit) {
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(limit);
    gsl_function g;
    g.function = [](double x, void* p) {
        return (*static_cast<const std::function<double(double)>*>(p))(x);
    };
    g.params = const_cast<std::function<double(double)>*>(&f);
    double result = 0, err = 0;
    if (rule == GslRule::Extrapolating)
        gsl_integration_qags(&g, a, b, epsabs, epsrel, limit, w, &result, &err);
    else
        gsl_integration_qag(&g, a, b, epsabs, epsrel, limit,
                            rule == GslRule::GaussKronrod21 ? GSL_INTEG_GAUSS21 : GSL_INTEG_GAUSS61,
                            w, &result, &err);
    gsl_integration_workspace_free(w);
    return result;
}

} // namespace chaplygin::test
