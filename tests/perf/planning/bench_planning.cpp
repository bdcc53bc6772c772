// chaplygin-bench-planning: BM_Plan, the pose-to-pose planner (docs/numerics.md §9) on 200 fixed
// random targets with |x|, |y| <= 5 b and any heading, from (0, 0, 0), b = v_T = 1: the certified
// least-time motion (least) and every motion within the default horizon (all). Each iteration
// plans one target, the next in turn; the counters give the median and the worst over the targets
// (the goal: median <= 1 ms for least, <= 10 ms for all).
#include "planning/pose_planner.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <numbers>
#include <random>
#include <vector>

namespace chaplygin {
namespace {

const std::vector<Pose>& targets() {
    static const std::vector<Pose> t = [] {
        std::mt19937 rng(29);
        std::uniform_real_distribution<double> xy(-5, 5),
            heading(-std::numbers::pi, std::numbers::pi);
        std::vector<Pose> v(200);
        for (Pose& p : v)
            p = {xy(rng), xy(rng), heading(rng)};
        return v;
    }();
    return t;
}

void BM_Plan(benchmark::State& state) {
    const bool least = state.range(0) == 1;
    PlanRequest r;
    r.system.a = 0;
    r.optimalOnly = least;
    std::vector<double> ms;
    std::size_t i = 0, uncertified = 0;
    for (auto _ : state) {
        r.to = targets()[i++ % targets().size()];
        const auto start = std::chrono::steady_clock::now();
        const Plan plan = planVakonomic(r);
        ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
        uncertified += plan.certified ? 0 : 1;
        benchmark::DoNotOptimize(plan.geodesics.data());
    }
    std::sort(ms.begin(), ms.end());
    state.counters["median_ms"] = ms[ms.size() / 2];
    state.counters["p90_ms"] = ms[ms.size() * 9 / 10];
    state.counters["max_ms"] = ms.back();
    state.counters["uncertified"] = static_cast<double>(uncertified);
    state.SetLabel(least ? "least" : "all");
}
BENCHMARK(BM_Plan)->Arg(1)->Arg(0)->Iterations(200)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace chaplygin

BENCHMARK_MAIN();
