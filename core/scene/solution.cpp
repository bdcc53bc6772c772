#include "scene/solution.h"

#include "common/input_error.h"
#include "control/piece_control.h"
#include "numerics/chebyshev.h"
#include "planning/scene_path.h"
#include "scene/finite_results.h"
#include "scene/perturbation.h"
#include "systems/system_parameters.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace chaplygin {
namespace {

FreeInitial initialState(const std::shared_ptr<const Path>& path, const ControlParams& params) {
    FreeInitial init;
    const PathPiece& first = path->pieces().front();
    PathNode n = path->start();
    init.x = n.x;
    init.y = n.y;
    init.phi = n.phi;
    ControlState c = first.kind == PathPiece::Kind::Pivot
                         ? controlAtPivot(params, n.phi, first.phiTo - first.phiFrom)
                         : controlOnPiece(params, first, first.table->nodes().front());
    init.sdot = c.sdot;
    init.phidot = c.phidot;
    return init;
}

// the free body's state and the tracking's lambda(0), the vakonomic system's only free constant
VakonomicInitial vakonomicInitial(const std::shared_ptr<const Path>& path,
                                  const ControlParams& params) {
    FreeInitial f = initialState(path, params);
    const PathPiece& first = path->pieces().front();
    PathNode n = path->start();
    ControlState c = first.kind == PathPiece::Kind::Pivot
                         ? controlAtPivot(params, n.phi, first.phiTo - first.phiFrom)
                         : controlOnPiece(params, first, first.table->nodes().front());
    return {f.x, f.y, f.phi, f.sdot, f.phidot, c.lambda};
}

double horizonOf(const Scene& scene, double duration) {
    if (!scene.tEnd)
        return duration;
    double t = *scene.tEnd;
    if (!std::isfinite(t) || !(t > 0))
        throw InputError("t_end", "must be a finite number > 0, got " + formatNumber(t));
    if (t > duration * (1 + 1e-12))
        throw InputError("t_end", formatNumber(t) +
                                      " s is beyond the end of the path, which the body "
                                      "reaches at t = " +
                                      formatNumber(duration) + " s");
    return std::min(t, duration);
}

// what the path table interpolates, and to what bound
std::string interpolationModel(const Path& path) {
    PathTable::Bounds b;
    bool interpolated = false, closed = false;
    int lowDegree = 0, panels = 0;
    for (const PathPiece& p : path.pieces()) {
        if (p.kind != PathPiece::Kind::Curve)
            continue;
        const PathTable::Bounds& t = p.table->bounds();
        interpolated = interpolated || !p.table->chebPanels().empty();
        for (const PathTable::ChebPanel& c : p.table->chebPanels()) {
            lowDegree += c.certified && c.degree == cheb::kLowDegree ? 1 : 0;
            ++panels;
        }
        closed = closed || p.table->uniform();
        b.position = std::max(b.position, t.position);
        b.kappa = std::max(b.kappa, t.kappa);
        b.dkappa = std::max(b.dkappa, t.dkappa);
        b.exactPanels += t.exactPanels;
    }
    std::string out;
    if (closed)
        out += "; lines and circles: closed-form geometry";
    if (interpolated) {
        out += "; x, y, phi, kappa, dkappa/ds, s interpolated per panel (Chebyshev, degree 8 on " +
               std::to_string(lowDegree) + " of " + std::to_string(panels) +
               " panels, else 16; bounds: position " + formatNumber(b.position) + " m, kappa " +
               formatNumber(b.kappa) + " 1/m, dkappa/ds " + formatNumber(b.dkappa) + " 1/m^2)";
        if (b.exactPanels > 0)
            out += ", exact evaluation on " + std::to_string(b.exactPanels) + " panel(s)";
    }
    return out;
}

// the scene's perturbation checked against its path, mode and horizon (docs/physics.md §9)
PerturbationSpec perturbationSpec(const Perturbation& p, const Path& path,
                                  const ControlParams& params, double tEnd) {
    if (params.mode != SpeedMode::Energy)
        throw InputError("perturbation", "perturbations need constant-energy mode");
    if (path.pieces().size() != 1 || path.pieces().front().kind != PathPiece::Kind::Curve ||
        path.pieces().front().direction != 1)
        throw InputError("perturbation",
                         "perturbations need a smooth path without corners or cusps");
    checkPerturbation(p);
    if (p.tPush && !(*p.tPush < tEnd))
        throw InputError("perturbation t_push",
                         formatNumber(*p.tPush) +
                             " s is not before the horizon t_end = " + formatNumber(tEnd) + " s");
    const PathNode n = path.start();
    const double psi0 = controlOnCurve(params, n.kappa, n.dkappa, n.phi).psi;
    if (!(psi0 + p.dpsi > 0 && psi0 + p.dpsi < std::numbers::pi))
        throw InputError("perturbation dpsi",
                         "Psi(0) + dpsi = " + formatNumber(psi0 + p.dpsi) +
                             " rad leaves (0, pi): the body would not move forward");
    PerturbationSpec spec;
    spec.dy = p.dy;
    spec.dphi = p.dphi;
    spec.dpsi = p.dpsi;
    spec.tPush = p.tPush;
    spec.pushPsi = p.pushPsi;
    spec.pushDy = p.pushDy;
    spec.rate = p.feedbackRate;
    spec.psiLimit = p.feedbackLimit;
    spec.controllerB = p.controllerB.value_or(params.system.b);
    return spec;
}

} // namespace

