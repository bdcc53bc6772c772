#include "scene/annotations_json.h"

#include "common/input_error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace chaplygin {

namespace {

using nlohmann::json;

[[noreturn]] void bad(const std::string& pointer, const std::string& what) {
    throw InputError("scene file " + pointer, what);
}

double coordinate(const json& v, const std::string& at) {
    if (!v.is_number())
        bad(at, std::string("must be a number, got ") + v.type_name());
    const double d = v.get<double>();
    if (!std::isfinite(d))
        bad(at, "must be finite");
    return d;
}

bool finite(const AnnotationMark& mark) {
    return std::all_of(mark.points.begin(), mark.points.end(), [](const auto& p) {
        return std::isfinite(p.first) && std::isfinite(p.second);
    });
}

AnnotationMark readMark(const json& v, const std::string& at) {
    if (!v.is_object())
        bad(at, std::string("must be an object, got ") + v.type_name());
    for (auto it = v.begin(); it != v.end(); ++it)
        if (it.key() != "colour" && it.key() != "kind" && it.key() != "points")
            bad(at + "/" + it.key(), "unknown field (use colour, kind or points)");
    for (const char* key : {"colour", "kind", "points"})
        if (!v.contains(key))
            bad(at, std::string("missing \"") + key + "\"");
    AnnotationMark mark;
    const json& colour = v["colour"];
    if (!colour.is_string())
        bad(at + "/colour", std::string("must be a string, got ") + colour.type_name());
    mark.colour = markColourFromName(colour.get<std::string>());
    if (mark.colour < 0)
        bad(at + "/colour",
            "unknown colour \"" + colour.get<std::string>() + "\" (use red, blue, green or black)");
    const json& kind = v["kind"];
    if (kind == "freehand")
        mark.kind = MarkKind::Freehand;
    else if (kind == "arrow")
        mark.kind = MarkKind::Arrow;
    else
        bad(at + "/kind", "must be \"freehand\" or \"arrow\"");
    const json& points = v["points"];
    if (!points.is_array())
        bad(at + "/points",
            std::string("must be an array of [x, y] pairs, got ") + points.type_name());
    if (mark.kind == MarkKind::Arrow && points.size() != 2)
        bad(at + "/points",
            "an arrow has two points, its tail and its head; got " + std::to_string(points.size()));
    if (points.empty())
        bad(at + "/points", "must have at least one point");
    if (points.size() > kMaxMarkPoints)
        bad(at + "/points", "has " + std::to_string(points.size()) +
                                " points; a mark has at most " + std::to_string(kMaxMarkPoints));
    for (std::size_t i = 0; i < points.size(); ++i) {
        const std::string p = at + "/points/" + std::to_string(i);
        if (!points[i].is_array() || points[i].size() != 2)
            bad(p, "must be an [x, y] pair (metres)");
        mark.points.emplace_back(coordinate(points[i][0], p + "/0"),
                                 coordinate(points[i][1], p + "/1"));
    }
    return mark;
}

} // namespace

json annotationsToJson(const std::vector<AnnotationMark>& marks) {
    json out = json::array();
    for (const AnnotationMark& mark : marks) {
        const bool pointsFit = mark.kind == MarkKind::Arrow
                                   ? mark.points.size() == 2
                                   : !mark.points.empty() && mark.points.size() <= kMaxMarkPoints;
        if (markColourName(mark.colour).empty() || !pointsFit || !finite(mark))
            continue;
        if (out.size() == kMaxMarks)
            break;
        json points = json::array();
        for (const auto& [x, y] : mark.points)
            points.push_back({x, y});
        out.push_back({{"colour", markColourName(mark.colour)},
                       {"kind", mark.kind == MarkKind::Arrow ? "arrow" : "freehand"},
                       {"points", std::move(points)}});
    }
    return out;
}

std::vector<AnnotationMark> annotationsFromJson(const json& v, const std::string& at) {
    if (!v.is_array())
        bad(at, std::string("must be an array of marks, got ") + v.type_name());
    if (v.size() > kMaxMarks)
        bad(at, "has " + std::to_string(v.size()) + " marks; a scene has at most " +
                    std::to_string(kMaxMarks));
    std::vector<AnnotationMark> marks;
    for (std::size_t i = 0; i < v.size(); ++i)
        marks.push_back(readMark(v[i], at + "/" + std::to_string(i)));
    return marks;
}

} // namespace chaplygin
