#include "scene/perturbation.h"

#include "common/input_error.h"

#include <array>
#include <cmath>
#include <numbers>

namespace chaplygin {
namespace {

constexpr std::array<std::string_view, 9> kNames = {
    "dy",      "dphi",          "dpsi",           "t_push",      "push_psi",
    "push_dy", "feedback_rate", "feedback_limit", "controller_b"};

std::string nameList() {
    std::string out;
    for (std::size_t i = 0; i < kNames.size(); ++i)
        out += (i == 0 ? "" : i + 1 == kNames.size() ? " or " : ", ") + std::string(kNames[i]);
    return out;
}

void require(bool ok, std::string_view name, const std::string& what) {
    if (!ok)
        throw InputError("perturbation " + std::string(name), what);
}

} // namespace

std::span<const std::string_view> perturbationFieldNames() {
    return kNames;
}

void setPerturbationField(Perturbation& p, std::string_view name, double value) {
    require(std::isfinite(value), name, "must be a finite number");
    // the feedback's chained form needs |theta_e| < pi/2 (docs/physics.md §9)
    const auto heading = [&](double& field) {
        require(std::fabs(value) < std::numbers::pi / 2, name,
                "must be less than pi/2 in magnitude, got " + formatNumber(value));
        field = value;
    };
    const auto positive = [&](auto& field, const char* unit) {
        require(value > 0, name,
                std::string("must be > 0 ") + unit + ", got " + formatNumber(value));
        field = value;
    };
    if (name == "dy")
        p.dy = value;
    else if (name == "dphi")
        heading(p.dphi);
    else if (name == "dpsi")
        heading(p.dpsi);
    else if (name == "t_push") {
        require(value >= 0, name, "must be >= 0 s, got " + formatNumber(value));
        p.tPush = value;
    } else if (name == "push_psi")
        heading(p.pushPsi);
    else if (name == "push_dy")
        p.pushDy = value;
    else if (name == "feedback_rate")
        positive(p.feedbackRate, "1/m");
    else if (name == "feedback_limit")
        positive(p.feedbackLimit, "rad/s");
    else if (name == "controller_b")
        positive(p.controllerB, "m");
    else
        throw InputError("perturbation",
                         "unknown field '" + std::string(name) + "' (use " + nameList() + ")");
}

std::vector<std::pair<std::string, double>> perturbationFields(const Perturbation& p) {
    std::vector<std::pair<std::string, double>> out = {
        {"dy", p.dy}, {"dphi", p.dphi}, {"dpsi", p.dpsi}};
    if (p.tPush) {
        out.emplace_back("t_push", *p.tPush);
        out.emplace_back("push_psi", p.pushPsi);
        out.emplace_back("push_dy", p.pushDy);
    }
    out.emplace_back("feedback_rate", p.feedbackRate);
    if (p.feedbackLimit)
        out.emplace_back("feedback_limit", *p.feedbackLimit);
    if (p.controllerB)
        out.emplace_back("controller_b", *p.controllerB);
    return out;
}

void checkPerturbation(const Perturbation& p) {
    const bool push = p.pushPsi != 0 || p.pushDy != 0;
    if (push && !p.tPush)
        throw InputError(p.pushPsi != 0 ? "perturbation push_psi" : "perturbation push_dy",
                         "a push needs its time t_push");
    if (p.tPush && !push)
        throw InputError("perturbation t_push", "needs a push: push_psi or push_dy");
}

} // namespace chaplygin
