// The canvas's curves against the exact curves (docs/architecture.md, "ui/: the desktop
// application"): every drawn point within 0.25 device pixels of the exact path, every exact point
// within 0.25 px of the drawn line, and the knife point on the drawn path within 0.5 px at every
// frame. The exact paths are the presets' own formulas evaluated here, not the path table the
// canvas reads.
#include "canvas/curve_flattening.h"
#include "scene/presets.h"
#include "scene/scene_json.h"
#include "scene/scene_resources.h"
#include "scene/solution.h"

#include <QtTest>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

using Polyline = std::vector<QPointF>;

double distanceToSegment(QPointF p, QPointF a, QPointF b) {
    const QPointF ab = b - a, ap = p - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(ap, ab) / len2, 0.0, 1.0) : 0.0;
    const QPointF d = ap - t * ab;
    return std::hypot(d.x(), d.y());
}

// the largest distance [m] from any point of `from` (its vertices and `between` points between
// each two) to the polyline `to`; a distance above `exhaustiveAbove` [m] is looked for everywhere
double largestDistance(const Polyline& from, const Polyline& to, int between,
                       double exhaustiveAbove) {
    double worst = 0;
    std::size_t hint = 0; // both run the same way: search near the last closest segment first
    auto distance = [&](QPointF p) {
        double best = std::numeric_limits<double>::infinity();
        auto look = [&](std::size_t lo, std::size_t hi) {
            for (std::size_t k = lo; k + 1 < hi; ++k) {
                const double d = distanceToSegment(p, to[k], to[k + 1]);
                if (d < best) {
                    best = d;
                    hint = k;
                }
            }
        };
        const std::size_t window = 64;
        look(hint > window ? hint - window : 0, std::min(to.size(), hint + window));
        if (best > exhaustiveAbove) // the window may have missed: a cusp's branches lie close

            look(0, to.size());
        return best;
    };
    for (std::size_t i = 0; i < from.size(); ++i) {
        worst = std::max(worst, distance(from[i]));
        if (i + 1 < from.size())
            for (int j = 1; j <= between; ++j) {
                const QPointF q = from[i] + (from[i + 1] - from[i]) * j / double(between + 1);
                worst = std::max(worst, distance(q));
            }
    }
    return worst;
}

Polyline exactCurve(const std::function<QPointF(double)>& f, double u0, double u1, int count) {
    Polyline out;
    for (int i = 0; i <= count; ++i)
        out.push_back(f(u0 + (u1 - u0) * i / count));
    return out;
}

struct ExactPath {
    const char* name;
    std::function<Scene()> scene;
    std::function<QPointF(double)> curve;
    double u0, u1;
};

std::vector<ExactPath> exactPaths() {
    const double pi = std::numbers::pi;
    return {
        {"circle", [] { return presetScene("circle"); },
         [](double u) { return QPointF(2 * std::cos(u), 2 * std::sin(u)); }, 0, 2 * pi},
        {"catenary", [] { return presetScene("catenary"); },
         [](double u) { return QPointF(std::sqrt(u * u + 1), std::log(u + std::sqrt(u * u + 1))); },
         0, 5},
        {"sinusoid", [] { return presetScene("sinusoid"); },
         [](double x) { return QPointF(x, -std::sin(x)); }, 0, 4 * pi},
        {"cusp",
         [] {
             for (const SceneResource& r : sceneResources())
                 if (r.path == "gallery/cusp.json")
                     return sceneFromJson(std::string(r.text));
             throw std::logic_error("no gallery/cusp.json among the compiled-in scenes");
         },
         [](double u) { return QPointF(u * u, u * u * u); }, -1, 1},
    };
}

// device pixels per metre: a projector's whole-path view to a close zoom
constexpr double kScales[] = {20, 57, 160, 400, 1000};

} // namespace

class CurveFlatteningTest : public QObject {
    Q_OBJECT
  private slots:
    void drawnPathWithinQuarterPixelOfExactPath();
    void knifePointOnDrawnPathAtEveryFrame();
    void trailsWithinQuarterPixelOfTheirMotion();
    void pushedTrailsWithinQuarterPixelOfTheirMotion();
    void curveTooDenseForTheBudgetEndsExactly();
};

