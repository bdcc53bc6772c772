// GUI tests of the Sweep dock (a parameter sweep in the shared job runner, with progress,
// cancel and click-to-load through the undo stack) and of File > Export animation.
#include "canvas/body_sprites.h"
#include "canvas/scene_canvas.h"
#include "canvas/vector_painter.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "panels/sweep_panel.h"
#include "scene/presets.h"
#include "shell/animation_dialog.h"
#include "shell/main_window.h"
#include "widgets/number_field.h"

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QLineEdit>
#include <QMenuBar>
#include <QProgressBar>
#include <QProgressDialog>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QtTest>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestSweepAnimation : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase();
    void init();
    void cleanup();
    void sweepRunsAndPlotsTheClosedForm();
    void badRangeIsRefusedBeforeAnyWork();
    void cancelStopsASweep();
    void sceneChangeCancelsASweep();
    void clickingAPointLoadsItsValueAsOneUndoStep();
    void exportWritesFramesRenderedOffscreen();
    void exportDialogPathWithCancelLeavesNoFiles();
    void exportGifAndMissingFfmpeg();
    void exportDialogRemembersItsSettings();
    void exportedArrowsAndScaleBarsKeepClear();
    void scaleBarsOfFiveArrowsFitASmallExportUnderTheBodies();

  private:
    void load(const char* preset);
    void chooseRange(const char* name, double from, double to, int count);
    std::unique_ptr<MainWindow> m_window;
};

void TestSweepAnimation::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_sweep_animation_tests"));
}

void TestSweepAnimation::init() {
    m_window = test::showTestWindow();
    QVERIFY(m_window && m_window->document()->solution());
}

void TestSweepAnimation::cleanup() {
    m_window.reset();
}

void TestSweepAnimation::load(const char* preset) {
    m_window->loadScene(presetScene(preset));
    QVERIFY(m_window->document()->error().isEmpty());
}

void TestSweepAnimation::chooseRange(const char* name, double from, double to, int count) {
    SweepPanel* panel = m_window->sweepPanel();
    panel->parameterBox()->setCurrentText(QString::fromLatin1(name));
    QCOMPARE(panel->parameterBox()->currentText(), QString::fromLatin1(name));
    panel->fromBox()->setValue(from);
    panel->toBox()->setValue(to);
    panel->countBox()->setValue(count);
}

void TestSweepAnimation::sweepRunsAndPlotsTheClosedForm() {
    load("circle");
    m_window->showSweepDock();
    SweepPanel* panel = m_window->sweepPanel();
    chooseRange("b", 0.6, 2.4, 4);
    QTest::mouseClick(panel->runButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!panel->isRunning(), 30000);
    QVERIFY(panel->report());
    QCOMPARE(int(panel->report()->rows.size()), 4);
    QCOMPARE(panel->progressBar()->value(), panel->progressBar()->maximum());
    // circle R = 2 (paper (82)-(96)): max |lambda| = m a v_T / sqrt(R^2 + b^2)
    QCOMPARE(panel->plot()->graphCount(), 1);
    QCOMPARE(panel->plot()->graph(0)->dataCount(), 4);
    for (int i = 0; i < 4; ++i) {
        double b = 0.6 + 0.6 * i;
        double y = panel->plot()->graph(0)->data()->at(i)->value;
        QVERIFY(std::fabs(y - 0.5 / std::sqrt(4 + b * b)) < 1e-12);
    }
    // another quantity redraws without a new sweep: duration 2 pi sqrt(b^2 + R^2)
    panel->quantityBox()->setCurrentIndex(static_cast<int>(SweepQuantity::Duration));
    double t0 = panel->plot()->graph(0)->data()->at(0)->value;
    QVERIFY(std::fabs(t0 - 2 * M_PI * std::sqrt(0.36 + 4)) < 1e-10);
}

