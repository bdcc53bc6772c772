#pragma once
// The scene file's optional "annotations" member: the pen's marks (scene/annotations.h) to JSON
// and back, every bad value named by its JSON path as the rest of the scene file is.
#include "scene/annotations.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace chaplygin {

/// The marks as the scene file holds them: [{"colour": "red", "kind": "freehand", "points":
/// [[x, y], ...]}, ...] (metres). A mark the reader would refuse (a non-finite point, an unknown
/// colour, too many points, an arrow without two) is left out, and the marks past kMaxMarks.
nlohmann::json annotationsToJson(const std::vector<AnnotationMark>& marks);

/// Reads the "annotations" member at JSON pointer `at`. Throws InputError whose where() is
/// "scene file" and the path of the bad value: not an array, more than kMaxMarks marks, an
/// unknown field, colour or kind, no points or more than kMaxMarkPoints, an arrow without
/// exactly two points, a point that is not two finite numbers.
std::vector<AnnotationMark> annotationsFromJson(const nlohmann::json& v, const std::string& at);

} // namespace chaplygin