void CurveFlatteningTest::drawnPathWithinQuarterPixelOfExactPath() {
    for (const ExactPath& p : exactPaths()) {
        auto solution = std::make_shared<const Solution>(Solution::compute(p.scene()));
        const Polyline exact = exactCurve(p.curve, p.u0, p.u1, 40000);
        for (double scale : kScales) {
            CanvasCurves curves;
            curves.update(solution, scale);
            const Polyline& drawn = curves.path().points;
            const double drawnOff = largestDistance(drawn, exact, 3, 0.1 / scale) * scale;
            const double exactOff = largestDistance(exact, drawn, 0, 0.1 / scale) * scale;
            qInfo("%s at %g px/m: %zu points, drawn to exact %.3f px, exact to drawn %.3f px",
                  p.name, scale, drawn.size(), drawnOff, exactOff);
            QVERIFY2(drawnOff <= CanvasCurves::kTolerancePx,
                     qPrintable(QString("%1 at %2 px/m: a drawn point %3 px from the exact path")
                                    .arg(p.name)
                                    .arg(scale)
                                    .arg(drawnOff)));
            QVERIFY2(exactOff <= CanvasCurves::kTolerancePx,
                     qPrintable(QString("%1 at %2 px/m: an exact point %3 px from the drawn path")
                                    .arg(p.name)
                                    .arg(scale)
                                    .arg(exactOff)));
        }
    }
}

void CurveFlatteningTest::knifePointOnDrawnPathAtEveryFrame() {
    for (const ExactPath& p : exactPaths()) {
        auto solution = std::make_shared<const Solution>(Solution::compute(p.scene()));
        Polyline knife;
        const double dt = 1.0 / 60; // every frame at 60 Hz
        for (double t = 0; t <= solution->tEnd(); t += dt) {
            const MotionSample m = solution->at(t);
            knife.push_back({m.x, m.y});
        }
        for (double scale : kScales) {
            CanvasCurves curves;
            curves.update(solution, scale);
            const double off = largestDistance(knife, curves.path().points, 0, 0.1 / scale) * scale;
            QVERIFY2(off <= 0.5, qPrintable(QString("%1 at %2 px/m: the knife %3 px off the path")
                                                .arg(p.name)
                                                .arg(scale)
                                                .arg(off)));
        }
    }
}

void CurveFlatteningTest::trailsWithinQuarterPixelOfTheirMotion() {
    // the free and vakonomic trails against their bodies' positions at dense times
    for (const ExactPath& p : exactPaths()) {
        auto solution = std::make_shared<const Solution>(Solution::compute(p.scene()));
        Polyline free, vak;
        const int count = 20000;
        for (int i = 0; i <= count; ++i) {
            const double t = solution->tEnd() * i / count;
            const FreeState f = solution->freeAt(t);
            const VakonomicState v = solution->vakonomicAt(t);
            free.push_back({f.x, f.y});
            vak.push_back({v.x, v.y});
        }
        for (double scale : {20.0, 160.0}) {
            CanvasCurves curves;
            curves.update(solution, scale);
            const double freeOff =
                largestDistance(curves.free().points, free, 3, 0.1 / scale) * scale;
            const double vakOff =
                largestDistance(curves.vakonomic().points, vak, 3, 0.1 / scale) * scale;
            QVERIFY2(freeOff <= CanvasCurves::kTolerancePx,
                     qPrintable(QString("%1: free trail %2 px off").arg(p.name).arg(freeOff)));
            QVERIFY2(vakOff <= CanvasCurves::kTolerancePx,
                     qPrintable(QString("%1: vakonomic trail %2 px off").arg(p.name).arg(vakOff)));
        }
    }
}

