#include "document/plot_series.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <vector>

namespace chaplygin::ui {

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

} // namespace chaplygin::ui
