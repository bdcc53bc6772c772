#include "lab/work_precision.h"
#include "numerics_support.h"

#include <gtest/gtest.h>

#include <atomic>
#include <set>

namespace chaplygin {
namespace {

// the measured case of docs/numerics.md §2: catenary, t_end = 10
class CatenaryWorkPrecision : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        s_report = new WorkPrecisionReport(runWorkPrecision(test::sceneWith("catenary", 10)));
    }
    static void TearDownTestSuite() {
        delete s_report;
        s_report = nullptr;
    }
    static WorkPrecisionReport* s_report;
};
WorkPrecisionReport* CatenaryWorkPrecision::s_report = nullptr;

TEST_F(CatenaryWorkPrecision, HoldsAtLeastSixMethodsPerProblem) {
    for (MotionProblem p : {MotionProblem::Controlled, MotionProblem::Free}) {
        std::set<std::string> names;
        for (const WorkPrecisionRow& r : s_report->rows)
            if (r.problem == p)
                names.insert(r.method);
        EXPECT_GE(names.size(), 6u) << motionProblemName(p);
    }
}

TEST_F(CatenaryWorkPrecision, ReachesOneInTenToTheTenOnBothProblemsWithoutTheReference) {
    for (MotionProblem p : {MotionProblem::Controlled, MotionProblem::Free}) {
        double best = INFINITY;
        for (const WorkPrecisionRow& r : s_report->rows)
            if (r.problem == p && !r.chosen)
                best = std::min(best, r.error);
        EXPECT_LE(best, 1e-10) << motionProblemName(p);
    }
}

// Pareto membership depends on wall time, so it is measured by the benchmark
// BM_ChosenOnParetoFront (tests/perf/numerics), not here; this checks the accuracy side.
TEST_F(CatenaryWorkPrecision, ChosenConfigurationsAreExactToRounding) {
    int chosen = 0;
    for (std::size_t i = 0; i < s_report->rows.size(); ++i)
        if (s_report->rows[i].chosen) {
            ++chosen;
            EXPECT_LE(s_report->rows[i].error, 1e-13) << s_report->rows[i].method;
        }
    EXPECT_EQ(chosen, 2);
}

TEST_F(CatenaryWorkPrecision, HorizonsAndReferencesAreReported) {
    EXPECT_NEAR(s_report->freeEnd, 10.0, 0.0);
    EXPECT_LT(s_report->controlledEnd, 10.0); // the body reaches the path's end first
    EXPECT_NE(s_report->controlledReference.find("QAG"), std::string::npos);
    EXPECT_NE(s_report->freeReference.find("closed_form"), std::string::npos);
}

// "model no more than a scene needs": on every preset the app's choice is exact
class PresetWorkPrecision : public ::testing::TestWithParam<std::string> {};

TEST_P(PresetWorkPrecision, ChosenConfigurationsAreExactToRounding) {
    WorkPrecisionReport r = runWorkPrecision(presetScene(GetParam()));
    int chosen = 0;
    for (std::size_t i = 0; i < r.rows.size(); ++i)
        if (r.rows[i].chosen) {
            ++chosen;
            EXPECT_LE(r.rows[i].error, 1e-12) << motionProblemName(r.rows[i].problem);
        }
    EXPECT_EQ(chosen, 2);
}

INSTANTIATE_TEST_SUITE_P(Presets, PresetWorkPrecision,
                         ::testing::Values("line", "circle", "sinusoid"));

TEST(WorkPrecisionCsv, HasTheIssueHeaderAndOneRowPerConfiguration) {
    WorkPrecisionReport r;
    r.rows.push_back({MotionProblem::Free, "closed_form", 0, 0, 1e-4, 0, 0, true});
    r.rows.push_back({MotionProblem::Controlled, "gsl_rk8pd", 1e-10, 2e-12, 1e-3, 1400, 0, false});
    EXPECT_EQ(formatWorkPrecisionCsv(r),
              "problem,method,tolerance,error,seconds,rhs_evals,chosen\n"
              "free,closed_form,0,0.000000e+00,1.000000e-04,0,1\n"
              "controlled,gsl_rk8pd,1e-10,2.000000e-12,1.000000e-03,1400,0\n");
}

TEST(WorkPrecisionPareto, DominatedRowIsOffTheFront) {
    std::vector<WorkPrecisionRow> rows(3);
    rows[0] = {MotionProblem::Free, "a", 0, 1e-10, 1e-3, 0, 0, false};
    rows[1] = {MotionProblem::Free, "b", 0, 1e-12, 1e-4, 0, 0, false};       // better in both
    rows[2] = {MotionProblem::Controlled, "c", 0, 1e-14, 1e-5, 0, 0, false}; // other problem
    EXPECT_FALSE(onParetoFront(rows, 0));
    EXPECT_TRUE(onParetoFront(rows, 1));
    EXPECT_TRUE(onParetoFront(rows, 2));
}

TEST(WorkPrecisionSweep, ReportsProgressAndStopsOnCancel) {
    std::atomic<bool> cancel{false};
    WorkPrecisionOptions o;
    o.tolerances = {1e-4, 1e-8};
    o.stepCounts = {16, 32};
    o.minTimingSeconds = 0;
    int last = 0, total = 0, calls = 0;
    o.progress = [&](int done, int all) {
        EXPECT_GT(done, last);
        last = done;
        total = all;
        if (++calls == 3)
            cancel = true;
    };
    o.cancel = &cancel;
    WorkPrecisionReport r = runWorkPrecision(presetScene("circle"), o);
    EXPECT_TRUE(r.cancelled);
    EXPECT_EQ(calls, 3);
    EXPECT_EQ(r.rows.size(), 3u);
    EXPECT_GT(total, 3);
}

TEST(WorkPrecisionSweep, CompletesWithProgressReachingTheTotal) {
    WorkPrecisionOptions o;
    o.tolerances = {1e-6};
    o.stepCounts = {64};
    o.minTimingSeconds = 0;
    int last = 0, total = -1;
    o.progress = [&](int done, int all) {
        last = done;
        total = all;
    };
    WorkPrecisionReport r = runWorkPrecision(presetScene("line"), o);
    EXPECT_FALSE(r.cancelled);
    EXPECT_EQ(last, total);
    for (const WorkPrecisionRow& row : r.rows)
        EXPECT_LE(row.error, 1e-9) << row.method; // a line: every method is exact to 1e-9 at 1e-6
}

} // namespace
} // namespace chaplygin