void TestSweepAnimation::badRangeIsRefusedBeforeAnyWork() {
    load("circle");
    SweepPanel* panel = m_window->sweepPanel();
    chooseRange("b", 0.2, 2, 5);
    QTest::mouseClick(panel->runButton(), Qt::LeftButton);
    QVERIFY(!panel->isRunning());
    QVERIFY(!panel->report());
    QVERIFY2(panel->statusText().contains(QLatin1String("b = 0.2 (value 1 of 5) is invalid")),
             qPrintable(panel->statusText()));
}

void TestSweepAnimation::cancelStopsASweep() {
    load("catenary");
    SweepPanel* panel = m_window->sweepPanel();
    chooseRange("b", 0.6, 3, 1000);
    panel->start();
    QVERIFY(panel->isRunning());
    QTRY_VERIFY_WITH_TIMEOUT(panel->progressBar()->value() > 0, 20000);
    QTest::mouseClick(panel->cancelButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!panel->isRunning(), 20000);
    QVERIFY(panel->report());
    QVERIFY(panel->report()->cancelled);
    QVERIFY(panel->report()->rows.size() < 1000);
    QVERIFY(panel->statusText().startsWith(QLatin1String("Cancelled")));
    QVERIFY(panel->runButton()->isEnabled());
}

void TestSweepAnimation::sceneChangeCancelsASweep() {
    load("catenary");
    SweepPanel* panel = m_window->sweepPanel();
    chooseRange("vT", 0.5, 3, 1000);
    panel->start();
    QVERIFY(panel->isRunning());
    load("circle");
    QTRY_VERIFY_WITH_TIMEOUT(!panel->isRunning(), 20000);
    QVERIFY(panel->report() && panel->report()->cancelled);
    QVERIFY2(panel->statusText().contains(QLatin1String("the scene changed")),
             qPrintable(panel->statusText()));
}

void TestSweepAnimation::clickingAPointLoadsItsValueAsOneUndoStep() {
    load("circle");
    m_window->showSweepDock();
    SweepPanel* panel = m_window->sweepPanel();
    chooseRange("vT", 0.5, 2, 4);
    panel->start();
    panel->waitForFinished();
    QVERIFY(panel->report() && panel->report()->rows.size() == 4);
    QCoreApplication::processEvents();
    panel->plot()->replot();
    const Scene before = m_window->document()->scene();
    const int undoCount = m_window->undoStack()->count();
    // click the third point where the plot draws it
    const SweepRow& row = panel->report()->rows[2];
    QPoint at(int(std::lround(panel->plot()->xAxis->coordToPixel(row.value))),
              int(std::lround(panel->plot()->yAxis->coordToPixel(row.maxAbsLambda))));
    QTest::mouseClick(panel->plot(), Qt::LeftButton, Qt::NoModifier, at);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().speed, 1.5);
    QCOMPARE(m_window->undoStack()->count(), undoCount + 1);
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QVERIFY(m_window->document()->scene() == before);
}

void TestSweepAnimation::exportWritesFramesRenderedOffscreen() {
    load("line");
    QTemporaryDir dir;
    AnimationSettings s;
    s.file = dir.filePath(QStringLiteral("frames/"));
    s.fps = 2;
    s.size = QSize(640, 360);
    s.withPlots = true;
    // the window is hidden behind the export: frames come from an offscreen widget
    m_window->hide();
    QVERIFY2(m_window->exportAnimationTo(s), qPrintable(m_window->lastFileError()));
    QStringList frames = QDir(s.file).entryList({QStringLiteral("frame_*.png")}, QDir::Files);
    // the line takes 4 sqrt(5) = 8.94 s: frames at 0, 0.5, ..., 8.5 and 8.94
    QCOMPARE(frames.size(), 19);
    QImage first(QDir(s.file).filePath(frames.first()));
    QImage last(QDir(s.file).filePath(frames.last()));
    QCOMPARE(first.size(), QSize(640, 360));
    QVERIFY(first != last); // the body has moved
    // the plots beside the canvas are drawn: the free motion's red curves (plot_figures.cpp)
    int red = 0;
    for (int y = 0; y < first.height(); ++y)
        for (int x = first.width() * 3 / 5; x < first.width(); ++x) {
            QColor c = first.pixelColor(x, y);
            red += c.red() > 180 && c.green() < 110 && c.blue() < 110;
        }
    QVERIFY2(red > 100, qPrintable(QString::number(red)));
}

