#include "scene/scene_plan.h"

#include "common/input_error.h"

#include <string>

namespace chaplygin {

Pose planStart(const ScenePlan& plan, const Solution& solution) {
    if (plan.from)
        return *plan.from;
    const MotionSample start = solution.at(0);
    return {start.x, start.y, start.phi};
}

PlanRequest planRequestOf(const ScenePlan& plan, const Solution& solution) {
    if (solution.scene().mode != SpeedMode::Energy)
        throw InputError("plan", "the constant-speed mode keeps the speed, not the energy, and "
                                 "has no genuine vakonomic motion to plan; choose constant energy");
    PlanRequest request;
    request.from = planStart(plan, solution);
    request.to = plan.to;
    request.system = solution.system();
    request.vT = solution.scene().speed;
    request.horizon = plan.horizon.value_or(0);
    return request;
}

Plan planOf(const ScenePlan& plan, const Solution& solution) {
    Plan result = planVakonomic(planRequestOf(plan, solution));
    if (result.geodesics.empty())
        throw InputError("plan to", "no genuine vakonomic motion reaches the target within the "
                                    "horizon of " +
                                        formatNumber(result.horizon) + " s");
    if (plan.choice < 0 || std::size_t(plan.choice) >= result.geodesics.size())
        throw InputError("plan choice", "is " + std::to_string(plan.choice) + "; the plan lists " +
                                            std::to_string(result.geodesics.size()) +
                                            " motions, counted from 0");
    return result;
}

} // namespace chaplygin
