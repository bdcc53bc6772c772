// The genuine vakonomic body in the app: drawn as a third body with its own colour, toggled
// from the View menu, and its Psi, chi, lambda and T in the plots.
#include "canvas/scene_canvas.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "plots/plots_panel.h"
#include "scene/presets.h"
#include "shell/main_window.h"
#include "shell/playback.h"

#include <QAction>
#include <QImage>
#include <QtTest>
#include <qcustomplot.h>

#include <cmath>
#include <memory>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestVakonomicBody : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase();
    void init();
    void cleanup();

    void thirdBodyDrawnAndToggles();
    void plotsShowItsPsiChiLambdaAndEnergy();

  private:
    std::unique_ptr<MainWindow> m_window;
};

void TestVakonomicBody::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_vakonomic_tests"));
}

void TestVakonomicBody::init() {
    m_window = test::showTestWindow();
    QVERIFY(m_window && m_window->document()->solution());
    m_window->document()->setSceneNow(presetScene("circle"));
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution()->scene().preset, std::string("circle"));
}

void TestVakonomicBody::cleanup() {
    m_window.reset();
}

void TestVakonomicBody::thirdBodyDrawnAndToggles() {
    SceneCanvas* canvas = m_window->canvas();
    // drawn to scale (the circle's automatic display is an outline), and framed with every body
    CanvasStyle style = canvas->canvasStyle();
    style.body = BodyDisplay::ToScale;
    canvas->setCanvasStyle(style);
    canvas->fitEverything();
    QAction* toggle = m_window->findChild<QAction*>(QStringLiteral("showVakonomicAction"));
    QVERIFY(toggle);
    QVERIFY(toggle->isCheckable() && toggle->isChecked());
    QVERIFY(canvas->showsVakonomic());
    const double t = 5.0;
    m_window->playback()->seek(t);
    MotionSample m = m_window->document()->solution()->at(t);
    // it has left the circle of radius 2 and is clear of the other two bodies
    QVERIFY2(std::abs(std::hypot(m.vak.x, m.vak.y) - 2) > 0.5,
             qPrintable(QString::number(std::hypot(m.vak.x, m.vak.y))));
    QVERIFY(std::hypot(m.vak.x - m.x, m.vak.y - m.y) > 1.5);
    QVERIFY(std::hypot(m.vak.x - m.free.x, m.vak.y - m.free.y) > 1.5);
    // a point on its board, between the knife and the centre of mass (a = 0.5 ahead of P)
    const double ahead = 0.25;
    const QPointF onBoard(m.vak.x + ahead * std::cos(m.vak.phi) - 0.3 * std::sin(m.vak.phi),
                          m.vak.y + ahead * std::sin(m.vak.phi) + 0.3 * std::cos(m.vak.phi));
    auto colourAt = [&](QPointF world) {
        QImage image = canvas->grab().toImage();
        QPointF p = canvas->toPixel(world) * image.devicePixelRatio();
        return image.pixelColor(p.toPoint());
    };
    QColor shown = colourAt(onBoard);
    // pale purple (0x9467bd as a translucent ghost): blue, then red, above green
    QVERIFY2(shown.blue() > shown.green() + 15 && shown.red() > shown.green() + 5,
             qPrintable(shown.name()));
    // the View menu's toggle hides it (and its legend line), and shows it again
    toggle->trigger();
    QVERIFY(!canvas->showsVakonomic());
    QColor hidden = colourAt(onBoard);
    QVERIFY2(hidden.blue() < hidden.green() + 10, qPrintable(hidden.name()));
    toggle->trigger();
    QVERIFY(canvas->showsVakonomic());
    QCOMPARE(colourAt(onBoard), shown);
}

void TestVakonomicBody::plotsShowItsPsiChiLambdaAndEnergy() {
    const auto& solution = m_window->document()->solution();
    // plots 0..3: Psi, chi, lambda, T; each has a vakonomic graph with the body's own values
    for (int index = 0; index < 4; ++index) {
        QCustomPlot* plot = m_window->plotsPanel()->plot(index);
        QCPGraph* vak = nullptr;
        for (int g = 0; g < plot->graphCount(); ++g)
            if (plot->graph(g)->name().startsWith(QStringLiteral("vakonomic")))
                vak = plot->graph(g);
        QVERIFY2(vak, qPrintable(QStringLiteral("plot %1").arg(index)));
        QVERIFY(vak->data()->size() > 100);
        double worst = 0;
        for (const QCPGraphData& d : *vak->data()) {
            VakonomicState v = solution->vakonomicAt(d.key);
            double expected = index == 0   ? v.psi
                              : index == 1 ? v.chi
                              : index == 2 ? v.lambda
                                           : v.energy;
            worst = std::max(worst, std::abs(d.value - expected));
        }
        QVERIFY2(worst < 1e-14, qPrintable(QString::number(worst)));
    }
    // on the circle the tracking's lambda is constant, the vakonomic lambda is not
    QCustomPlot* lambda = m_window->plotsPanel()->plot(2);
    double lo = INFINITY, hi = -INFINITY;
    for (int g = 0; g < lambda->graphCount(); ++g)
        if (lambda->graph(g)->name().startsWith(QStringLiteral("vakonomic")))
            for (const QCPGraphData& d : *lambda->graph(g)->data()) {
                lo = std::min(lo, d.value);
                hi = std::max(hi, d.value);
            }
    QVERIFY2(hi - lo > 0.1, qPrintable(QString::number(hi - lo)));
}

QTEST_MAIN(TestVakonomicBody)
#include "test_vakonomic_body.moc"
