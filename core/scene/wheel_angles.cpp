#include "scene/wheel_angles.h"

#include "scene/solution.h"

#include <algorithm>

namespace chaplygin {

namespace {

double param(const SystemSpec& spec, const char* name) {
    const auto it = spec.params.find(name);
    if (it != spec.params.end())
        return it->second;
    return defaultSystemParams(spec.kind).at(name);
}

} // namespace

double signedTravel(const Path& path, double s) {
    // each curve piece runs from its s0 to the next piece's; sdot has the piece's direction
    const auto& pieces = path.pieces();
    double travel = 0;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const PathPiece& piece = pieces[k];
        if (piece.kind != PathPiece::Kind::Curve || s <= piece.s0)
            continue;
        const double end = k + 1 < pieces.size() ? pieces[k + 1].s0 : path.length();
        travel += piece.direction * (std::min(s, end) - piece.s0);
    }
    return travel;
}

WheelAngles wheelAngles(const SystemSpec& spec, double travel, double turn) {
    WheelAngles w;
    switch (spec.kind) {
    case SystemKind::Sleigh:
        break;
    case SystemKind::Disk:
        // sdot = R thetadot, paper (A5)
        w.wheels = 1;
        w.theta1 = travel / param(spec, "R");
        break;
    case SystemKind::Carriage: {
        // sdot + a phidot = R thetadot1, sdot - a phidot = R thetadot2, paper (B2)-(B3)
        const double r = param(spec, "R"), a = param(spec, "a");
        w.wheels = 2;
        w.theta1 = (travel + a * turn) / r;
        w.theta2 = (travel - a * turn) / r;
        break;
    }
    }
    return w;
}

WheelAngles wheelAnglesAt(const Solution& solution, const MotionSample& m) {
    const SystemSpec& spec = solution.scene().system;
    if (spec.kind == SystemKind::Sleigh)
        return {};
    const double phi0 = solution.at(0, MotionParts{true, false, false, false}).phi;
    return wheelAngles(spec, signedTravel(*solution.path(), m.s), m.phi - phi0);
}

} // namespace chaplygin
