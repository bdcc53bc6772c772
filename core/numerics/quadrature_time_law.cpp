#include "numerics/quadrature_time_law.h"

#include "numerics/gsl_callback.h"

#include <gsl/gsl_integration.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace chaplygin {
namespace {

constexpr std::size_t kLimit = 1000;

struct WorkspaceDeleter {
    void operator()(gsl_integration_workspace* w) const { gsl_integration_workspace_free(w); }
};
using WorkspacePtr = std::unique_ptr<gsl_integration_workspace, WorkspaceDeleter>;

} // namespace

QuadratureTimeLaw::QuadratureTimeLaw(const Curve& curve, const ControlParams& params, double tolerance)
    : m_curve(curve), m_params(params), m_tolerance(tolerance) {}

double QuadratureTimeLaw::rate(double u) const {
    CurveGeometry g = geometryOf(m_curve.eval(u));
    if (m_params.mode == SpeedMode::Speed)
        return g.speed / m_params.speed;
    // dt/ds = sqrt(1 + b^2 kappa^2)/v_T
    const double bk = m_params.system.b * g.kappa;
    return g.speed * std::sqrt(1 + bk * bk) / m_params.speed;
}

std::vector<double> QuadratureTimeLaw::invert(const std::vector<double>& times, OdeWork& work) const {
    WorkspacePtr ws(gsl_integration_workspace_alloc(kLimit));
    if (!ws)
        throw std::runtime_error("gsl_integration_workspace_alloc failed");
    gsl::ErrorHandlerOff quiet;
    auto integrand = [this](double u) { return rate(u); };
    gsl::FunctionAdapter<decltype(integrand)> adapter{&integrand, &work.rhsEvals};
    gsl_function fn = adapter.function();
    const double span = m_curve.u1() - m_curve.u0();
    // \int_{u0}^{u1} dt/du du, error share proportional to the stretch of the path
    auto integral = [&](double from, double to) {
        double result = 0, abserr = 0;
        double epsabs = std::max(m_tolerance * std::fabs(to - from) / span, 1e-300);
        int status = gsl_integration_qag(&fn, from, to, epsabs, m_tolerance, kLimit, GSL_INTEG_GAUSS21,
                                         ws.get(), &result, &abserr);
        if (status != GSL_SUCCESS && status != GSL_EROUND)
            throw std::runtime_error(std::string("gsl_integration_qag: ") + gsl_strerror(status));
        return result;
    };
    std::vector<double> out;
    out.reserve(times.size());
    double uPrev = m_curve.u0(), tPrev = 0;
    for (double target : times) {
        double rPrev = rate(uPrev);
        ++work.rhsEvals;
        double u = uPrev + (target - tPrev) / rPrev;
        double tAt = tPrev + integral(uPrev, u);
        for (int iter = 0; iter < 50; ++iter) {
            // Newton on t(u) = target with dt/du exact
            double r = rate(u);
            ++work.rhsEvals;
            double delta = (tAt - target) / r;
            double next = u - delta;
            tAt += integral(u, next);
            u = next;
            ++work.steps;
            if (std::fabs(delta) <= 1e-15 * (1 + std::fabs(u)))
                break;
        }
        out.push_back(u);
        uPrev = u;
        tPrev = tAt;
    }
    return out;
}

} // namespace chaplygin
