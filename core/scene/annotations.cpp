#include "scene/annotations.h"

#include <array>
#include <cmath>

namespace chaplygin {

namespace {
constexpr std::array<const char*, kMarkColours> kColourNames{"red", "blue", "green", "black"};
} // namespace

std::string markColourName(int colour) {
    return colour >= 0 && colour < kMarkColours ? kColourNames[std::size_t(colour)] : "";
}

int markColourFromName(const std::string& name) {
    for (int i = 0; i < kMarkColours; ++i)
        if (name == kColourNames[std::size_t(i)])
            return i;
    return -1;
}

PenMarks PenMarks::ofFile(std::vector<AnnotationMark> marks, bool savedWithScene) {
    const bool any = !marks.empty();
    return {marks, marks, savedWithScene || any};
}

std::vector<std::pair<double, double>>
simplifyStroke(const std::vector<std::pair<double, double>>& points, double minDistance) {
    if (points.size() <= 2)
        return points;
    std::vector<std::pair<double, double>> kept{points.front()};
    for (std::size_t i = 1; i + 1 < points.size(); ++i) {
        const auto [x, y] = points[i];
        const auto [lx, ly] = kept.back();
        if (std::hypot(x - lx, y - ly) >= minDistance)
            kept.push_back(points[i]);
    }
    kept.push_back(points.back());
    return kept;
}

} // namespace chaplygin