void TestSweepAnimation::exportDialogPathWithCancelLeavesNoFiles() {
    load("circle");
    QTemporaryDir dir;
    const QString folder = dir.filePath(QStringLiteral("clip/"));
    bool dialogSeen = false, cancelled = false;
    QTimer poll;
    poll.setInterval(10);
    connect(&poll, &QTimer::timeout, this, [&] {
        if (auto* dialog = qobject_cast<AnimationDialog*>(QApplication::activeModalWidget())) {
            dialogSeen = true;
            dialog->fileEdit()->setText(folder);
            dialog->fpsBox()->setValue(30);
            dialog->widthBox()->setValue(320);
            dialog->heightBox()->setValue(240);
            dialog->accept();
            return;
        }
        auto* progress = m_window->findChild<QProgressDialog*>(QStringLiteral("animationProgress"));
        if (progress && progress->value() >= 3 && !cancelled) {
            cancelled = true;
            progress->cancel();
        }
    });
    poll.start();
    QAction* action = nullptr;
    for (QAction* menu : m_window->menuBar()->actions())
        if (menu->menu())
            for (QAction* a : menu->menu()->actions())
                if (a->text().contains(QLatin1String("animation")))
                    action = a;
    QVERIFY(action);
    action->trigger();
    poll.stop();
    QVERIFY(dialogSeen);
    QVERIFY(cancelled);
    QVERIFY(m_window->lastFileError().isEmpty());
    QVERIFY(QDir(folder).entryList({QStringLiteral("*.png")}, QDir::Files).isEmpty());
}

void TestSweepAnimation::exportGifAndMissingFfmpeg() {
    load("circle");
    QTemporaryDir dir;
    AnimationSettings s;
    s.file = dir.filePath(QStringLiteral("circle.gif"));
    s.fps = 2;
    s.size = QSize(200, 150);
    // without ffmpeg on PATH: refused with the reason, nothing written
    const QByteArray path = qgetenv("PATH");
    qputenv("PATH", "/nonexistent");
    const bool written = m_window->exportAnimationTo(s);
    qputenv("PATH", path);
    QVERIFY(!written);
    QVERIFY2(m_window->lastFileError().contains(QLatin1String("needs the ffmpeg program")),
             qPrintable(m_window->lastFileError()));
    QVERIFY(QDir(dir.path())
                .entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden)
                .isEmpty());
    if (findFfmpeg().isEmpty())
        QSKIP("ffmpeg is not installed");
    QVERIFY2(m_window->exportAnimationTo(s), qPrintable(m_window->lastFileError()));
    QFile gif(s.file);
    QVERIFY(gif.open(QIODevice::ReadOnly));
    QCOMPARE(gif.read(6), QByteArray("GIF89a"));
    QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden),
             QStringList{QStringLiteral("circle.gif")});
}

