#include "scene/csv_writer.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace chaplygin {

std::string formatCsv(const std::vector<MotionSample>& rows) {
    const std::span<const CsvColumn> columns =
        csvColumnsWritten(!rows.empty() && rows.front().perturbed);
    std::string out;
    for (std::size_t i = 0; i < columns.size(); ++i) {
        if (i)
            out += ',';
        out += columns[i].name;
    }
    out += '\n';
    for (const MotionSample& m : rows) {
        for (std::size_t i = 0; i < columns.size(); ++i) {
            const double value = columns[i].value(m);
            if (!std::isfinite(value))
                throw std::runtime_error("internal error: column " + std::string(columns[i].name) +
                                         " is not finite at t = " + std::to_string(m.t));
            char buf[32];
            auto res = std::to_chars(buf, buf + sizeof buf, value);
            if (i)
                out += ',';
            out.append(buf, res.ptr);
        }
        out += '\n';
    }
    return out;
}

} // namespace chaplygin
