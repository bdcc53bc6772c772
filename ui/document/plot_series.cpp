#include "document/plot_series.h"

#include "common/input_error.h"
#include "planning/planned_samples.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace chaplygin::ui {

void requireFiniteSeries(const PlotSeries& p) {
    struct Named {
        const char* name;
        const QVector<double>* values;
        const QVector<double>* times;
    };
    const Named all[] = {
        {"s", &p.s, &p.t},
        {"x", &p.x, &p.t},
        {"y", &p.y, &p.t},
        {"Psi", &p.psi, &p.t},
        {"chi", &p.chi, &p.t},
        {"lambda", &p.lambda, &p.t},
        {"T", &p.energy, &p.t},
        {"free x", &p.freeX, &p.freeT},
        {"free y", &p.freeY, &p.freeT},
        {"free Psi", &p.freePsi, &p.freeT},
        {"free chi", &p.freeChi, &p.freeT},
        {"free T", &p.freeEnergy, &p.freeT},
        {"vakonomic x", &p.vakX, &p.vakT},
        {"vakonomic y", &p.vakY, &p.vakT},
        {"vakonomic Psi", &p.vakPsi, &p.vakT},
        {"vakonomic chi", &p.vakChi, &p.vakT},
        {"vakonomic lambda", &p.vakLambda, &p.vakT},
        {"vakonomic T", &p.vakEnergy, &p.vakT},
        {"open-loop x", &p.pertX, &p.pertT},
        {"open-loop y", &p.pertY, &p.pertT},
        {"closed-loop x", &p.fbX, &p.pertT},
        {"closed-loop y", &p.fbY, &p.pertT},
    };
    for (const Named& n : all)
        for (qsizetype i = 0; i < n.values->size(); ++i)
            if (!std::isfinite((*n.values)[i]))
                throw InputError(
                    std::string("plot of ") + n.name,
                    "not finite at t = " + formatNumber(i < n.times->size() ? (*n.times)[i] : NAN) +
                        " s (" + formatNumber((*n.values)[i]) + ")");
    for (qsizetype i = 0; i < p.pathX.size(); ++i)
        if (!std::isfinite(p.pathX[i]) || !std::isfinite(p.pathY[i]))
            throw InputError("path", "point " + std::to_string(i + 1) + " is not finite");
}

PlotSeries collectSeries(const Solution& solution, int freeSamples, int exactSamples) {
    PlotSeries p;
    p.tEnd = solution.tEnd();
    std::vector<MotionSample> controlled =
        exactSamples > 0 ? solution.sample(exactSamples) : solution.controlledAtNodes();
    for (const MotionSample& m : controlled) {
        p.t << m.t;
        p.s << m.s;
        p.x << m.x;
        p.y << m.y;
        p.psi << m.control.psi;
        p.chi << m.control.chi;
        p.lambda << m.control.lambda;
        p.energy << m.control.energy;
    }
    freeSamples = std::max(freeSamples, 2);
    for (int i = 0; i < freeSamples; ++i) {
        double t = p.tEnd * i / (freeSamples - 1);
        FreeState f = solution.freeAt(t);
        p.freeT << t;
        p.freeX << f.x;
        p.freeY << f.y;
        p.freePsi << f.psi;
        p.freeChi << f.chi;
        p.freeEnergy << f.energy;
        VakonomicState v = solution.vakonomicAt(t);
        p.vakT << t;
        p.vakX << v.x;
        p.vakY << v.y;
        p.vakPsi << v.psi;
        p.vakChi << v.chi;
        p.vakLambda << v.lambda;
        p.vakEnergy << v.energy;
    }
    if (solution.perturbed()) {
        p.perturbed = true;
        std::vector<double> times(p.freeT.begin(), p.freeT.end());
        for (const TrackingError& e : solution.trackingErrors(times)) {
            const PerturbedState open = solution.openLoop()->at(e.t);
            const PerturbedState fb = solution.feedback()->at(e.t);
            p.pertT << e.t;
            p.pertX << open.x;
            p.pertY << open.y;
            p.fbX << fb.x;
            p.fbY << fb.y;
            p.openE << e.openE;
            p.openTheta << e.openTheta;
            p.fbE << e.fbE;
            p.fbTheta << e.fbTheta;
        }
    }
    for (const PathPiece& piece : solution.path()->pieces()) {
        if (piece.kind != PathPiece::Kind::Curve)
            continue;
        for (const PathNode& n : piece.table->nodes()) {
            p.pathX << n.x;
            p.pathY << n.y;
        }
    }
    return p;
}

