#include "canvas/plan_tool.h"

#include "canvas/body_painter.h"
#include "canvas/canvas_style.h"
#include "canvas/canvas_view.h"
#include "common/input_error.h"
#include "document/scene_document.h"
#include "motion/free_motion.h"
#include "motion/vakonomic_motion.h"
#include "planning/plan_track.h"
#include "scene/scene_plan.h"

#include <QElapsedTimer>
#include <QFontMetricsF>
#include <QLineF>
#include <QLocale>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWidget>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>
#include <exception>
#include <numbers>
#include <optional>
#include <utility>

namespace chaplygin::ui {

namespace {

constexpr double kHeadingHandlePx = 48; // from the target's position to its heading's handle
constexpr double kSnapAngle = std::numbers::pi / 12;

double distanceToSegment(QPointF p, QPointF a, QPointF b) {
    const QPointF ab = b - a, ap = p - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(ap, ab) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(ap.x() - t * ab.x(), ap.y() - t * ab.y());
}

QString timeLabel(double t) {
    return PlanTool::tr("%1 s").arg(QLocale().toString(t, 'f', t < 10 ? 2 : 1));
}

} // namespace

PlanTool::PlanTool(const CanvasView& view, const CanvasStyle& style, SceneDocument* document,
                   QObject* parent)
    : CanvasTool(parent), m_view(view), m_style(style), m_document(document) {
    connect(&m_planWatcher, &QFutureWatcherBase::finished, this, &PlanTool::takeBackgroundPlan);
    m_playTimer.setInterval(16);
    connect(&m_playTimer, &QTimer::timeout, this, [this] {
        const int i = chosen();
        if (i < 0) {
            stopPlaying();
            return;
        }
        const double t = m_playClock.nsecsElapsed() * 1e-9;
        showAt(t);
        if (t >= m_planned.geodesics[std::size_t(i)].t)
            m_playTimer.stop();
    });
}

void PlanTool::play() {
    if (chosen() < 0)
        return;
    m_playClock.start();
    m_playTimer.start();
    showAt(0);
}

void PlanTool::showAt(double t) {
    const int i = chosen();
    m_playTime = i < 0 ? -1 : std::clamp(t, 0.0, m_planned.geodesics[std::size_t(i)].t);
    emit playTimeChanged(m_playTime);
    emit changed();
}

void PlanTool::stopPlaying() {
    m_playTimer.stop();
    m_playTime = -1;
    emit playTimeChanged(m_playTime);
    emit changed();
}

void PlanTool::trackPlan() {
    const int i = chosen();
    if (i < 0 || m_planned.geodesics[std::size_t(i)].t <= 0)
        return;
    Scene scene = m_document->scene();
    try {
        scene.path = planTrack(m_request, m_planned.geodesics[std::size_t(i)]);
    } catch (const std::exception& e) {
        m_error = QString::fromStdString(e.what());
        emit changed();
        return;
    }
    scene.preset.clear();
    scene.tEnd.reset(); // the time to traverse the track: the motion's own
    // the plan keeps its start where the new path begins, and the motion chosen
    ScenePlan plan = m_plan;
    plan.from = m_request.from;
    scene.plan = plan;
    m_plan = plan;
    m_document->edit(scene, tr("Track this plan"));
}

QString PlanTool::chosenSummary() const {
    const int i = chosen();
    if (i < 0)
        return m_error;
    const PlannedGeodesic& g = m_planned.geodesics[std::size_t(i)];
    const QLocale locale;
    auto number = [&](double v) { return locale.toString(v, 'g', 6); };
    QString family;
    switch (g.family) {
    case GeodesicFamily::Rest:
        family = tr("at rest");
        break;
    case GeodesicFamily::Pivot:
        family = tr("pivoting");
        break;
    case GeodesicFamily::Line:
        family = tr("straight line");
        break;
    case GeodesicFamily::Libration:
        family = tr("libration");
        break;
    case GeodesicFamily::Rotation:
        family = tr("rotation");
        break;
    case GeodesicFamily::Separatrix:
        family = tr("separatrix");
        break;
    }
    const QString cut =
        std::isfinite(g.cutTime) ? tr("%1 s").arg(number(g.cutTime)) : QStringLiteral("\u221e");
    return tr("motion %1 of %2: %3, k = %4, \u03a8\u2080 = %5 rad, \u03bb(0) = %6 kg m/s, "
              "t = %7 s, cut time %8%9")
        .arg(i + 1)
        .arg(m_planned.geodesics.size())
        .arg(family, number(g.modulus), number(g.psi0), number(g.lambda0), number(g.t), cut,
             g.optimal ? tr(", optimal") : QString());
}

double PlanTool::handleRadius() const {
    return 7 * m_style.lineScale;
}

int PlanTool::chosen() const {
    const int n = int(m_planned.geodesics.size());
    return m_plan.choice >= 0 && m_plan.choice < n ? m_plan.choice : -1;
}

ScenePlan PlanTool::defaultPlan() const {
    ScenePlan plan;
    const auto& solution = m_document->solution();
    if (!solution)
        return plan;
    // the path's end pose: how the sleigh would get there by itself
    const MotionSample end = solution->at(solution->tEnd());
    const MotionSample start = solution->at(0);
    plan.to = {end.x, end.y, end.phi};
    if (std::hypot(end.x - start.x, end.y - start.y) < 1e-9)
        plan.to = {start.x + 2 * std::cos(start.phi), start.y + 2 * std::sin(start.phi), start.phi};
    return plan;
}

void PlanTool::syncFromDocument() {
    if (m_drag == Drag::Target || m_drag == Drag::Heading || m_drag == Drag::Start)
        return; // the drag's own plan until it ends
    const Scene& scene = m_document->scene();
    m_plan = scene.plan ? *scene.plan : defaultPlan();
    replan();
    emit planChanged();
    emit playTimeChanged(m_playTime);
    emit changed();
}

void PlanTool::replan() {
    ++m_generation; // what a background plan brings back now is stale
    m_nextRequest.reset();
    m_playTimer.stop();
    m_playTime = -1;
    m_planned = {};
    m_error.clear();
    ++m_planId;
    const auto& solution = m_document->solution();
    if (!solution)
        return;
    if (solution->scene().mode != SpeedMode::Energy) {
        m_error = tr("Planning needs constant energy (v_T): the constant-speed mode has no "
                     "genuine vakonomic motion");
        return;
    }
    try {
        m_request = planRequestOf(m_plan, *solution);
        m_planned = planVakonomic(m_request);
        if (m_planned.geodesics.empty())
            m_error = tr("No motion reaches the target within %1 s").arg(m_planned.horizon);
    } catch (const std::exception& e) {
        m_error = QString::fromStdString(e.what());
    }
}

QPointF PlanTool::targetHandle() const {
    return m_view.toPixel({m_plan.to.x, m_plan.to.y});
}

QPointF PlanTool::headingHandle() const {
    // y up in the world, down on the screen
    return targetHandle() + kHeadingHandlePx * m_style.lineScale *
                                QPointF(std::cos(m_plan.to.phi), -std::sin(m_plan.to.phi));
}

QPointF PlanTool::startHandle() const {
    if (const auto& solution = m_document->solution()) {
        const Pose from = planStart(m_plan, *solution);
        return m_view.toPixel({from.x, from.y});
    }
    return {};
}

bool PlanTool::press(const QMouseEvent& e) {
    if (e.button() != Qt::LeftButton || !m_document->solution())
        return false;
    const QPointF at = e.position();
    const double reach = handleRadius() + 5;
    auto near = [&](QPointF handle) { return QLineF(handle, at).length() <= reach; };
    if (near(headingHandle())) {
        m_drag = Drag::Heading;
    } else if (near(targetHandle())) {
        m_drag = Drag::Target;
        m_grabOffset = QPointF(m_plan.to.x, m_plan.to.y) - m_view.toWorld(at);
    } else if (near(startHandle())) {
        m_drag = Drag::Start;
        const Pose from = planStart(m_plan, *m_document->solution());
        m_plan.from = from;
        m_grabOffset = QPointF(from.x, from.y) - m_view.toWorld(at);
    } else if (motionAt(at) >= 0) {
        m_drag = Drag::Choosing;
    } else {
        return false;
    }
    return true;
}

bool PlanTool::move(const QMouseEvent& e) {
    if (m_drag == Drag::None || m_drag == Drag::Choosing)
        return m_drag == Drag::Choosing;
    const bool snap = e.modifiers() & Qt::ShiftModifier;
    auto snapped = [&](QPointF world) {
        if (!snap)
            return world;
        const double step = 0.5 * m_view.gridStep();
        return QPointF(step * std::round(world.x() / step), step * std::round(world.y() / step));
    };
    const QPointF world = m_view.toWorld(e.position());
    if (m_drag == Drag::Heading) {
        const QPointF d = e.position() - targetHandle();
        if (std::hypot(d.x(), d.y()) < 1)
            return true;
        double phi = std::atan2(-d.y(), d.x());
        if (snap)
            phi = kSnapAngle * std::round(phi / kSnapAngle);
        m_plan.to.phi = phi;
    } else if (m_drag == Drag::Target) {
        const QPointF to = snapped(world + m_grabOffset);
        m_plan.to.x = to.x();
        m_plan.to.y = to.y();
    } else {
        const QPointF from = snapped(world + m_grabOffset);
        m_plan.from->x = from.x();
        m_plan.from->y = from.y();
    }
    m_plan.choice = 0; // the least time while dragging
    planInBackground();
    emit changed();
    return true;
}

void PlanTool::planInBackground() {
    const auto& solution = m_document->solution();
    if (!solution || solution->scene().mode != SpeedMode::Energy)
        return;
    PlanRequest request;
    try {
        request = planRequestOf(m_plan, *solution);
    } catch (const InputError&) {
        return;
    }
    // the latest pose wins: one plan at a time, the newest pose next
    m_nextRequest = request;
    if (m_planWatcher.isRunning())
        return;
    const quint64 generation = m_generation;
    m_nextRequest.reset();
    m_planWatcher.setFuture(QtConcurrent::run([request, generation]() {
        BackgroundPlan job{request, {}, generation, 0, {}};
        QElapsedTimer clock;
        clock.start();
        try {
            job.plan = planVakonomic(request);
        } catch (const std::exception& e) {
            job.error = QString::fromStdString(e.what());
        }
        job.ms = clock.nsecsElapsed() * 1e-6;
        return job;
    }));
}

void PlanTool::takeBackgroundPlan() {
    const BackgroundPlan job = m_planWatcher.result();
    m_slowestMs = std::max(m_slowestMs, job.ms);
    // a plan made before the document's last one is stale
    if (job.generation == m_generation && active()) {
        m_request = job.request;
        m_planned = job.plan;
        m_error = job.error;
        if (m_error.isEmpty() && m_planned.geodesics.empty())
            m_error = tr("No motion reaches the target within %1 s").arg(m_planned.horizon);
        ++m_planId;
        emit planChanged();
        emit changed();
    }
    if (m_nextRequest && active())
        planInBackground();
}

void PlanTool::release(const QMouseEvent& e) {
    if (m_drag == Drag::None || e.button() != Qt::LeftButton)
        return;
    const Drag drag = m_drag;
    m_drag = Drag::None;
    if (drag == Drag::Choosing) {
        const int motion = motionAt(e.position());
        if (motion >= 0 && motion != m_plan.choice) {
            ScenePlan plan = m_plan;
            plan.choice = motion;
            commit(plan, tr("Choose a planned motion"));
        }
        return;
    }
    commit(m_plan,
           drag == Drag::Start ? tr("Move the plan's start") : tr("Move the plan's target"));
}

void PlanTool::cancel() {
    if (m_drag == Drag::None)
        return;
    m_drag = Drag::None;
    syncFromDocument();
}

void PlanTool::commit(const ScenePlan& plan, const QString& description) {
    Scene scene = m_document->scene();
    scene.plan = plan;
    m_plan = plan;
    m_document->edit(scene, description);
    emit planChanged();
    emit changed();
}

void PlanTool::updateTracks() const {
    const auto* widget = qobject_cast<const QWidget*>(parent());
    const double dpr = widget ? widget->devicePixelRatioF() : 1.0;
    const double scale = m_view.scale() * dpr;
    const QRectF view =
        widget ? m_view.transform().inverted().mapRect(QRectF(widget->rect())) : QRectF();
    if (m_tracks.planId == m_planId && m_tracks.scale == scale && m_tracks.seen == view)
        return;
    m_tracks = {m_planId, scale, view, {}};
    const auto& solution = m_document->solution();
    if (!solution)
        return;
    // each within the canvas's point budget, to 0.25 device pixels where it can be seen
    for (const PlannedGeodesic& g : m_planned.geodesics) {
        const VakonomicMotion body(m_request.system, plannedStart(m_request, g));
        FlattenLimits limits{CanvasCurves::kTolerancePx / scale, view};
        m_tracks.curves.push_back(flattenWithinBudget(
            [&](FlattenLimits& l) {
                return flattenInTime(
                    [&](double t) {
                        const VakonomicState s = body.at(t);
                        return QPointF(s.x, s.y);
                    },
                    g.t, l, 200);
            },
            limits));
    }
}

QRectF PlanTool::worldBounds() const {
    const auto& solution = m_document->solution();
    if (!solution)
        return {};
    const Pose from = planStart(m_plan, *solution);
    double x0 = std::min(from.x, m_plan.to.x), x1 = std::max(from.x, m_plan.to.x);
    double y0 = std::min(from.y, m_plan.to.y), y1 = std::max(from.y, m_plan.to.y);
    // each motion from its closed form, whatever the view: the drawn tracks are flattened only
    // where the view sees them, so a fit from them would keep what it had
    constexpr int kSamples = 256;
    for (const PlannedGeodesic& g : m_planned.geodesics) {
        const VakonomicMotion body(m_request.system, plannedStart(m_request, g));
        for (int i = 0; i <= kSamples; ++i) {
            const VakonomicState p = body.at(g.t * i / kSamples);
            x0 = std::min(x0, p.x);
            x1 = std::max(x1, p.x);
            y0 = std::min(y0, p.y);
            y1 = std::max(y1, p.y);
        }
    }
    return QRectF(QPointF(x0, y0), QPointF(x1, y1));
}

int PlanTool::motionAt(QPointF pixel) const {
    updateTracks();
    const QTransform world = m_view.transform();
    const double reach = 6 * m_style.lineScale;
    int best = -1;
    double bestDistance = reach;
    for (std::size_t i = 0; i < m_tracks.curves.size(); ++i) {
        const auto& points = m_tracks.curves[i].points;
        for (std::size_t k = 0; k + 1 < points.size(); ++k) {
            const double d =
                distanceToSegment(pixel, world.map(points[k]), world.map(points[k + 1]));
            if (d < bestDistance) {
                bestDistance = d;
                best = int(i);
            }
        }
    }
    return best;
}

void PlanTool::paint(QPainter& p) const {
    const auto& solution = m_document->solution();
    if (!solution)
        return;
    updateTracks();
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    const QTransform world = m_view.transform();
    const QColor ink = m_style.vakonomic();
    QColor faint = ink;
    faint.setAlphaF(0.35);
    const int choice = chosen();
    auto isFull = [&](std::size_t i) { return int(i) == choice || m_planned.geodesics[i].optimal; };
    // the faint ones first, the full ones over them
    for (int pass = 0; pass < 2; ++pass) {
        for (std::size_t i = 0; i < m_tracks.curves.size(); ++i) {
            if (isFull(i) != (pass == 1))
                continue;
            QPainterPath track;
            const auto& points = m_tracks.curves[i].points;
            if (points.empty())
                continue;
            track.moveTo(world.map(points[0]));
            for (std::size_t k = 1; k < points.size(); ++k)
                track.lineTo(world.map(points[k]));
            const bool chosenOne = int(i) == choice;
            p.setPen(m_style.pen(pass == 1 ? ink : faint,
                                 chosenOne   ? 3
                                 : pass == 1 ? 2
                                             : 1.5,
                                 chosenOne || pass == 0 ? Qt::SolidLine : Qt::DashLine));
            p.setBrush(Qt::NoBrush);
            p.drawPath(track);
        }
    }
    // the body's outline at both ends of the chosen motion and of every optimal one
    const BodyLook outline{BodyDisplay::Outline, 0, m_style.lineScale};
    for (std::size_t i = 0; i < m_planned.geodesics.size(); ++i) {
        if (!isFull(i))
            continue;
        const PlannedGeodesic& g = m_planned.geodesics[i];
        const VakonomicMotion body(m_request.system, plannedStart(m_request, g));
        for (double t : {0.0, g.t}) {
            const VakonomicState s = body.at(t);
            p.save();
            p.setTransform(world, true);
            paintBody(p, solution->scene().system, solution->system(), {s.x, s.y, s.phi}, ink, true,
                      outline);
            p.restore();
        }
    }
    // each motion's time beside its track where no other label is: the full ones first, a
    // faint one left without when its track has no free place
    QFont font = p.font();
    font.setPointSizeF(font.pointSizeF() * m_style.lineScale);
    p.setFont(font);
    const QFontMetricsF metrics(font);
    std::vector<QRectF> placed;
    for (int pass = 1; pass >= 0; --pass) {
        for (std::size_t i = 0; i < m_tracks.curves.size(); ++i) {
            const auto& c = m_tracks.curves[i];
            if (c.points.empty() || isFull(i) != (pass == 1))
                continue;
            const double t = m_planned.geodesics[i].t;
            const QString label = timeLabel(t);
            std::optional<std::pair<QPointF, QRectF>> spot;
            for (double along : {1.0 / 3, 0.5, 2.0 / 3, 1.0 / 6, 5.0 / 6}) {
                const std::size_t k = std::min(c.countUpTo(t * along), c.points.size() - 1);
                const QPointF at = world.map(c.points[k]) + QPointF(6, -6) * m_style.lineScale;
                const QRectF box =
                    metrics.boundingRect(label).translated(at).adjusted(-2, -1, 2, 1);
                const bool free = std::none_of(placed.begin(), placed.end(),
                                               [&](const QRectF& r) { return r.intersects(box); });
                if (free || (!spot && pass == 1))
                    spot = std::pair{at, box};
                if (free)
                    break;
            }
            if (!spot)
                continue;
            placed.push_back(spot->second);
            p.setPen(Qt::NoPen);
            p.setBrush(QColor(255, 255, 255, isFull(i) ? 220 : 150));
            p.drawRoundedRect(spot->second, 3, 3);
            p.setPen(isFull(i) ? ink.darker(130) : faint);
            p.drawText(spot->first, label);
        }
    }
    // the played bodies: the genuine vakonomic one along the chosen motion, the free ghost from
    // the same start
    if (const int i = chosen(); i >= 0 && m_playTime >= 0) {
        const PlannedGeodesic& g = m_planned.geodesics[std::size_t(i)];
        const VakonomicInitial start = plannedStart(m_request, g);
        const VakonomicState s = VakonomicMotion(m_request.system, start).at(m_playTime);
        const FreeState ghost =
            FreeMotion(m_request.system, {start.x, start.y, start.phi, start.sdot, start.phidot},
                       g.t)
                .at(m_playTime);
        const BodyLook toScale{BodyDisplay::ToScale, m_style.bodyOpacity, m_style.lineScale};
        p.save();
        p.setTransform(world, true);
        paintBody(p, solution->scene().system, solution->system(), {ghost.x, ghost.y, ghost.phi},
                  m_style.free(), true, toScale);
        paintBody(p, solution->scene().system, solution->system(), {s.x, s.y, s.phi}, ink, false,
                  toScale);
        p.restore();
    }
    // the handles: the start, the target's position and its heading
    const QPointF target = targetHandle(), heading = headingHandle(), start = startHandle();
    const double r = handleRadius();
    p.setPen(m_style.pen(ink.darker(150), 1.5));
    p.drawLine(target, heading);
    p.setBrush(Qt::white);
    p.drawEllipse(start, r * 0.8, r * 0.8);
    p.setBrush(ink);
    p.drawEllipse(target, r, r);
    p.setBrush(Qt::white);
    p.drawEllipse(heading, r * 0.7, r * 0.7);
    if (!m_error.isEmpty()) {
        p.setPen(m_style.pen(QColor(170, 0, 0), 1));
        p.drawText(target + QPointF(r + 4, r + metrics.ascent()), m_error);
    }
    p.restore();
}

} // namespace chaplygin::ui
