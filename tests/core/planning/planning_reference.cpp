#include "planning_reference.h"

#include "lab/vakonomic_problem.h"
#include "motion/vakonomic_motion.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>
#include <gsl/gsl_odeiv2.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

namespace chaplygin::test {
namespace {

using std::numbers::pi;

int odeRhs(double t, const double y[], double f[], void* p) {
    static_cast<const VakonomicProblem*>(p)->rhs(t, y, f);
    return GSL_SUCCESS;
}

double wrap(double a) {
    return std::remainder(a, 2 * pi);
}

struct ShootingTarget {
    double X, Y, Phi;
};

int shootingResidual(const gsl_vector* v, void* p, gsl_vector* f) {
    const auto* tg = static_cast<const ShootingTarget*>(p);
    const double psi0 = gsl_vector_get(v, 0), lambda0 = gsl_vector_get(v, 1);
    const Pose end = unitEnd(psi0, lambda0, gsl_vector_get(v, 2));
    gsl_vector_set(f, 0, end.x - tg->X);
    gsl_vector_set(f, 1, end.y - tg->Y);
    gsl_vector_set(f, 2, wrap(end.phi - tg->Phi));
    return GSL_SUCCESS;
}

} // namespace

Pose unitEnd(double psi0, double lambda0, double t) {
    DerivedSystem unit;
    unit.mass = unit.translatingMass = 1;
    unit.a = 0;
    unit.b = 1;
    VakonomicInitial init;
    init.sdot = std::sin(psi0);
    init.phidot = std::cos(psi0);
    init.lambda = lambda0;
    const VakonomicState s = VakonomicMotion(unit, init).at(t);
    return {s.x, s.y, s.phi};
}

Pose integratedEnd(const DerivedSystem& system, double vT, const Pose& from, double psi0,
                   double lambda0, double t) {
    gsl_set_error_handler_off();
    VakonomicProblem problem(system);
    gsl_odeiv2_system ode{odeRhs, nullptr, 6, &problem};
    gsl_odeiv2_driver* d =
        gsl_odeiv2_driver_alloc_y_new(&ode, gsl_odeiv2_step_rk8pd, 1e-3, 1e-13, 1e-13);
    const double phidot0 = vT * std::cos(psi0) / system.b;
    // y[5] = lambda_c/m = lambda/m + a phidot
    double y[6] = {from.x,   from.y,
                   from.phi, vT * std::sin(psi0),
                   phidot0,  lambda0 / system.mass + system.a * phidot0};
    double t0 = 0;
    const int status = t > 0 ? gsl_odeiv2_driver_apply(d, &t0, t, y) : GSL_SUCCESS;
    gsl_odeiv2_driver_free(d);
    if (status != GSL_SUCCESS)
        throw std::runtime_error("rk8pd failed");
    return {y[0], y[1], y[2]};
}

double poseError(const Pose& a, const Pose& b, double length) {
    return std::fabs(a.x - b.x) / length + std::fabs(a.y - b.y) / length +
           std::fabs(wrap(a.phi - b.phi));
}

std::vector<ShootingResult> motionsByShooting(double X, double Y, double Phi, double tMax,
                                              int starts, unsigned seed) {
    gsl_set_error_handler_off();
    ShootingTarget tg{X, Y, Phi};
    gsl_multiroot_function f{shootingResidual, 3, &tg};
    gsl_multiroot_fsolver* s = gsl_multiroot_fsolver_alloc(gsl_multiroot_fsolver_hybrids, 3);
    gsl_vector* x = gsl_vector_alloc(3);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    const double d = std::hypot(X, Y);
    std::vector<ShootingResult> found;
    for (int i = 0; i < starts; ++i) {
        gsl_vector_set(x, 0, -pi + 2 * pi * unit(rng));
        gsl_vector_set(x, 1, 2 * std::sinh(3 * unit(rng) - 1.5));
        gsl_vector_set(x, 2, d + (tMax - d) * unit(rng));
        gsl_multiroot_fsolver_set(s, &f, x);
        int status = GSL_CONTINUE;
        for (int iter = 0; iter < 200 && status == GSL_CONTINUE; ++iter) {
            if (gsl_multiroot_fsolver_iterate(s))
                break;
            status = gsl_multiroot_test_residual(s->f, 1e-12);
        }
        ShootingResult r;
        r.t = gsl_vector_get(s->x, 2);
        r.psi0 = wrap(gsl_vector_get(s->x, 0));
        r.psidot0 = gsl_vector_get(s->x, 1);
        if (status != GSL_SUCCESS || !(r.t > 0) || r.t > tMax)
            continue;
        bool known = false;
        for (ShootingResult& k : found)
            if (std::fabs(k.t - r.t) < 1e-8 && std::fabs(wrap(k.psi0 - r.psi0)) < 1e-6 &&
                std::fabs(k.psidot0 - r.psidot0) < 1e-6) {
                ++k.converged;
                known = true;
            }
        if (!known) {
            r.converged = 1;
            found.push_back(r);
        }
    }
    gsl_vector_free(x);
    gsl_multiroot_fsolver_free(s);
    return found;
}

ShootingResult leastTimeByShooting(double X, double Y, double Phi, int starts, unsigned seed) {
    ShootingResult best;
    best.t = std::numeric_limits<double>::infinity();
    const double upper = std::hypot(X, Y) + 1.5 * pi;
    for (const ShootingResult& r : motionsByShooting(X, Y, Phi, upper, starts, seed)) {
        best.converged += r.converged;
        if (r.t < best.t) {
            best.t = r.t;
            best.psi0 = r.psi0;
            best.psidot0 = r.psidot0;
        }
    }
    return best;
}

} // namespace chaplygin::test
