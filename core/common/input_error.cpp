#include "common/input_error.h"

#include <charconv>

namespace chaplygin {

std::string formatNumber(double v) {
    char buf[64];
    auto res = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, res.ptr);
}

} // namespace chaplygin