// fps, size and "with plots" chosen once are what the dialog shows the next time, in this window
// and in the next one (QSettings)
void TestSweepAnimation::exportDialogRemembersItsSettings() {
    load("circle");
    QTemporaryDir dir;
    const QString folder = dir.filePath(QStringLiteral("clip/"));
    auto exportAction = [this] {
        for (QAction* menu : m_window->menuBar()->actions())
            if (menu->menu())
                for (QAction* a : menu->menu()->actions())
                    if (a->text().contains(QLatin1String("animation")))
                        return a;
        return static_cast<QAction*>(nullptr);
    };
    QVERIFY(exportAction());
    int fps = 0, width = 0, height = 0;
    bool plots = false, seen = false;
    QTimer poll;
    poll.setInterval(10);
    // the first time: choose 12 fps, 640x360 with plots, export and cancel the rendering
    connect(&poll, &QTimer::timeout, this, [&] {
        if (auto* dialog = qobject_cast<AnimationDialog*>(QApplication::activeModalWidget())) {
            seen = true;
            QVERIFY(dialog->fpsBox()->value() != 12);
            QVERIFY(!dialog->plotsBox()->isChecked());
            dialog->fileEdit()->setText(folder);
            dialog->fpsBox()->setValue(12);
            dialog->widthBox()->setValue(640);
            dialog->heightBox()->setValue(360);
            dialog->plotsBox()->setChecked(true);
            dialog->accept();
        } else if (auto* progress =
                       m_window->findChild<QProgressDialog*>(QStringLiteral("animationProgress")))
            progress->cancel();
    });
    poll.start();
    exportAction()->trigger();
    poll.stop();
    QVERIFY(seen);
    // the next times, here and in a new window: what was chosen, read and then dismissed
    poll.disconnect();
    connect(&poll, &QTimer::timeout, this, [&] {
        if (auto* dialog = qobject_cast<AnimationDialog*>(QApplication::activeModalWidget())) {
            fps = int(dialog->fpsBox()->value());
            width = int(dialog->widthBox()->value());
            height = int(dialog->heightBox()->value());
            plots = dialog->plotsBox()->isChecked();
            dialog->reject();
        }
    });
    for (int window = 0; window < 2; ++window) {
        if (window == 1) {
            m_window = test::showTestWindow();
            QVERIFY(m_window);
        }
        fps = width = height = 0;
        plots = false;
        poll.start();
        exportAction()->trigger();
        poll.stop();
        QCOMPARE(fps, 12);
        QCOMPARE(width, 640);
        QCOMPARE(height, 360);
        QVERIFY(plots);
    }
}

// the canvas of an exported frame at the export sizes (with the plots it is 3/5 of the frame),
// with every arrow shown: the legend strip under the drawing area is the same with the arrows
// as without (an arrow ran across the legend's text), and the arrows' scale bars lie in a corner
// of the drawing area that no body crosses in any frame, when there is one (a 640x360 GIF with
// plots put them over the body); when every corner is crossed, in one crossed least
void TestSweepAnimation::exportedArrowsAndScaleBarsKeepClear() {
    int frames = 0, clear = 0;
    for (const char* preset : {"catenary", "sinusoid", "circle", "line"}) {
        Scene plain = presetScene(preset), arrows = plain;
        for (int i = 0; i < 2; ++i) // two arrows: two rows of scale bars
            (arrows.vectors.*vectorToggle(VectorKind(i))).shown = true;
        for (const QSize size : {QSize(384, 360), QSize(768, 720), QSize(1280, 720)}) {
            QImage without[12];
            for (const bool shown : {false, true}) {
                m_window->loadScene(shown ? arrows : plain);
                QVERIFY(m_window->document()->error().isEmpty());
                SceneCanvas canvas(m_window->document());
                canvas.setAttribute(Qt::WA_DontShowOnScreen);
                canvas.setLook(m_window->canvas()->look());
                canvas.resize(size);
                canvas.show();
                canvas.fitScene();
                const QString where = QStringLiteral("%1 at %2x%3")
                                          .arg(QLatin1String(preset))
                                          .arg(size.width())
                                          .arg(size.height());
                const Solution& solution = *m_window->document()->solution();
                const QRectF area = canvas.drawingArea();
                const QRect legend(0, int(std::ceil(area.bottom())) + 1, size.width(),
                                   size.height() - int(std::ceil(area.bottom())) - 1);
                QVERIFY(legend.height() > 20);
                const double s = canvas.scale();
                const QPointF origin = canvas.toPixel({0, 0});
                const QTransform world(s, 0, 0, -s, origin.x(), origin.y());
                const BodyLook look{canvas.shownBodyDisplay(), canvas.canvasStyle().bodyOpacity,
                                    canvas.canvasStyle().lineScale};
                constexpr Qt::Corner corners[] = {Qt::BottomRightCorner, Qt::BottomLeftCorner,
                                                  Qt::TopRightCorner};
                int crossed[3] = {}, chosen = 0;
                for (int k = 0; k < 12; ++k) {
                    const double t = solution.tEnd() * k / 11;
                    canvas.setTime(t);
                    const QImage image = canvas.grab().toImage().copy(legend);
                    if (!shown) {
                        without[k] = image;
                        continue;
                    }
                    QVERIFY2(image == without[k],
                             qPrintable(where +
                                        QStringLiteral(", t = %1: an arrow on the legend").arg(t)));
                    const MotionSample now = solution.at(t);
                    const BodyPose poses[] = {{now.x, now.y, now.phi},
                                              {now.free.x, now.free.y, now.free.phi},
                                              {now.vak.x, now.vak.y, now.vak.phi}};
                    for (const BodyPose& pose : poses) {
                        const QRectF body = BodySprites::pixelBounds(
                            world, s, solution.scene().system, solution.system(), pose, look);
                        for (int c = 0; c < 3; ++c)
                            crossed[c] +=
                                body.intersects(QRectF(canvas.vectorLayer().scaleBarsBounds(
                                    arrows.vectors, area, corners[c])))
                                    ? 1
                                    : 0;
                        chosen += body.intersects(QRectF(
                                      canvas.vectorLayer().scaleBarsBounds(arrows.vectors, area)))
                                      ? 1
                                      : 0;
                    }
                    ++frames;
                }
                if (!shown)
                    continue;
                const int least = *std::min_element(std::begin(crossed), std::end(crossed));
                QVERIFY2(least > 0 || chosen == 0,
                         qPrintable(where + QStringLiteral(": the scale bars cover a body in %1 "
                                                           "frames, a corner is free")
                                                .arg(chosen)));
                clear += least == 0;
            }
        }
    }
    QCOMPARE(frames, 4 * 3 * 12);
    QVERIFY2(clear >= 3, qPrintable(QString::number(clear)));
}