void CurveFlatteningTest::pushedTrailsWithinQuarterPixelOfTheirMotion() {
    // the open- and closed-loop bodies of the gallery's pushed scene against their states at
    // dense times (each an integration step from the last accepted one, docs/physics.md §9)
    Scene scene;
    for (const SceneResource& r : sceneResources())
        if (r.path == "gallery/pushed-off-path.json")
            scene = sceneFromJson(std::string(r.text));
    QVERIFY(scene.perturbation.has_value());
    auto solution = std::make_shared<const Solution>(Solution::compute(scene));
    QVERIFY(solution->perturbed());
    for (const PerturbedMotion* body : {solution->openLoop(), solution->feedback()}) {
        // dense times, and the push's instant from both sides
        std::vector<double> times;
        const int count = 20000;
        for (int i = 0; i <= count; ++i)
            times.push_back(solution->tEnd() * i / count);
        const double tPush = scene.perturbation->tPush.value();
        times.insert(times.end(), {tPush * (1 - 1e-12), tPush * (1 + 1e-12)});
        std::sort(times.begin(), times.end());
        Polyline exact;
        for (double t : times) {
            const PerturbedState b = body->at(t);
            exact.push_back({b.x, b.y});
        }
        for (double scale : {20.0, 160.0, 1000.0}) {
            CanvasCurves curves;
            curves.update(solution, scale);
            const FlatCurve& drawn =
                body == solution->openLoop() ? curves.openLoop() : curves.closedLoop();
            // the drawn line between two points at the same time is the push's jump: its ends
            // are checked, not the line between them
            double drawnOff = largestDistance(drawn.points, exact, 0, 0.1 / scale);
            for (std::size_t i = 0; i + 1 < drawn.points.size(); ++i) {
                if (!(drawn.param[i + 1] > drawn.param[i]))
                    continue;
                const Polyline middle{0.5 * (drawn.points[i] + drawn.points[i + 1])};
                const double d = largestDistance(middle, exact, 0, 0.1 / scale);
                drawnOff = std::max(drawnOff, d);
            }
            const double exactOff = largestDistance(exact, drawn.points, 0, 0.1 / scale);
            qInfo("%s at %g px/m: %zu points, drawn to exact %.3f px, exact to drawn %.3f px",
                  body == solution->openLoop() ? "open loop" : "feedback", scale,
                  drawn.points.size(), drawnOff * scale, exactOff * scale);
            QVERIFY(drawnOff * scale <= CanvasCurves::kTolerancePx);
            QVERIFY(exactOff * scale <= CanvasCurves::kTolerancePx);
        }
    }
}

void CurveFlatteningTest::curveTooDenseForTheBudgetEndsExactly() {
    // 600 laps of the unit circle in time (the long horizon's controlled body) at 2.7e3 device
    // px/m, seen near (1, 0): no tolerance fits the budget, so the curve is drawn at the one
    // asked for as far as the budget goes, every point and chord within it of the circle, and
    // ends there; its seeds alone were chords of 12.5 rad, straight across the view
    const double pi = std::numbers::pi;
    const double tEnd = 1200 * pi;
    auto circle = [](double t) { return QPointF(std::cos(t), std::sin(t)); };
    const double tolerance = CanvasCurves::kTolerancePx / 4096;
    FlattenLimits limits{tolerance, QRectF(0.6, -0.2, 0.6, 0.4)};
    const FlatCurve flat = flattenWithinBudget(
        [&](FlattenLimits& l) { return flattenInTime(circle, tEnd, l); }, limits);
    QVERIFY(flat.truncated);
    QVERIFY2(flat.points.size() <= kPointBudget + 1,
             qPrintable(QString::number(flat.points.size())));
    QCOMPARE(limits.tolerance, tolerance);
    QVERIFY(flat.param.back() > 0 && flat.param.back() < tEnd);
    QVERIFY(flat.reaches(flat.param.back()));
    QVERIFY(!flat.reaches(std::nextafter(flat.param.back(), tEnd)));
    // within the seen region, chords within the tolerance of the circle (the sagitta of a chord
    // of the unit circle subtending angle d is 1 - cos(d/2)); elsewhere only the seeds, 12.5 rad
    // apart, as before
    int seenChords = 0;
    for (std::size_t i = 1; i < flat.points.size(); ++i) {
        const QPointF a = flat.points[i - 1], b = flat.points[i];
        if (!limits.seen.contains(a) || !limits.seen.contains(b))
            continue;
        ++seenChords;
        const double angle = flat.param[i] - flat.param[i - 1];
        QVERIFY2(1 - std::cos(angle / 2) <= tolerance * (1 + 1e-9),
                 qPrintable(
                     QStringLiteral("a chord of %1 rad at t = %2").arg(angle).arg(flat.param[i])));
        for (QPointF q : {a, b})
            QVERIFY(std::abs(std::hypot(q.x(), q.y()) - 1) < 1e-12);
    }
    // the laps drawn lie over the ones left out: the picture is the whole curve's
    QVERIFY2(seenChords > 100 * 10, qPrintable(QString::number(seenChords)));
    QVERIFY(flat.param.back() > 100 * 2 * pi);
}

QTEST_GUILESS_MAIN(CurveFlatteningTest)
#include "test_curve_flattening.moc"
