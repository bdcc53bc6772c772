// The wheels' rolling angles on the canvas (docs/user-guide.md, Seeing the wheels roll): the
// marked stripe on the disk's tread and the marked spokes of the side view are found in the
// canvas's pixels and their angles compared with closed forms derived here (a line: theta =
// v t/R; a circle of radius rho: the carriage's wheels at rho -+ a), not with the program's
// formulas. The side view shows only when asked, and the sleigh's picture does not change.
#include "canvas/scene_canvas.h"
#include "canvas/wheel_marks.h"
#include "desktop_entry.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "shell/body_display_menu.h"
#include "shell/main_window.h"

#include <QImage>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numbers>
#include <optional>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

constexpr double kPi = std::numbers::pi;

bool orange(QColor c) {
    return c.red() > 200 && c.green() > 70 && c.green() < 160 && c.blue() < 80;
}

// the centroid of the marked colour's pixels in box, or nothing when there are none
std::optional<QPointF> markCentroid(const QImage& image, const QRectF& box) {
    double sx = 0, sy = 0;
    int n = 0;
    const QRect r = box.toAlignedRect() & image.rect();
    for (int y = r.top(); y <= r.bottom(); ++y)
        for (int x = r.left(); x <= r.right(); ++x)
            if (orange(image.pixelColor(x, y))) {
                sx += x + 0.5;
                sy += y + 0.5;
                ++n;
            }
    if (n < 4)
        return std::nullopt;
    return QPointF(sx / n, sy / n);
}

// the difference of two angles in (-pi, pi]
double angleBetween(double a, double b) {
    return std::remainder(a - b, 2 * kPi);
}

Scene diskOnALine() {
    // along +x, so the disk's heading is the screen's x; v_T = 1, R = 0.5: theta = 2 t
    Scene s;
    s.system.kind = SystemKind::Disk;
    s.system.params = {{"m", 1.0}, {"R", 0.5}, {"I1", 0.125}, {"I2", 0.0625}};
    s.path.kind = PathKind::Parametric;
    s.path.xOfU = "u";
    s.path.yOfU = "0";
    s.path.from = 0;
    s.path.to = 6;
    s.speed = 1;
    return s;
}

Scene carriageOnACircle() {
    // a left turn of radius rho = 1.5 (docs/physics.md §2: sdot = v_T/sqrt(1 + b^2/rho^2))
    Scene s;
    s.system.kind = SystemKind::Carriage;
    s.system.params = {{"R", 0.3},   {"a", 0.4}, {"m", 0.5}, {"I1", 0.02},
                       {"I2", 0.01}, {"M", 3.0}, {"I", 0.2}};
    s.path.kind = PathKind::Parametric;
    s.path.xOfU = "1.5*sin(u)";
    s.path.yOfU = "1.5*(1-cos(u))";
    s.path.from = 0;
    s.path.to = 4;
    s.speed = 1;
    return s;
}

// the carriage's wheels' angles on that circle at t: (theta1, theta2), outer and inner
std::pair<double, double> carriageAnglesAt(double t) {
    const double rho = 1.5, a = 0.4, r = 0.3;
    // b^2 = J/m_eff (App. B, B18)
    const double mEff = 3.0 + 2 * (0.5 + 0.02 / 0.09);
    const double j = 0.2 + 2 * 0.01 + 2 * 0.16 * (0.5 + 0.02 / 0.09);
    const double sdot = 1 / std::sqrt(1 + j / mEff / (rho * rho));
    return {sdot * t * (rho + a) / (rho * r), sdot * t * (rho - a) / (rho * r)};
}

struct Canvas {
    SceneDocument document;
    SceneCanvas canvas{&document};
    explicit Canvas(const Scene& scene, bool inset) {
        document.setSceneNow(scene);
        canvas.resize(1000, 640);
        CanvasStyle style = canvas.canvasStyle();
        style.body = BodyDisplay::ToScale;
        style.wheelInset = inset;
        canvas.setCanvasStyle(style);
    }
    QImage at(double t) {
        canvas.setTime(t);
        return canvas.grab().toImage();
    }
};

} // namespace

class TestWheelMarks : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase();
    void stripesSeenFromAboveAreTheUpperHalf();
    void spokeTurnsClockwiseRollingForwards();
    void diskStripeMovesAlongTheTreadAtItsRollingAngle();
    void sideViewSpokesTurnByTheWheelsAngles();
    void sideViewOnlyWhenAsked();
    void sleighPictureUnchanged();
    void menuTogglesTheSideView();
    void screenshotOptions();
};

void TestWheelMarks::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_wheel_marks_tests"));
}