// every arrow in the smallest export (its canvas 3/5 of 384x360): the scale bars' box stays inside
// the drawing area and leaves most of it to the scene, and a body crossing the bars' corner is
// drawn over them, not under them: with opaque bodies, fewer of the bars' pixels show at a time
// when the controlled body lies on their corner than when nothing does (the bars moved to another
// corner are the reference: the two pictures differ only where the bars are)
void TestSweepAnimation::scaleBarsOfFiveArrowsFitASmallExportUnderTheBodies() {
    Scene arrows = presetScene("sinusoid");
    for (int i = 0; i < kVectorKinds; ++i)
        (arrows.vectors.*vectorToggle(VectorKind(i))).shown = true;
    m_window->loadScene(arrows);
    QVERIFY(m_window->document()->error().isEmpty());
    SceneCanvas canvas(m_window->document());
    canvas.setAttribute(Qt::WA_DontShowOnScreen);
    CanvasLook look = m_window->canvas()->look();
    look.style.bodyOpacity = 1;
    canvas.setLook(look);
    canvas.resize(QSize(384 * 3 / 5, 360));
    canvas.show();
    canvas.fitScene();
    canvas.setTime(0);
    canvas.grab(); // the bars' corner chosen and their texts measured
    const QRectF area = canvas.drawingArea();
    const VectorLayer& layer = canvas.vectorLayer();
    const QRect bars = layer.scaleBarsBounds(arrows.vectors, area);
    QVERIFY2(area.contains(QRectF(bars)),
             qPrintable(QStringLiteral("bars %1,%2 %3x%4 outside the drawing area")
                            .arg(bars.x())
                            .arg(bars.y())
                            .arg(bars.width())
                            .arg(bars.height())));
    QVERIFY2(bars.width() <= 0.8 * area.width() && bars.height() <= 0.45 * area.height(),
             qPrintable(QStringLiteral("bars %1x%2 in an area %3x%4")
                            .arg(bars.width())
                            .arg(bars.height())
                            .arg(area.width())
                            .arg(area.height())));
    // the view panned (a middle-button drag) so that the controlled body at t = tEnd/2 lies on the
    // bars' column; a time when no body is on the bars' box in that view is the reference
    const Solution& solution = *m_window->document()->solution();
    const double tOn = solution.tEnd() / 2;
    const MotionSample on = solution.at(tOn);
    const QPointF body = canvas.toPixel({on.x, on.y});
    const QPointF target(bars.right() - 0.3 * bars.width(), bars.center().y());
    QTest::mousePress(&canvas, Qt::MiddleButton, {}, body.toPoint());
    QTest::mouseMove(&canvas, ((body + target) / 2).toPoint());
    QTest::mouseMove(&canvas, target.toPoint());
    QTest::mouseRelease(&canvas, Qt::MiddleButton, {}, target.toPoint());
    QVERIFY2(QLineF(canvas.toPixel({on.x, on.y}), target).length() < 2,
             "the drag did not pan the body onto the bars");
    const double s = canvas.scale();
    const QPointF origin = canvas.toPixel({0, 0});
    const QTransform world(s, 0, 0, -s, origin.x(), origin.y());
    const BodyLook bodyLook{canvas.shownBodyDisplay(), 1, canvas.canvasStyle().lineScale};
    const auto onBox = [&](const BodyPose& pose, const QRectF& box) {
        return BodySprites::pixelBounds(world, s, solution.scene().system, solution.system(), pose,
                                        bodyLook)
            .intersects(box);
    };
    constexpr Qt::Corner corners[] = {Qt::BottomRightCorner, Qt::BottomLeftCorner,
                                      Qt::TopRightCorner};
    const Qt::Corner corner = canvas.vectorLayer().barsCorner();
    const QRect box = layer.scaleBarsBounds(arrows.vectors, area, corner);
    double tOff = -1;
    for (int k = 0; k <= 200 && tOff < 0; ++k) {
        const double t = solution.tEnd() * k / 200;
        const MotionSample m = solution.at(t);
        if (!onBox({m.x, m.y, m.phi}, box) && !onBox({m.free.x, m.free.y, m.free.phi}, box) &&
            !onBox({m.vak.x, m.vak.y, m.vak.phi}, box))
            tOff = t;
    }
    QVERIFY2(tOff >= 0, "no time without a body on the bars");
    Qt::Corner other = corner;
    for (const Qt::Corner c : corners)
        if (!layer.scaleBarsBounds(arrows.vectors, area, c).intersects(box))
            other = c;
    QVERIFY(other != corner);
    // the bars' pixels that show at time t: the picture with the bars in their corner against the
    // one with them in the other, inside their box
    const auto barsShown = [&](double t) {
        canvas.setTime(t);
        canvas.grab();
        canvas.vectorLayer().setBarsCorner(corner);
        const QImage with = canvas.grab().toImage().copy(box);
        canvas.vectorLayer().setBarsCorner(other);
        const QImage without = canvas.grab().toImage().copy(box);
        int shown = 0;
        for (int y = 0; y < with.height(); ++y)
            for (int x = 0; x < with.width(); ++x)
                shown += with.pixel(x, y) != without.pixel(x, y) ? 1 : 0;
        return shown;
    };
    const int clear = barsShown(tOff), crossed = barsShown(tOn);
    QVERIFY2(clear > 100, qPrintable(QString::number(clear)));
    QVERIFY2(crossed < clear - 20,
             qPrintable(QStringLiteral("%1 of the bars' pixels show under the body at t = %2, %3 "
                                       "with no body on them at t = %4")
                            .arg(crossed)
                            .arg(tOn)
                            .arg(clear)
                            .arg(tOff)));
}

QTEST_MAIN(TestSweepAnimation)
#include "test_sweep_animation.moc"
