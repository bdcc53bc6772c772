#include "scene/body_vectors.h"

#include <cmath>

namespace chaplygin {

BodyState controlledBodyState(const MotionSample& m) {
    BodyState b;
    b.x = m.x;
    b.y = m.y;
    b.phi = m.phi;
    b.sdot = m.control.sdot;
    b.phidot = m.control.phidot;
    b.forceAxial = m.control.forceAxial;
    b.knifeReaction = m.control.knifeReaction;
    b.controlCouple = m.control.controlCouple;
    b.pivot = std::isinf(m.kappa);
    return b;
}

BodyState freeBodyState(const DerivedSystem& system, const FreeState& free) {
    BodyState b;
    b.x = free.x;
    b.y = free.y;
    b.phi = free.phi;
    b.sdot = free.sdot;
    b.phidot = free.phidot;
    const double ratio = system.a / system.b;
    b.knifeReaction = system.mass * (1 - ratio * ratio) * free.sdot * free.phidot;
    return b;
}

BodyVectors bodyVectors(const DerivedSystem& system, const BodyState& body) {
    const double c = std::cos(body.phi), s = std::sin(body.phi), a = system.a;
    BodyVectors v;
    v.cx = body.x + a * c;
    v.cy = body.y + a * s;
    // s-hat = (cos phi, sin phi), n-hat = (-sin phi, cos phi)
    v.knifeVelocity = {body.x, body.y, body.sdot * c, body.sdot * s};
    const double along = body.sdot, across = a * body.phidot;
    v.cmVelocity = {v.cx, v.cy, along * c - across * s, along * s + across * c};
    v.axialForce = {v.cx, v.cy, body.forceAxial * c, body.forceAxial * s};
    v.lateralReaction = {body.x, body.y, -body.knifeReaction * s, body.knifeReaction * c};
    v.couple = body.controlCouple;
    return v;
}

} // namespace chaplygin