void TestWheelMarks::stripesSeenFromAboveAreTheUpperHalf() {
    // theta = 0: the marked point is under the axle, hidden; half a turn later on top, at the
    // centre; a quarter turn past that at the front end (x = +R)
    const double r = 0.4;
    auto marked = [&](double theta) -> std::optional<double> {
        for (const TreadStripe& s : treadStripes(theta, r))
            if (s.marked)
                return s.along;
        return std::nullopt;
    };
    QVERIFY(!marked(0));
    QVERIFY(!marked(1.4));
    QVERIFY(marked(kPi));
    QVERIFY(std::abs(*marked(kPi)) < 1e-15);
    QVERIFY(std::abs(*marked(kPi + 1.5) - r * std::sin(1.5)) < 1e-15);
    // half the stripes show at any angle
    for (double theta : {0.1, 1.0, 2.0, 3.3, 5.9})
        QCOMPARE(int(treadStripes(theta, r).size()), kTreadStripes / 2);
}

void TestWheelMarks::spokeTurnsClockwiseRollingForwards() {
    // screen coordinates, y down: spoke 0 points down at 0, back (left) a quarter turn later
    const QPointF c(50, 50);
    const QPointF down = spokeTip(c, 10, 0) - c, back = spokeTip(c, 10, kPi / 2) - c;
    QVERIFY(std::abs(down.x()) < 1e-12 && std::abs(down.y() - 10) < 1e-12);
    QVERIFY(std::abs(back.x() + 10) < 1e-12 && std::abs(back.y()) < 1e-12);
}

void TestWheelMarks::diskStripeMovesAlongTheTreadAtItsRollingAngle() {
    // the marked stripe's pixels at x_P - R sin(theta) along the heading, theta = v t/R = 2 t
    Canvas c(diskOnALine(), false);
    const double r = 0.5;
    for (double t : {1.2, 1.8, 4.6}) {
        const QImage image = c.at(t);
        const double theta = 2 * t;
        QVERIFY(std::cos(theta) < -0.5); // the stripe is on top, seen
        const QPointF p = c.canvas.toPixel({t, 0});
        const double scale = c.canvas.scale();
        const QRectF around(p.x() - 1.2 * r * scale, p.y() - 0.3 * r * scale, 2.4 * r * scale,
                            0.6 * r * scale);
        const std::optional<QPointF> mark = markCentroid(image, around);
        QVERIFY2(mark, qPrintable(QStringLiteral("no mark at t = %1").arg(t)));
        const double expected = p.x() - r * std::sin(theta) * scale;
        QVERIFY2(std::abs(mark->x() - expected) < 1.5,
                 qPrintable(QStringLiteral("t = %1: the mark at x = %2 px, expected %3 px")
                                .arg(t)
                                .arg(mark->x())
                                .arg(expected)));
        QVERIFY(std::abs(mark->y() - p.y()) < 1.5);
    }
    // under the axle it is hidden: theta = 2 t = 2 pi
    const QImage hidden = c.at(kPi);
    const QPointF p = c.canvas.toPixel({kPi, 0});
    const double reach = 1.2 * r * c.canvas.scale();
    QVERIFY(!markCentroid(hidden, QRectF(p.x() - reach, p.y() - reach, 2 * reach, 2 * reach)));
}

void TestWheelMarks::sideViewSpokesTurnByTheWheelsAngles() {
    Canvas c(carriageOnACircle(), true);
    const QFont font = [&] {
        QFont f = c.canvas.font();
        f.setPointSizeF(8.5);
        return f;
    }();
    const WheelInsetLayout layout = wheelInsetLayout(2, 1, font);
    double before[2] = {};
    for (double t : {1.0, 1.7}) {
        const QImage image = c.at(t);
        const QRectF box = c.canvas.wheelInsetBounds();
        QVERIFY(!box.isEmpty());
        QCOMPARE(box.size(), layout.size);
        const auto [theta1, theta2] = carriageAnglesAt(t);
        const double expected[2] = {theta1, theta2};
        for (int k = 0; k < 2; ++k) {
            const QPointF centre = box.topLeft() + layout.centres[std::size_t(k)];
            const double r = layout.radius;
            const std::optional<QPointF> mark =
                markCentroid(image, QRectF(centre.x() - r, centre.y() - r, 2 * r, 2 * r));
            QVERIFY(mark);
            // the marked spoke from the centre along (-sin theta, cos theta) on the screen
            const QPointF d = *mark - centre;
            const double measured = std::atan2(-d.x(), d.y());
            QVERIFY2(std::abs(angleBetween(measured, expected[k])) < 3 * kPi / 180,
                     qPrintable(QStringLiteral("wheel %1 at t = %2: %3 rad, expected %4")
                                    .arg(k + 1)
                                    .arg(t)
                                    .arg(measured)
                                    .arg(std::remainder(expected[k], 2 * kPi))));
            // the turn between the two times, within the one the closed form gives
            if (t > 1.0) {
                const double turned = angleBetween(measured, before[k]);
                const auto [a1, a2] = carriageAnglesAt(1.0);
                const double should = expected[k] - (k == 0 ? a1 : a2);
                QVERIFY(std::abs(angleBetween(turned, should)) < 4 * kPi / 180);
            }
            before[k] = measured;
        }
    }
}

