#include "lab/gallery.h"

#include "common/input_error.h"
#include "scene/presets.h"

#include <numbers>
#include <utility>

namespace chaplygin {
namespace {

Scene polylineSquare(SpeedMode mode) {
    Scene s;
    s.path.kind = PathKind::Polyline;
    s.path.points = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    s.path.corners = CornerMode::Pivot;
    s.mode = mode;
    return s;
}

// the explanation becomes the scene's note
GalleryEntry entry(std::string name, std::string title, std::string note, Scene scene,
                   bool rejected, std::string message) {
    scene.note = std::move(note);
    return {std::move(name), std::move(title), std::move(scene), rejected, std::move(message)};
}

std::vector<GalleryEntry> build() {
    std::vector<GalleryEntry> g;
    g.push_back(entry(
        "printed-branch", "The paper's printed branch reverses at inflections",
        "The paper prints tan(Psi) = rho/b with Psi in (-pi/2, pi/2). On y = -sin x the curvature "
        "changes sign at every multiple of pi; with the printed branch Psi jumps from +pi/2 to "
        "-pi/2 there, sdot = v_T sin(Psi) becomes negative and the sleigh would reverse along a "
        "path it is meant to follow forwards. Chaplygin Lab takes Psi = atan2(1, b kappa) in "
        "(0, pi): Psi passes pi/2 smoothly and sdot stays positive.",
        presetScene("sinusoid"), false, {}));
    g.push_back(entry(
        "corner-pivot", "A corner in constant-energy mode: pivot in place",
        "At a corner of a drawn polyline the curvature is a delta function: Psi goes to 0 (left) "
        "or "
        "pi (right), sdot = 0 and |phidot| = v_T/b. The sleigh stops and turns about the knife "
        "point for b |dphi|/v_T seconds, driven by an impulsive but workless control.",
        polylineSquare(SpeedMode::Energy), false, {}));
    g.push_back(entry(
        "corner-constant-speed", "A corner in constant-speed mode: cannot turn",
        "With sdot = v_s fixed (App. C) the kinetic energy is (m/2) v_s^2 (1 + b^2 kappa^2), "
        "which "
        "is infinite at a corner. No finite control turns the sleigh there; the app refuses the "
        "scene and names the corner. Smooth the corners or use constant energy.",
        polylineSquare(SpeedMode::Speed), true, "cannot turn a corner"));
    Scene cusp;
    cusp.path.kind = PathKind::Parametric;
    cusp.path.xOfU = "u^2";
    cusp.path.yOfU = "u^3";
    cusp.path.from = -1;
    cusp.path.to = 1;
    g.push_back(entry(
        "cusp", "A cusp: the tangent vanishes",
        "On x = u^2, y = u^3 the velocity r'(u) vanishes at u = 0 and the tangent flips: to "
        "follow "
        "the cusp the sleigh would have to stop and back up (sdot changes sign), which the "
        "forward branch Psi in (0, pi) cannot do and the paper does not treat. The app refuses "
        "the path and names the place.",
        cusp, true, "path at u = 0"));
    Scene sharp = presetScene("sinusoid");
    sharp.path.y = "-0.001*sin(x/0.001)";
    sharp.path.to = 4 * std::numbers::pi * 0.001;
    sharp.preset.clear();
    g.push_back(entry(
        "high-curvature", "Very high curvature, b kappa = 1000",
        "A sinusoid a thousand times smaller than the sleigh: b kappa reaches 1000, the sleigh "
        "almost only turns, and sqrt(1 + b^2 kappa^2) has a near-kink at every inflection. "
        "Explicit ODE steppers in t need steps a thousand times smaller than on the paper's "
        "sinusoid; the app's quadrature on the adaptive path table stays exact.",
        sharp, false, {}));
    Scene laps = presetScene("circle");
    laps.preset.clear();
    laps.path.xOfU = "cos(u)";
    laps.path.yOfU = "sin(u)";
    laps.path.to = 2 * std::numbers::pi * 600;
    laps.tEnd = 5000;
    g.push_back(entry(
        "long-horizon", "A long horizon: t = 5000 s",
        "Six hundred laps of a unit circle, 5000 s. The free sleigh's phidot decays like sech and "
        "would reach subnormal numbers, slowing an ODE solver several times; the closed form "
        "switches to a straight line once the heading is constant to 1e-17, so every time "
        "costs the same.",
        laps, false, {}));
    g.push_back(entry(
        "open-loop", "Open-loop integration of (36)-(37) drifts off the path",
        "The paper integrates xdot = v_T sin(Psi) cos(phi), ydot = v_T sin(Psi) sin(phi) in time "
        "(Fig. 3). Nothing pulls the integrated body back to the path, so every error in phi "
        "accumulates and the body drifts away; the method lab shows it. The app integrates along "
        "the path instead and is on the path by construction.",
        presetScene("sinusoid"), false, {}));
    g.push_back(entry(
        "vakonomic-circle", "The genuine vakonomic system leaves the circle",
        "If lambda obeys its own equation (21) instead of being an external control, only "
        "lambda(0) is free. Started on the circle with the tracking lambda, the genuine vakonomic "
        "sleigh leaves the circle within seconds: the paper's tracking is a control-input "
        "system, not the vakonomic one (physics.md sec. 1).",
        presetScene("circle"), false, {}));
    return g;
}

} // namespace

const std::vector<GalleryEntry>& galleryEntries() {
    static const std::vector<GalleryEntry> entries = build();
    return entries;
}

const GalleryEntry& galleryEntry(const std::string& name) {
    for (const GalleryEntry& e : galleryEntries())
        if (e.name == name)
            return e;
    throw InputError("gallery", "unknown gallery scene '" + name + "'");
}

} // namespace chaplygin