PlotSeries collectPlanSeries(const PlanRequest& request, const PlannedGeodesic& motion,
                             int samples) {
    PlotSeries p;
    p.planned = true;
    p.tEnd = motion.t;
    for (const PlannedSample& s : samplePlannedMotion(request, motion, samples)) {
        p.freeT << s.t;
        p.freeX << s.free.x;
        p.freeY << s.free.y;
        p.freePsi << s.free.psi;
        p.freeChi << s.free.chi;
        p.freeEnergy << s.free.energy;
        p.vakT << s.t;
        p.vakX << s.vakonomic.x;
        p.vakY << s.vakonomic.y;
        p.vakPsi << s.vakonomic.psi;
        p.vakChi << s.vakonomic.chi;
        p.vakLambda << s.vakonomic.lambda;
        p.vakEnergy << s.vakonomic.energy;
    }
    return p;
}

QString sceneCaption(const Solution& solution) {
    const Scene& scene = solution.scene();
    const DerivedSystem& sys = solution.system();
    // systemKindName's words, for lupdate
    [[maybe_unused]] static const char* const kSystemNames[] = {
        QT_TRANSLATE_NOOP("PlotSeries", "sleigh"), QT_TRANSLATE_NOOP("PlotSeries", "disk"),
        QT_TRANSLATE_NOOP("PlotSeries", "carriage")};
    QString system =
        QCoreApplication::translate("PlotSeries", systemKindName(scene.system.kind).c_str());
    QString mode = scene.mode == SpeedMode::Energy
                       ? QCoreApplication::translate("PlotSeries", "constant energy, v_T = %1 m/s")
                       : QCoreApplication::translate("PlotSeries", "constant speed, v_s = %1 m/s");
    QString caption = QStringLiteral("%1: m_eff = %2 kg, a = %3 m, b = %4 m; %5")
                          .arg(system)
                          .arg(sys.mass, 0, 'g', 6)
                          .arg(sys.a, 0, 'g', 6)
                          .arg(sys.b, 0, 'g', 6)
                          .arg(mode.arg(scene.speed, 0, 'g', 6));
    if (!scene.preset.empty())
        caption = QCoreApplication::translate("PlotSeries", "preset %1 \u2014 ")
                      .arg(QString::fromStdString(scene.preset)) +
                  caption;
    return caption;
}

QString planCaption(const Solution& solution, const PlanRequest& request,
                    const PlannedGeodesic& motion) {
    const auto pose = [](const Pose& p) {
        return QStringLiteral("(%1, %2, %3)")
            .arg(p.x, 0, 'g', 6)
            .arg(p.y, 0, 'g', 6)
            .arg(p.phi, 0, 'g', 6);
    };
    const DerivedSystem& sys = solution.system();
    const Scene& scene = solution.scene();
    const QString system =
        QCoreApplication::translate("PlotSeries", systemKindName(scene.system.kind).c_str());
    return QCoreApplication::translate(
               "PlotSeries", "planned motion from %1 to %2 in t = %3 s, \u03a8(0) = %4, k = %5\n"
                             "%6: m_eff = %7 kg, a = %8 m, b = %9 m, v_T = %10 m/s")
        .arg(pose(request.from), pose(request.to))
        .arg(motion.t, 0, 'g', 10)
        .arg(motion.psi0, 0, 'g', 6)
        .arg(motion.modulus, 0, 'g', 6)
        .arg(system)
        .arg(sys.mass, 0, 'g', 6)
        .arg(sys.a, 0, 'g', 6)
        .arg(sys.b, 0, 'g', 6)
        .arg(request.vT, 0, 'g', 6);
}

} // namespace chaplygin::ui
