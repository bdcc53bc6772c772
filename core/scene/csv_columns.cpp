#include "scene/csv_columns.h"

#include <algorithm>

namespace chaplygin {

namespace {

// One line per column, in CSV order (docs/physics.md §2 for the control, §4 for the free body,
// §8 for the genuine vakonomic body, §9 for the perturbed ones). A new column is one more line.
constexpr CsvColumn kColumns[] = {
    {"t", "s", "time", [](auto& m) { return m.t; }},
    {"s", "m", "distance travelled along the path", [](auto& m) { return m.s; }},
    {"x", "m", "contact point P, x", [](auto& m) { return m.x; }},
    {"y", "m", "contact point P, y", [](auto& m) { return m.y; }},
    {"phi", "rad", "heading φ", [](auto& m) { return m.phi; }},
    {"psi", "rad", "control angle Ψ", [](auto& m) { return m.control.psi; }},
    {"chi", "rad", "χ = Ψ − (a/b) φ", [](auto& m) { return m.control.chi; }},
    {"lambda", "kg m/s", "multiplier λ = m b χ̇", [](auto& m) { return m.control.lambda; }},
    {"energy", "J", "kinetic energy T", [](auto& m) { return m.control.energy; }},
    {"free_x", "m", "free body's P, x", [](auto& m) { return m.free.x; }},
    {"free_y", "m", "free body's P, y", [](auto& m) { return m.free.y; }},
    {"free_phi", "rad", "free body's heading", [](auto& m) { return m.free.phi; }},
    {"free_sdot", "m/s", "free body's speed", [](auto& m) { return m.free.sdot; }},
    {"free_phidot", "rad/s", "free body's turning rate", [](auto& m) { return m.free.phidot; }},
    {"free_energy", "J", "free body's kinetic energy", [](auto& m) { return m.free.energy; }},
    {"sdot", "m/s", "signed speed ṡ along the heading", [](auto& m) { return m.control.sdot; }},
    {"phidot", "rad/s", "turning rate φ̇", [](auto& m) { return m.control.phidot; }},
    {"psidot", "rad/s", "rate of the control angle Ψ̇", [](auto& m) { return m.control.psidot; }},
    {"force_axial", "N", "axial control force F_cs", [](auto& m) { return m.control.forceAxial; }},
    {"force_lateral", "N", "lateral force F_cφ", [](auto& m) { return m.control.forceLateral; }},
    {"control_couple", "N m", "control couple τ", [](auto& m) { return m.control.controlCouple; }},
    {"vak_x", "m", "vakonomic body's P, x", [](auto& m) { return m.vak.x; }},
    {"vak_y", "m", "vakonomic body's P, y", [](auto& m) { return m.vak.y; }},
    {"vak_phi", "rad", "vakonomic body's heading", [](auto& m) { return m.vak.phi; }},
    {"vak_sdot", "m/s", "vakonomic body's speed", [](auto& m) { return m.vak.sdot; }},
    {"vak_phidot", "rad/s", "vakonomic body's turning rate", [](auto& m) { return m.vak.phidot; }},
    {"vak_lambda", "kg m/s", "vakonomic λ = λ_c − m a φ̇", [](auto& m) { return m.vak.lambda; }},
    {"pert_x", "m", "open-loop perturbed body's P, x", [](auto& m) { return m.pert.x; }, true},
    {"pert_y", "m", "open-loop perturbed body's P, y", [](auto& m) { return m.pert.y; }, true},
    {"pert_phi", "rad", "open-loop perturbed body's heading", [](auto& m) { return m.pert.phi; },
     true},
    {"pert_sdot", "m/s", "open-loop perturbed body's speed", [](auto& m) { return m.pert.sdot; },
     true},
    {"pert_phidot", "rad/s", "open-loop perturbed body's turning rate",
     [](auto& m) { return m.pert.phidot; }, true},
    {"fb_x", "m", "feedback body's P, x", [](auto& m) { return m.fb.x; }, true},
    {"fb_y", "m", "feedback body's P, y", [](auto& m) { return m.fb.y; }, true},
    {"fb_phi", "rad", "feedback body's heading", [](auto& m) { return m.fb.phi; }, true},
    {"fb_sdot", "m/s", "feedback body's speed", [](auto& m) { return m.fb.sdot; }, true},
    {"fb_phidot", "rad/s", "feedback body's turning rate", [](auto& m) { return m.fb.phidot; },
     true},
    {"fb_lambda", "kg m/s", "feedback body's control λ = m (b Ψ̇ − a φ̇)",
     [](auto& m) { return m.fb.lambda; }, true},
    {"fb_error", "m", "feedback body's lateral error e (left of the path > 0)",
     [](auto& m) { return m.fb.error; }, true},
};

// the perturbed bodies' columns come last, so the columns written are a prefix
constexpr std::size_t unperturbedCount() {
    std::size_t n = 0;
    while (n < std::size(kColumns) && !kColumns[n].perturbed)
        ++n;
    for (std::size_t i = n; i < std::size(kColumns); ++i)
        if (!kColumns[i].perturbed)
            return 0;
    return n;
}
static_assert(unperturbedCount() > 0, "the perturbed bodies' columns must come last");

} // namespace

std::span<const CsvColumn> csvColumns() {
    return kColumns;
}

std::span<const CsvColumn> csvColumnsWritten(bool perturbed) {
    return perturbed ? std::span<const CsvColumn>(kColumns)
                     : std::span<const CsvColumn>(kColumns, unperturbedCount());
}

MotionParts csvColumnParts(const CsvColumn& column) {
    const std::string_view name = column.name;
    const auto prefixed = [name](std::string_view prefix) { return name.starts_with(prefix); };
    MotionParts parts{false, false, false, false};
    if (prefixed("free_"))
        parts.free = true;
    else if (prefixed("vak_"))
        parts.vakonomic = true;
    else if (prefixed("pert_") || prefixed("fb_"))
        parts.perturbed = true;
    else if (name != "t")
        parts.controlled = true;
    return parts;
}

std::optional<std::size_t> csvColumnIndex(std::string_view name) {
    const auto* it = std::find_if(std::begin(kColumns), std::end(kColumns),
                                  [name](const CsvColumn& c) { return c.name == name; });
    if (it == std::end(kColumns))
        return std::nullopt;
    return static_cast<std::size_t>(it - std::begin(kColumns));
}

} // namespace chaplygin