void TestWheelMarks::sideViewOnlyWhenAsked() {
    QVERIFY(!CanvasStyle{}.wheelInset); // off by default
    Canvas off(carriageOnACircle(), false);
    const QImage without = off.at(1.0);
    QVERIFY(off.canvas.wheelInsetBounds().isEmpty());
    Canvas on(carriageOnACircle(), true);
    const QImage with = on.at(1.0);
    const QRectF box = on.canvas.wheelInsetBounds();
    QVERIFY(!box.isEmpty());
    QVERIFY(on.canvas.drawingArea().contains(box));
    // its marks in its box with it, none there without it (the body is elsewhere)
    QVERIFY(markCentroid(with, box));
    QVERIFY(!markCentroid(without, box));
    // it covers no body at the time shown
    const QPointF p =
        on.canvas.toPixel({on.document.solution()->at(1.0).x, on.document.solution()->at(1.0).y});
    QVERIFY(!box.contains(p));
}

void TestWheelMarks::sleighPictureUnchanged() {
    // the sleigh has no wheels: asking for their side view changes no pixel
    Scene sleigh;
    Canvas off(sleigh, false), on(sleigh, true);
    for (double t : {0.0, 3.5}) {
        QVERIFY(on.canvas.wheelInsetBounds().isEmpty());
        QCOMPARE(on.at(t), off.at(t));
    }
}

void TestWheelMarks::menuTogglesTheSideView() {
    std::unique_ptr<MainWindow> window = test::showTestWindow();
    QVERIFY(window);
    QVERIFY(!window->canvas()->canvasStyle().wheelInset);
    QAction* action = window->bodyDisplayMenu()->wheelInsetAction();
    QVERIFY(action->isCheckable() && !action->isChecked());
    QCOMPARE(action->shortcut(), QKeySequence(QStringLiteral("Ctrl+Shift+4")));
    action->trigger();
    QVERIFY(window->canvas()->canvasStyle().wheelInset);
    QVERIFY(action->isChecked());
    action->trigger();
    QVERIFY(!window->canvas()->canvasStyle().wheelInset);
}

void TestWheelMarks::screenshotOptions() {
    // --wheel-view draws the side view into the picture (the carriage's differs, the sleigh's
    // does not); --plots-zoom takes 0 ... 60 notches
    QTemporaryDir dir;
    const QByteArray png = dir.filePath(QStringLiteral("shot.png")).toUtf8();
    auto shot = [&](std::vector<const char*> extra) {
        std::vector<const char*> args = {"chaplygin-lab", "--screenshot", png.constData(),
                                         "--size",        "1000x700",     "--at",
                                         "1.5",           "--preset",     "sinusoid"};
        args.insert(args.end(), extra.begin(), extra.end());
        const int status = runScreenshot(int(args.size()), const_cast<char**>(args.data()));
        return std::pair(status, QImage(QString::fromUtf8(png)));
    };
    const auto [carriage, carriageImage] = shot({"--system", "carriage"});
    const auto [carriageWheels, carriageWheelsImage] =
        shot({"--system", "carriage", "--wheel-view"});
    QCOMPARE(carriage, 0);
    QCOMPARE(carriageWheels, 0);
    QVERIFY(carriageImage != carriageWheelsImage);
    const auto [sleigh, sleighImage] = shot({});
    const auto [sleighWheels, sleighWheelsImage] = shot({"--wheel-view"});
    QCOMPARE(sleigh, 0);
    QCOMPARE(sleighWheels, 0);
    QCOMPARE(sleighImage, sleighWheelsImage);
    QCOMPARE(shot({"--plots-zoom", "12"}).first, 0);
    for (const char* bad : {"61", "-1", "2.5", "x"})
        QCOMPARE(shot({"--plots-zoom", bad}).first, 2);
}

QTEST_MAIN(TestWheelMarks)
#include "test_wheel_marks.moc"