ControlParams controlParamsOf(const Scene& scene) {
    return controlParamsOf(scene, deriveSystem(scene.system));
}

ControlParams controlParamsOf(const Scene& scene, const DerivedSystem& system) {
    ControlParams p;
    p.system = system;
    p.mode = scene.mode;
    p.speed = scene.speed;
    return p;
}

Solution Solution::compute(const Scene& scene) {
    ControlParams params = controlParamsOf(scene); // parameters first: cheaper to reject
    Solution solution(scene, buildScenePath(scene.path), params);
    requireFiniteSolution(solution); // nothing non-finite reaches a view or a file
    return solution;
}

Solution Solution::compute(const Scene& scene, std::shared_ptr<const Path> path) {
    return compute(scene, std::move(path), deriveSystem(scene.system));
}

Solution Solution::compute(const Scene& scene, std::shared_ptr<const Path> path,
                           const DerivedSystem& system) {
    Solution solution(scene, std::move(path), controlParamsOf(scene, system));
    requireFiniteSolution(solution); // nothing non-finite reaches a view or a file
    return solution;
}

Solution::Solution(const Scene& scene, std::shared_ptr<const Path> path,
                   const ControlParams& params)
    : m_scene(scene), m_path(std::move(path)), m_params(params), m_timeLaw(m_path, params),
      m_free(params.system, initialState(m_path, params), horizonOf(scene, m_timeLaw.duration())),
      m_vak(params.system, vakonomicInitial(m_path, params)),
      m_tEnd(horizonOf(scene, m_timeLaw.duration())) {
    std::size_t panels = 0;
    for (const PathPiece& p : m_path->pieces())
        if (p.kind == PathPiece::Kind::Curve)
            panels += p.table->panels().size();
    m_models.path = "tabulated once: " + std::to_string(panels) +
                    " adaptive 8-point Gauss panels, curvature from exact derivatives";
    if (int pivots = m_path->pivotCount())
        m_models.path += ", " + std::to_string(pivots) + " pivot corner(s)";
    m_models.path += interpolationModel(*m_path);
    if (params.mode == SpeedMode::Speed) {
        m_models.timeLaw = TRANSLATABLE_TEXT("ModelReport", "closed form (t = s/v_s)");
        m_models.inversion = m_timeLaw.closedForm()
                                 ? TRANSLATABLE_TEXT("ModelReport", "closed form")
                                 : TRANSLATABLE_TEXT("ModelReport", "Newton on s(u)");
    } else if (m_timeLaw.closedForm()) {
        m_models.timeLaw = TRANSLATABLE_TEXT(
            "ModelReport", "closed form (constant curvature: t = s sqrt(1 + b^2 kappa^2)/v_T)");
        m_models.inversion = TRANSLATABLE_TEXT("ModelReport", "closed form");
    } else {
        m_models.timeLaw = TRANSLATABLE_TEXT(
            "ModelReport", "quadrature (Gauss-Legendre of sqrt(1 + b^2 kappa^2)/v_T ds)");
        m_models.inversion =
            TRANSLATABLE_TEXT("ModelReport", "Newton on t(s) with the exact dt/ds");
    }
    if (!m_timeLaw.closedForm() && m_timeLaw.interpolated(0) && m_path->pieces().size() == 1) {
        m_models.timeLaw = TRANSLATABLE_TEXT(
            "ModelReport", "quadrature (Gauss-Legendre of sqrt(1 + b^2 kappa^2)/v_T ds) at the "
                           "panel ends; inside a panel the integral of the Chebyshev "
                           "interpolant of dt/du at the panel's degree, certified to 1e-13 of the "
                           "panel's time on first use (exact Gauss-Legendre where it fails)");
        m_models.inversion = TRANSLATABLE_TEXT(
            "ModelReport", "Newton on the interpolated t(u) from a quintic Hermite start");
    }
    m_models.control = TRANSLATABLE_TEXT(
        "ModelReport", "closed form in kappa, dkappa/ds and phi (Psi = atan2(1, b kappa))");
    int cusps = 0;
    for (const PathPiece& p : m_path->pieces())
        cusps += p.kind == PathPiece::Kind::Curve && p.table->cuspEnds().end ? 1 : 0;
    if (cusps > 0)
        m_models.control += "; through " + std::to_string(cusps) +
                            " cusp(s): backing up between them (sdot < 0, Psi = atan2(sdot, b "
                            "phidot) continued), the limits sdot = 0, |phidot| = v_T/b at each";
    m_models.freeVelocity = m_free.velocityModel();
    m_models.freePosition = m_free.positionModel();
    m_models.vakonomic = m_vak.model();
    if (scene.perturbation) {
        const PerturbationSpec spec =
            perturbationSpec(*scene.perturbation, *m_path, params, m_tEnd);
        const PathPiece& piece = m_path->pieces().front();
        auto nominal = std::make_shared<const NominalControl>(m_path, m_timeLaw, params);
        m_frame = std::make_shared<const PathFrame>(piece.table, piece.phiOffset);
        const PathFrame& frame = *m_frame;
        m_open = std::make_shared<const PerturbedMotion>(PerturbedMotion::Kind::OpenLoop, nominal,
                                                         frame, spec, m_tEnd);
        m_feedback = std::make_shared<const PerturbedMotion>(PerturbedMotion::Kind::Feedback,
                                                             nominal, frame, spec, m_tEnd);
        m_models.perturbed = m_open->model();
        m_models.feedback = m_feedback->model();
    }
}

