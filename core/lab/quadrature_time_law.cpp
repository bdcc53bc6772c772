#include "lab/quadrature_time_law.h"

#include "numerics/gsl_callback.h"
#include "numerics/safeguarded_newton.h"

#include <gsl/gsl_integration.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace chaplygin {
namespace {

constexpr std::size_t kLimit = 1000;

// Converged at a step below 1e-15 of 1 + |u| (u is the path's own parameter) or when the bracket
// has closed; Newton steps onto the bracket's ends are taken, since the root may be u1 itself. 100
// iterations are a bound: Newton from the previous output's rate takes a few.
constexpr NewtonCaps kInversionCaps{.maxIterations = 100,
                                    .takenStep = {.value = 1e-15, .relativeToX = true, .scale = 1},
                                    .bracket = {.value = 0},
                                    .closedBracket = true};

struct WorkspaceDeleter {
    void operator()(gsl_integration_workspace* w) const { gsl_integration_workspace_free(w); }
};
using WorkspacePtr = std::unique_ptr<gsl_integration_workspace, WorkspaceDeleter>;

} // namespace

QuadratureTimeLaw::QuadratureTimeLaw(const Curve& curve, const ControlParams& params,
                                     double tolerance, int rule)
    : m_curve(curve), m_params(params), m_tolerance(tolerance) {
    switch (rule) {
    case 15:
        m_key = GSL_INTEG_GAUSS15;
        break;
    case 31:
        m_key = GSL_INTEG_GAUSS31;
        break;
    case 41:
        m_key = GSL_INTEG_GAUSS41;
        break;
    case 51:
        m_key = GSL_INTEG_GAUSS51;
        break;
    case 61:
        m_key = GSL_INTEG_GAUSS61;
        break;
    default:
        m_key = GSL_INTEG_GAUSS21;
    }
}

double QuadratureTimeLaw::rate(double u) const {
    CurveGeometry g = geometryOf(m_curve.eval(u));
    if (m_params.mode == SpeedMode::Speed)
        return g.speed / m_params.speed;
    // dt/ds = sqrt(1 + b^2 kappa^2)/v_T
    const double bk = m_params.system.b * g.kappa;
    return g.speed * std::sqrt(1 + bk * bk) / m_params.speed;
}

std::vector<double> QuadratureTimeLaw::invert(const std::vector<double>& times,
                                              OdeWork& work) const {
    WorkspacePtr ws(gsl_integration_workspace_alloc(kLimit));
    if (!ws)
        throw std::runtime_error("gsl_integration_workspace_alloc failed");
    gsl::ensureErrorHandlerOff();
    auto integrand = [this](double u) { return rate(u); };
    gsl::FunctionAdapter<decltype(integrand)> adapter{&integrand, &work.rhsEvals};
    gsl_function fn = adapter.function();
    const double span = m_curve.u1() - m_curve.u0();
    // \int_{u0}^{u1} dt/du du, error share proportional to the stretch of the path
    auto integral = [&](double from, double to) {
        double result = 0, abserr = 0;
        if (std::fabs(to - from) <= 1e-6 * span) {
            // a Newton correction: one Gauss-Kronrod 21 panel is exact to rounding here (its
            // error is O(h^42) in the panel width); QAG would subdivide below rounding
            double resabs = 0, resasc = 0;
            gsl_integration_qk21(&fn, from, to, &result, &abserr, &resabs, &resasc);
            return result;
        }
        double epsabs = std::max(m_tolerance * std::fabs(to - from) / span, 1e-300);
        int status = gsl_integration_qag(&fn, from, to, epsabs, m_tolerance, kLimit, m_key,
                                         ws.get(), &result, &abserr);
        if (status != GSL_SUCCESS && status != GSL_EROUND)
            throw std::runtime_error(std::string("gsl_integration_qag: ") + gsl_strerror(status));
        return result;
    };
    std::vector<double> out;
    out.reserve(times.size());
    double uPrev = m_curve.u0(), tPrev = 0;
    for (double target : times) {
        // Newton on t(u) = target with dt/du exact, safeguarded by bisection on [uPrev, u1]; t is
        // carried from point to point by the integral over each step
        double rPrev = rate(uPrev);
        ++work.rhsEvals;
        const double u0 = std::min(uPrev + (target - tPrev) / rPrev, m_curve.u1());
        double tAt = tPrev, from = uPrev;
        auto timeAt = [&](double u) {
            tAt += integral(from, u);
            from = u;
            ++work.steps;
            ++work.rhsEvals;
            return NewtonValue{tAt - target, rate(u)};
        };
        const double u = safeguardedNewton(timeAt, u0, {uPrev, m_curve.u1()}, kInversionCaps).x;
        tAt += integral(from, u);
        out.push_back(u);
        uPrev = u;
        tPrev = tAt;
    }
    return out;
}

} // namespace chaplygin
