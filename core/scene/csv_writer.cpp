#include "scene/csv_writer.h"

#include "scene/finite_results.h"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>

namespace chaplygin {
namespace {

// the header and one line per row, full double precision; a NaN never reaches a CSV
std::string csvText(std::span<const CsvColumn> columns, const std::vector<MotionSample>& rows) {
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
            // -0 is written 0: a spreadsheet reads "-0" as text
            const double value = columns[i].value(m) + 0.0;
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

} // namespace

std::string formatCsv(const std::vector<MotionSample>& rows) {
    return csvText(csvColumnsWritten(!rows.empty() && rows.front().perturbed), rows);
}

std::string formatPlanCsv(const PlanRequest& request, const PlannedGeodesic& motion,
                          const std::vector<double>& times) {
    std::vector<CsvColumn> columns;
    for (const CsvColumn& c : csvColumns())
        if (c.name == "t" || c.name.starts_with("vak_"))
            columns.push_back(c);
    const VakonomicMotion body(request.system, plannedStart(request, motion));
    std::vector<MotionSample> rows(times.size());
    for (std::size_t i = 0; i < times.size(); ++i) {
        rows[i].t = times[i];
        rows[i].vak = body.at(times[i]);
    }
    return csvText(columns, rows);
}

} // namespace chaplygin