void Solution::pivotAt(const PathPiece& piece, double t, double sinceStart,
                       MotionSample& out) const {
    // pivot about P at |phidot| = v_T/b (docs/physics.md §3)
    double turn = piece.phiTo - piece.phiFrom;
    double rate = m_params.speed / m_params.system.b;
    out.t = t;
    out.s = piece.s0;
    out.x = piece.x;
    out.y = piece.y;
    out.phi = piece.phiFrom + std::copysign(std::min(rate * sinceStart, std::fabs(turn)), turn);
    out.kappa = std::copysign(INFINITY, turn);
    out.control = controlAtPivot(m_params, out.phi, turn);
}

void Solution::controlledAt(double t, MotionSample& out) const {
    PathLocation loc = m_timeLaw.locate(t);
    const PathPiece& piece = m_path->pieces()[loc.piece];
    out.t = t;
    if (piece.kind == PathPiece::Kind::Pivot) {
        pivotAt(piece, t, loc.sincePivotStart, out);
        return;
    }
    PathNode n = piece.table->interpolatedAt(loc.panel, loc.xi);
    out.s = piece.s0 + n.s;
    out.x = n.x;
    out.y = n.y;
    out.kappa = piece.direction * n.kappa;
    out.control = controlOnPiece(m_params, piece, n, &out.phi);
}

