#include "motion/perturbed_motion.h"

#include "common/input_error.h"
#include "control/path_feedback.h"
#include "control/piece_control.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace chaplygin {

NominalControl::NominalControl(std::shared_ptr<const Path> path, TimeLaw timeLaw,
                               ControlParams params)
    : m_path(std::move(path)), m_timeLaw(std::move(timeLaw)), m_params(params) {}

ControlState NominalControl::at(double t, double* phi, double* x, double* y) const {
    const PathLocation loc = m_timeLaw.locate(t);
    const PathPiece& piece = m_path->pieces()[loc.piece];
    const PathNode n = piece.table->interpolatedAt(loc.panel, loc.xi);
    if (x)
        *x = n.x;
    if (y)
        *y = n.y;
    return controlOnPiece(m_params, piece, n, phi);
}

namespace {

enum Index { kX, kY, kPhi, kPsi, kU };

} // namespace

class PerturbedMotion::Problem final : public OdeProblem {
  public:
    Problem(Kind kind, std::shared_ptr<const NominalControl> nominal, PathFrame frame,
            const PerturbationSpec& spec)
        : m_kind(kind), m_nominal(std::move(nominal)), m_frame(std::move(frame)), m_spec(spec),
          m_sys(m_nominal->params().system), m_vT(m_nominal->params().speed) {}

    int dimension() const override { return m_kind == Kind::Feedback ? 5 : 4; }

    void rhs(double t, const double* y, double* f) const override {
        const double b = m_sys.b, a = m_sys.a;
        const double sdot = m_vT * std::sin(y[kPsi]), phidot = m_vT / b * std::cos(y[kPsi]);
        f[kX] = sdot * std::cos(y[kPhi]);
        f[kY] = sdot * std::sin(y[kPhi]);
        f[kPhi] = phidot;
        if (m_kind == Kind::OpenLoop) {
            // Psidot = lambda(t)/(m b) + (a/b) phidot with the nominal lambda(t)
            f[kPsi] = m_nominal->at(t).lambda / (m_sys.mass * b) + a / b * phidot;
            return;
        }
        const FeedbackLawValues v = feedback(y);
        f[kPsi] = psidot(v);
        f[kU] = v.sdotPath / v.closest.point.speed;
    }

    void jacobian(double, const double*, double*, double*) const override {
        throw std::logic_error("internal error: the perturbed bodies have no Jacobian");
    }

    FeedbackLawValues feedback(const double* y) const {
        const double b = m_sys.b, bc = m_spec.controllerB;
        const double sinPsi = std::sin(y[kPsi]), cosPsi = std::cos(y[kPsi]);
        const double sdot = m_vT * sinPsi;
        FeedbackLawValues v;
        v.closest = m_frame.project(y[kX], y[kY], y[kU]);
        const PathPoint& p = v.closest.point;
        v.theta = y[kPhi] - p.phi;
        v.kappaBody = cosPsi / (b * sinPsi); // phidot/sdot, measured
        PathError err;
        err.e = v.closest.e;
        err.theta = v.theta;
        err.kappaBody = v.kappaBody;
        err.kappa = p.kappa;
        err.dkappa = p.dkappa;
        err.ddkappa = p.ddkappa;
        v.sdotPath = sdot * std::cos(v.theta) / (1 - p.kappa * err.e);
        const ChainedForm z = chainedForm(err);
        v.z2 = z.z2;
        v.z3 = z.z3;
        v.z4 = z.z4;
        v.drift = z.drift;
        v.gain = z.gain;
        v.u = triplePoleInput(z, m_spec.rate);
        v.curvatureRate = curvatureRate(z, v.u);
        // the controller turns the rate into lambda with its own b; the plant's Psidot is then
        // (b_c/b) times the controller's (docs/physics.md §9)
        v.psidotAsked =
            bc / b * psiRateForCurvatureRate(bc, v.kappaBody, v.sdotPath, v.curvatureRate);
        v.saturated = m_spec.psiLimit && std::abs(v.psidotAsked) > *m_spec.psiLimit;
        return v;
    }

