#include "scene/csv_writer.h"

#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace chaplygin {

const std::vector<std::string>& csvColumns() {
    static const std::vector<std::string> columns = {"t",
                                                     "s",
                                                     "x",
                                                     "y",
                                                     "phi",
                                                     "psi",
                                                     "chi",
                                                     "lambda",
                                                     "energy",
                                                     "free_x",
                                                     "free_y",
                                                     "free_phi",
                                                     "free_sdot",
                                                     "free_phidot",
                                                     "free_energy",
                                                     "sdot",
                                                     "phidot",
                                                     "psidot",
                                                     "force_axial",
                                                     "force_lateral",
                                                     "control_couple",
                                                     "vak_x",
                                                     "vak_y",
                                                     "vak_phi",
                                                     "vak_sdot",
                                                     "vak_phidot",
                                                     "vak_lambda"};
    return columns;
}

std::string formatCsv(const std::vector<MotionSample>& rows) {
    const auto& columns = csvColumns();
    std::string out;
    for (std::size_t i = 0; i < columns.size(); ++i)
        out += (i ? "," : "") + columns[i];
    out += '\n';
    for (const MotionSample& m : rows) {
        const ControlState& c = m.control;
        const FreeState& f = m.free;
        const VakonomicState& v = m.vak;
        const std::array<double, 27> values = {
            m.t,      m.s,      m.x,      m.y,      m.phi,        c.psi,          c.chi,
            c.lambda, c.energy, f.x,      f.y,      f.phi,        f.sdot,         f.phidot,
            f.energy, c.sdot,   c.phidot, c.psidot, c.forceAxial, c.forceLateral, c.controlCouple,
            v.x,      v.y,      v.phi,    v.sdot,   v.phidot,     v.lambda};
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (!std::isfinite(values[i]))
                throw std::runtime_error("internal error: column " + columns[i] +
                                         " is not finite at t = " + std::to_string(m.t));
            char buf[32];
            auto res = std::to_chars(buf, buf + sizeof buf, values[i]);
            if (i)
                out += ',';
            out.append(buf, res.ptr);
        }
        out += '\n';
    }
    return out;
}

} // namespace chaplygin