std::vector<TrackingError> Solution::trackingErrors(const std::vector<double>& times) const {
    std::vector<TrackingError> out;
    if (!m_frame)
        return out;
    out.reserve(times.size());
    // Newton from the previous closest point; a lost projection restarts from the path's start
    double uOpen = m_frame->u0(), uFb = m_frame->u0();
    auto error = [&](const PerturbedState& b, double& u, double& e, double& theta) {
        try {
            const PathProjection p = m_frame->project(b.x, b.y, u);
            u = p.point.u;
            e = p.e;
            theta = std::remainder(b.phi - p.point.phi, 2 * std::numbers::pi);
        } catch (const std::runtime_error&) {
            u = m_frame->u0();
            e = theta = std::numeric_limits<double>::quiet_NaN();
        }
    };
    for (double t : times) {
        TrackingError r;
        r.t = t;
        error(m_open->at(t), uOpen, r.openE, r.openTheta);
        error(m_feedback->at(t), uFb, r.fbE, r.fbTheta);
        out.push_back(r);
    }
    return out;
}

MotionSample Solution::at(double t, const MotionParts& parts) const {
    MotionSample m;
    m.t = t;
    if (parts.controlled)
        controlledAt(t, m);
    if (parts.free)
        m.free = m_free.at(t);
    if (parts.vakonomic)
        m.vak = m_vak.at(t);
    if (m_open && parts.perturbed) {
        m.perturbed = true;
        m.pert = m_open->at(t);
        m.fb = m_feedback->at(t);
    }
    return m;
}

std::vector<MotionSample> Solution::sample(int count) const {
    count = std::max(count, 2);
    std::vector<double> times(count);
    for (int i = 0; i < count; ++i)
        times[i] = i + 1 == count ? m_tEnd : m_tEnd * i / (count - 1);
    return sampleAt(times);
}

std::vector<MotionSample> Solution::sampleAt(const std::vector<double>& times) const {
    std::vector<MotionSample> out;
    out.reserve(times.size());
    for (double t : times)
        out.push_back(at(t));
    return out;
}

std::vector<MotionSample> Solution::controlledAtNodes() const {
    std::vector<MotionSample> out;
    const auto& pieces = m_path->pieces();
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const PathPiece& piece = pieces[k];
        if (piece.kind == PathPiece::Kind::Pivot) {
            // both ends of the turn with the pivot's own state: Psi, chi and lambda are flat
            // during the turn and jump at its ends (the impulsive control)
            double t0 = m_timeLaw.pieceStart(k), t1 = m_timeLaw.pieceStart(k + 1);
            for (double t : {t0, t1}) {
                if (t > m_tEnd)
                    break;
                MotionSample m;
                pivotAt(piece, t, t - t0, m);
                out.push_back(m);
            }
            continue;
        }
        const auto& nodes = piece.table->nodes();
        const auto& times = m_timeLaw.nodeTimes(k);
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            if (times[i] > m_tEnd)
                break;
            MotionSample m;
            m.t = times[i];
            m.s = piece.s0 + nodes[i].s;
            m.x = nodes[i].x;
            m.y = nodes[i].y;
            m.kappa = piece.direction * nodes[i].kappa;
            m.control = controlOnPiece(m_params, piece, nodes[i], &m.phi);
            out.push_back(m);
        }
    }
    return out;
}

} // namespace chaplygin