    // the Psidot applied: the law's, within the bound
    double psidot(const FeedbackLawValues& v) const {
        return m_spec.psiLimit ? std::clamp(v.psidotAsked, -*m_spec.psiLimit, *m_spec.psiLimit)
                               : v.psidotAsked;
    }

    // why the chained form no longer holds at this state, or empty
    std::string outsideDomain(const double* y) const {
        const FeedbackLawValues v = feedback(y);
        if (std::sin(y[kPsi]) <= 1e-3)
            return "Psi reaches " + formatNumber(y[kPsi]) + " rad: the body stops moving forward";
        if (std::cos(v.theta) <= 1e-3)
            return "the heading error reaches " + formatNumber(v.theta) + " rad (pi/2)";
        if (1 - v.closest.point.kappa * v.closest.e <= 1e-3)
            return "the body reaches the path's centre of curvature (1 - kappa e = 0)";
        if (!std::isfinite(v.psidotAsked))
            return "the feedback is not finite";
        return {};
    }

    PerturbedState state(double t, const double* y) const {
        const double b = m_sys.b, a = m_sys.a, m = m_sys.mass;
        PerturbedState s;
        s.x = y[kX];
        s.y = y[kY];
        s.phi = y[kPhi];
        s.psi = y[kPsi];
        s.sdot = m_vT * std::sin(s.psi);
        s.phidot = m_vT / b * std::cos(s.psi);
        s.energy = 0.5 * m * (s.sdot * s.sdot + b * b * s.phidot * s.phidot);
        if (m_kind == Kind::OpenLoop) {
            s.lambda = m_nominal->at(t).lambda;
            s.psidot = s.lambda / (m * b) + a / b * s.phidot;
            return s;
        }
        s.law = feedback(y);
        s.psidot = psidot(s.law);
        s.lambda = m * (b * s.psidot - a * s.phidot);
        s.error = s.law.closest.e;
        s.pathS = s.law.closest.point.s;
        return s;
    }

    // a push: Psi jumps, and P moves to the left of the heading
    void push(double* y) const {
        y[kPsi] += m_spec.pushPsi;
        y[kX] -= m_spec.pushDy * std::sin(y[kPhi]);
        y[kY] += m_spec.pushDy * std::cos(y[kPhi]);
        if (m_kind == Kind::Feedback)
            y[kU] = m_frame.project(y[kX], y[kY], y[kU]).point.u;
    }

    OdeValue start() const {
        double phi = 0, x = 0, y = 0;
        const ControlState c = m_nominal->at(0, &phi, &x, &y);
        OdeValue s{};
        s[kX] = x - m_spec.dy * std::sin(phi);
        s[kY] = y + m_spec.dy * std::cos(phi);
        s[kPhi] = phi + m_spec.dphi;
        s[kPsi] = c.psi + m_spec.dpsi;
        if (m_kind == Kind::Feedback)
            s[kU] = m_frame.project(s[kX], s[kY], m_frame.u0()).point.u;
        return s;
    }

    const PerturbationSpec& spec() const { return m_spec; }

  private:
    Kind m_kind;
    std::shared_ptr<const NominalControl> m_nominal;
    PathFrame m_frame;
    PerturbationSpec m_spec;
    DerivedSystem m_sys;
    double m_vT;
};

