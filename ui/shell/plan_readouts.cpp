#include "shell/plan_readouts.h"

#include "canvas/plan_tool.h"
#include "canvas/scene_canvas.h"
#include "document/plot_series.h"
#include "panels/accuracy_readout.h"
#include "plots/plots_panel.h"

#include <memory>
#include <optional>

namespace chaplygin::ui {

namespace {

// the motion the readouts show, to draw its series again only when it changed
struct Shown {
    PlanRequest request;
    PlannedGeodesic motion;
    bool same(const PlanRequest& r, const PlannedGeodesic& g) const {
        auto pose = [](const Pose& a, const Pose& b) {
            return a.x == b.x && a.y == b.y && a.phi == b.phi;
        };
        const DerivedSystem& s = request.system;
        return pose(request.from, r.from) && pose(request.to, r.to) && request.vT == r.vT &&
               s.mass == r.system.mass && s.a == r.system.a && s.b == r.system.b &&
               motion.t == g.t && motion.psi0 == g.psi0 && motion.psidot0 == g.psidot0 &&
               motion.optimal == g.optimal && motion.cutTime == g.cutTime &&
               motion.endError == g.endError;
    }
};

} // namespace

void installPlanReadouts(SceneCanvas& canvas, PlotsPanel& plots, AccuracyReadout& accuracy) {
    PlanTool* tool = canvas.planTool();
    auto shown = std::make_shared<std::optional<Shown>>();
    auto update = [&canvas, &plots, &accuracy, tool, shown] {
        const int i = canvas.planMode() ? tool->chosen() : -1;
        if (i < 0) {
            shown->reset();
            plots.showScene();
            accuracy.showPlan(std::nullopt);
            return;
        }
        const auto& motions = tool->planned().geodesics;
        const PlannedGeodesic& g = motions[std::size_t(i)];
        const PlanRequest& request = tool->plannedRequest();
        accuracy.showPlan(
            PlanAccuracy{i + 1, int(motions.size()), g.t, g.cutTime, g.endError, g.optimal});
        if (*shown && (*shown)->same(request, g))
            return;
        *shown = Shown{request, g};
        plots.showPlan(collectPlanSeries(request, g));
        plots.setPlanTime(tool->playTime());
    };
    QObject::connect(tool, &PlanTool::planChanged, &plots, update);
    QObject::connect(&canvas, &SceneCanvas::planModeChanged, &plots, update);
    QObject::connect(tool, &PlanTool::playTimeChanged, &plots, &PlotsPanel::setPlanTime);
    // a click on a plot of the planned motion shows the played bodies at that time
    QObject::connect(&plots, &PlotsPanel::planSeekRequested, tool, [tool](double t) {
        tool->stopPlaying();
        tool->showAt(t);
    });
}

} // namespace chaplygin::ui
