// The two-wheeled carriage in the GUI: the parameters panel accepts a carriage whose radius of
// gyration b is below its half-axle a (App. B: a is not a centre-of-mass offset), and the canvas
// draws its two wheels at +-a across the heading.
#include "canvas/body_painter.h"
#include "canvas/scene_canvas.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "panels/parameters_panel.h"
#include "shell/main_window.h"
#include "widgets/number_field.h"

#include <QComboBox>
#include <QImage>
#include <QLabel>
#include <QPainter>
#include <QtTest>

#include <memory>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestCarriage : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase();
    void carriageBelowHalfAxleThroughThePanel();
    void wheelsAtHalfAxleAcrossTheHeading();
};

void TestCarriage::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_carriage_tests"));
}

void TestCarriage::carriageBelowHalfAxleThroughThePanel() {
    std::unique_ptr<MainWindow> window = test::showTestWindow();
    QVERIFY(window);
    ParametersPanel* panel = window->parametersPanel();
    auto* combo = panel->findChild<QComboBox*>();
    combo->setCurrentIndex(2);
    emit combo->activated(2);
    window->document()->flush();
    QCOMPARE(window->document()->scene().system.kind, SystemKind::Carriage);
    const std::pair<const char*, double> values[] = {
        {"R", 0.3}, {"a", 0.4}, {"m", 0.5}, {"I1", 0.02}, {"I2", 0.01}, {"M", 3.0}, {"I", 0.2}};
    for (const auto& [name, value] : values) {
        NumberField* spin = panel->spinBox(QString::fromLatin1(name));
        QVERIFY2(spin, name);
        spin->setValue(value);
    }
    window->document()->flush();
    QVERIFY2(panel->errorText().isEmpty(), qPrintable(panel->errorText()));
    const DerivedSystem& d = window->document()->solution()->system();
    QCOMPARE(window->document()->solution()->scene().system.params.at("a"), 0.4);
    QVERIFY(std::fabs(d.b - 0.31859064644147983668) < 1e-12);
    QCOMPARE(d.a, 0.0);
    QVERIFY(panel->spinBox(QStringLiteral("a"))->toolTip().contains(QStringLiteral("half-axle")));
    window->canvas()->grab();
}

void TestCarriage::wheelsAtHalfAxleAcrossTheHeading() {
    // 1 m = 200 px, P at the image centre, heading along +x: the wheels are the dark bands at
    // y = +-a, 2R long and 0.44 R wide
    for (double a : {0.4, 0.8}) {
        SystemSpec spec{
            SystemKind::Carriage,
            {{"R", 0.3}, {"a", a}, {"m", 0.5}, {"I1", 0.02}, {"I2", 0.01}, {"M", 3.0}, {"I", 0.2}}};
        DerivedSystem d = deriveSystem(spec);
        QImage image(400, 400, QImage::Format_ARGB32);
        image.fill(Qt::white);
        QPainter p(&image);
        p.setRenderHint(QPainter::Antialiasing, false);
        p.translate(200, 200);
        p.scale(200, -200);
        paintBody(p, spec, d, {0, 0, 0}, QColor(40, 90, 200), false);
        p.end();
        auto dark = [&](double x, double y) {
            QColor c = image.pixelColor(int(200 + 200 * x), int(200 - 200 * y));
            return c.lightness() < 100;
        };
        for (double side : {1.0, -1.0}) {
            QVERIFY2(dark(0.2, side * a), qPrintable(QString("wheel at %1").arg(side * a)));
            QVERIFY2(dark(-0.2, side * a), qPrintable(QString("wheel at %1").arg(side * a)));
            QVERIFY2(!dark(0.2, side * (a + 0.12)), "nothing beyond the wheel");
        }
        QVERIFY(bodyExtent(spec, d) >= std::hypot(0.3, a));
    }
}

QTEST_MAIN(TestCarriage)
#include "test_carriage.moc"