PerturbedMotion::PerturbedMotion(Kind kind, std::shared_ptr<const NominalControl> nominal,
                                 PathFrame frame, const PerturbationSpec& spec, double tEnd)
    : m_kind(kind),
      m_problem(std::make_shared<const Problem>(kind, std::move(nominal), std::move(frame), spec)) {
    const Problem& problem = *m_problem;
    const char* body = kind == Kind::Feedback ? "the feedback body" : "the open-loop body";
    // the last accepted step, and the step budget that bounds the work a scene may ask for
    double tLast = 0;
    long steps = 0;
    const auto check = [&](double t, const double* y) {
        tLast = t;
        if (++steps > kPerturbedStepBudget)
            throw InputError("perturbation",
                             std::string(body) + " needs more than " +
                                 std::to_string(kPerturbedStepBudget) +
                                 " steps of the integrator by t = " + formatNumber(t) + " s of " +
                                 formatNumber(tEnd) +
                                 " s: the path turns too tightly for its offsets; try a smaller "
                                 "offset or push, a smoother path or no perturbation");
        if (kind != Kind::Feedback)
            return;
        const std::string why = problem.outsideDomain(y);
        if (!why.empty())
            throw InputError("perturbation",
                             "the feedback body leaves the chained form's domain at t = " +
                                 formatNumber(t) + " s: " + why +
                                 " (docs/physics.md §9); try a smaller offset, a smaller "
                                 "feedback rate or no |Psidot| limit");
    };
    OdeValue y{};
    double t0 = 0;
    const auto run = [&](double t1) {
        Segment seg{t0, integrateGslSteps(problem, GslStepper::Rk8pd, t0, y.data(), t1,
                                          kPerturbedTolerance, check)};
        m_work.rhsEvals += seg.steps.work.rhsEvals;
        m_work.steps += seg.steps.work.steps;
        m_work.rejected += seg.steps.work.rejected;
        y = seg.steps.y.back();
        m_segments.push_back(std::move(seg));
    };
    try {
        y = problem.start();
        if (spec.tPush && *spec.tPush > 0) {
            run(*spec.tPush);
            t0 = *spec.tPush;
        }
        if (spec.tPush)
            problem.push(y.data());
        run(tEnd);
    } catch (const PathProjectionError&) {
        throw InputError(
            "perturbation",
            "the feedback body has no closest point on the path after t = " + formatNumber(tLast) +
                " s: it is farther from the path than the path's bends allow "
                "(docs/physics.md §9); try a smaller offset or push, or a smoother "
                "path");
    }
}

PerturbedState PerturbedMotion::at(double t) const {
    t = std::clamp(t, m_segments.front().t0, m_segments.back().steps.t.back());
    auto it = std::find_if(m_segments.rbegin(), m_segments.rend(),
                           [t](const Segment& s) { return s.t0 <= t; });
    const Segment& seg = it == m_segments.rend() ? m_segments.front() : *it;
    OdeValue y{};
    gslStepFrom(*m_problem, GslStepper::Rk8pd, seg.steps, t, y.data());
    return m_problem->state(t, y.data());
}

std::vector<TrailKnot> PerturbedMotion::trailKnots() const {
    std::vector<TrailKnot> out;
    for (const Segment& seg : m_segments)
        for (std::size_t i = 0; i < seg.steps.t.size(); ++i) {
            const OdeValue& y = seg.steps.y[i];
            const OdeValue& f = seg.steps.f[i];
            out.push_back({seg.steps.t[i], y[kX], y[kY], f[kX], f[kY]});
        }
    return out;
}

std::string PerturbedMotion::model() const {
    const PerturbationSpec& s = m_problem->spec();
    std::string out = "GSL rk8pd at tolerance " + formatNumber(kPerturbedTolerance) +
                      " (abs = rel) on x, y, phi, Psi";
    if (m_kind == Kind::OpenLoop)
        out += ", the nominal lambda(t) as the input (open loop)";
    else {
        out += " and the closest point's u; chained-form feedback (De Luca, Oriolo, Samson "
               "1998) with a triple pole at -" +
               formatNumber(s.rate) +
               " 1/m in path length, controller b = " + formatNumber(s.controllerB) + " m";
        if (s.psiLimit)
            out += ", |Psidot| <= " + formatNumber(*s.psiLimit) + " rad/s";
        out += "; closest point by Newton on the path table's interpolants";
    }
    if (s.tPush)
        out += "; restarted after the push at t = " + formatNumber(*s.tPush) + " s";
    out += "; between steps one rk8pd step from the last accepted one";
    return out;
}

} // namespace chaplygin
