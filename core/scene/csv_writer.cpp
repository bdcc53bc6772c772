#include "scene/csv_writer.h"

#include "scene/finite_results.h"

#include <charconv>

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
        requireFiniteSample(m); // an InputError naming the column and the time
        for (std::size_t i = 0; i < columns.size(); ++i) {
            const double value = columns[i].value(m);
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
