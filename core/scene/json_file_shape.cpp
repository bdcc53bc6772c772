#include "scene/json_file_shape.h"

#include "common/input_error.h"

namespace chaplygin {

void checkJsonFileShape(const std::string& text, const std::string& file, const std::string& noun,
                        std::size_t maxBytes, int maxNesting) {
    const auto bad = [&file](const std::string& what) { throw InputError(file + " /", what); };
    if (text.empty())
        bad("the file is empty");
    if (text.size() > maxBytes)
        bad("the file is " + std::to_string(text.size()) + " bytes; " + noun + " is at most " +
            std::to_string(maxBytes) + " bytes");
    if (text.size() >= 3 && static_cast<unsigned char>(text[0]) == 0xEF &&
        static_cast<unsigned char>(text[1]) == 0xBB && static_cast<unsigned char>(text[2]) == 0xBF)
        bad("the file starts with a UTF-8 byte-order mark; save it as plain UTF-8");
    int depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\0')
            bad("the file contains a NUL byte at offset " + std::to_string(i) + " (binary data?)");
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '{' || c == '[') {
            if (++depth > maxNesting)
                bad("nested deeper than " + std::to_string(maxNesting) + " levels at offset " +
                    std::to_string(i));
        } else if (c == '}' || c == ']') {
            --depth;
        }
    }
}

} // namespace chaplygin
