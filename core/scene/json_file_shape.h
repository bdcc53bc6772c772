#pragma once
#include <cstddef>
#include <string>

namespace chaplygin {

/// What a JSON file of the program must be before it is parsed: not empty, at most maxBytes, no
/// UTF-8 byte-order mark, no NUL byte, nested at most maxNesting deep. Throws
/// InputError(file + " /", ...) naming the first problem; noun names the file's kind in the size's
/// message ("a scene is at most 16777216 bytes").
void checkJsonFileShape(const std::string& text, const std::string& file, const std::string& noun,
                        std::size_t maxBytes, int maxNesting);

} // namespace chaplygin
