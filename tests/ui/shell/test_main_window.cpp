// GUI tests: drive the real widgets of the main window under the offscreen platform.
#include "canvas/scene_canvas.h"
#include "desktop_entry.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "panels/parameters_panel.h"
#include "panels/path_panel.h"
#include "plots/plots_panel.h"
#include "scene/presets.h"
#include "scene/scene_json.h"
#include "shell/main_window.h"
#include "shell/playback.h"
#include "shell/timeline_bar.h"
#include "widgets/number_field.h"

#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

QVector<double> graphValues(QCustomPlot* plot, int graph = 0) {
    QVector<double> v;
    for (const QCPGraphData& d : *plot->graph(graph)->data())
        v << d.value;
    return v;
}

double maxAbsDifference(const QVector<double>& a, const QVector<double>& b) {
    double worst = a.size() == b.size() ? 0 : INFINITY;
    for (int i = 0; i < std::min(a.size(), b.size()); ++i)
        worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
}

void typeInto(QLineEdit* edit, const QString& text) {
    edit->selectAll();
    QTest::keyClick(edit, Qt::Key_Delete);
    QTest::keyClicks(edit, text);
}

} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase();
    void init();
    void cleanup();

    void typedValidPath();
    void typedInvalidPathKeepsLastValid();
    void drawPathWithMouse();
    void editDrawnPathPoints();
    void parameterChangeUpdatesPlots();
    void canvasDrawsBodiesAtTheirPoses();
    void typedParametricPath();
    void sliderDragCoalesces();
    void invalidParameterKeepsSolution();
    void systemSwitch();
    void gyrationAndModeSwitch();
    void playPauseSeek();
    void clickingPlotSeeks();
    void spaceTypesInTextFields();
    void undoRedo();
    void saveLoadRoundTrip();
    void openBadFileKeepsScene();
    void exportFilesValid();
    void exportedCsvHasNoNegativeZero();
    void screenshotMode();
    void settingsKeepRecentFilesAndLayout();

  private:
    std::unique_ptr<MainWindow> m_window;
    QTemporaryDir m_dir;
};

void TestMainWindow::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_tests"));
}

void TestMainWindow::init() {
    m_window = test::showTestWindow();
    QVERIFY(m_window && m_window->document()->solution());
}

void TestMainWindow::cleanup() {
    m_window.reset();
}

void TestMainWindow::typedValidPath() {
    PathPanel* panel = m_window->pathPanel();
    typeInto(panel->graphEdit(), QStringLiteral("0.3*x^2"));
    panel->fromSpin()->setValue(0);
    panel->toSpin()->setValue(3);
    QTest::keyClick(panel->graphEdit(), Qt::Key_Return);
    m_window->document()->flush();
    const Scene& scene = m_window->document()->scene();
    QCOMPARE(QString::fromStdString(scene.path.y), QStringLiteral("0.3*x^2"));
    QVERIFY(panel->errorText().isEmpty());
    // the new solution runs along the parabola: it ends at (3, 2.7)
    const auto& solution = m_window->document()->solution();
    PathNode end = solution->path()->end();
    QVERIFY(std::abs(end.x - 3) < 1e-9);
    QVERIFY(std::abs(end.y - 2.7) < 1e-9);
}

void TestMainWindow::typedInvalidPathKeepsLastValid() {
    PathPanel* panel = m_window->pathPanel();
    auto before = m_window->document()->solution();
    Scene sceneBefore = m_window->document()->scene();
    typeInto(panel->graphEdit(), QStringLiteral("sin(x"));
    QTest::keyClick(panel->graphEdit(), Qt::Key_Return);
    m_window->document()->flush();
    QVERIFY2(!panel->errorText().isEmpty(), "an inline error is shown");
    QVERIFY2(panel->errorText().contains(QStringLiteral("position")),
             qPrintable(panel->errorText()));
    QVERIFY(panel->findChild<QLabel*>(QStringLiteral("pathError"))->isVisible());
    QCOMPARE(m_window->document()->solution(), before);
    QVERIFY(m_window->document()->scene() == sceneBefore);
    QCOMPARE(m_window->undoStack()->count(), 0);
    // a valid path afterwards clears the error
    typeInto(panel->graphEdit(), QStringLiteral("sin(x)"));
    QTest::keyClick(panel->graphEdit(), Qt::Key_Return);
    QTRY_VERIFY(panel->errorText().isEmpty()); // a slow path is built on the worker
    QCOMPARE(QString::fromStdString(m_window->document()->scene().path.y),
             QStringLiteral("sin(x)"));
}

void TestMainWindow::drawPathWithMouse() {
    m_window->pathPanel()->cornersBox()->setCurrentIndex(0); // smooth
    m_window->pathPanel()->drawButton()->click();
    SceneCanvas* canvas = m_window->canvas();
    QVERIFY(canvas->drawMode());
    QPoint start(100, 200);
    QPointF startWorld = canvas->toWorld(QPointF(start)); // before the view refits to the new path
    QTest::mousePress(canvas, Qt::LeftButton, {}, start);
    for (int i = 1; i <= 30; ++i) {
        QPoint p(100 + 15 * i, 200 - int(60 * std::sin(i / 5.0)));
        QMouseEvent move(QEvent::MouseMove, p, canvas->mapToGlobal(p), Qt::NoButton, Qt::LeftButton,
                         {});
        QApplication::sendEvent(canvas, &move);
    }
    QPoint end(100 + 15 * 30, 200 - int(60 * std::sin(6.0)));
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, end);
    m_window->document()->flush();
    const PathSource& path = m_window->document()->scene().path;
    QCOMPARE(path.kind, PathKind::Polyline);
    QVERIFY2(path.points.size() >= 20, "the stroke is sampled");
    QCOMPARE(path.corners, CornerMode::Smooth);
    // the first point is where the mouse went down, in metres
    QVERIFY(std::abs(path.points.front().first - startWorld.x()) < 1e-9);
    QVERIFY(std::abs(path.points.front().second - startWorld.y()) < 1e-9);
    QVERIFY(m_window->document()->error().isEmpty());
    QCOMPARE(m_window->document()->solution()->scene().path.kind, PathKind::Polyline);
    QVERIFY(m_window->document()->solution()->path()->length() > 1.0);
}

void TestMainWindow::editDrawnPathPoints() {
    m_window->pathPanel()->cornersBox()->setCurrentIndex(1); // pivot
    m_window->pathPanel()->drawButton()->click();
    SceneCanvas* canvas = m_window->canvas();
    // three right-angle turns: each a pivot corner (over the corner angle, 35 degrees)
    test::dragStroke(canvas, QPoint(100, 300),
                     {QPoint(200, 300), QPoint(200, 200), QPoint(300, 200)}, QPoint(300, 300));
    m_window->document()->flush();
    auto points = m_window->document()->scene().path.points;
    QCOMPARE(points.size(), std::size_t(5));
    QCOMPARE(m_window->document()->scene().path.corners, CornerMode::Pivot);
    QCOMPARE(m_window->document()->solution()->path()->pivotCount(), 3);
    // drag vertex 2 by (0, +40) px
    QPoint from = canvas->toPixel(QPointF(points[2].first, points[2].second)).toPoint();
    QPoint to = from + QPoint(0, 40);
    QPointF target = canvas->toWorld(QPointF(to));
    QTest::mousePress(canvas, Qt::LeftButton, {}, from);
    QMouseEvent move(QEvent::MouseMove, to, canvas->mapToGlobal(to), Qt::NoButton, Qt::LeftButton,
                     {});
    QApplication::sendEvent(canvas, &move);
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, to);
    m_window->document()->flush();
    auto moved = m_window->document()->solution()->scene().path.points;
    QCOMPARE(moved.size(), std::size_t(5));
    QVERIFY(std::abs(moved[2].first - target.x()) < 1e-9);
    QVERIFY(std::abs(moved[2].second - target.y()) < 1e-9);
    QCOMPARE(moved[1], points[1]);
    // right click deletes a vertex
    QPoint third = canvas->toPixel(QPointF(moved[3].first, moved[3].second)).toPoint();
    QTest::mousePress(canvas, Qt::RightButton, {}, third);
    QTest::mouseRelease(canvas, Qt::RightButton, {}, third);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution()->scene().path.points.size(), std::size_t(4));
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QVERIFY(m_window->document()->solution()->scene().path.points == moved);
}

void TestMainWindow::parameterChangeUpdatesPlots() {
    QCustomPlot* psi = m_window->plotsPanel()->plot(0);
    QVector<double> before = graphValues(psi);
    QVERIFY(before.size() > 10);
    NumberField* b = m_window->parametersPanel()->spinBox(QStringLiteral("b"));
    QVERIFY(b);
    b->setValue(2.0);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution()->system().b, 2.0);
    QVector<double> after = graphValues(psi);
    QVERIFY2(maxAbsDifference(before, after) > 0.05, "Psi = atan2(1, b kappa) changed with b");
    // tan Psi = 1/(b kappa) and max |kappa| = 1 on y = -sin x: |Psi - pi/2| peaks at pi/2 -
    // atan(1/b) on the crests
    double devBefore = 0, devAfter = 0;
    for (double v : before)
        devBefore = std::max(devBefore, std::abs(v - M_PI / 2));
    for (double v : after)
        devAfter = std::max(devAfter, std::abs(v - M_PI / 2));
    QVERIFY2(std::abs(devBefore - (M_PI / 2 - std::atan(1.0))) < 1e-2,
             qPrintable(QString::number(devBefore)));
    QVERIFY2(std::abs(devAfter - (M_PI / 2 - std::atan(0.5))) < 1e-2,
             qPrintable(QString::number(devAfter)));
}

void TestMainWindow::canvasDrawsBodiesAtTheirPoses() {
    SceneCanvas* canvas = m_window->canvas();
    canvas->fitEverything(); // the free ghost runs far from the path
    m_window->playback()->seek(6.0);
    MotionSample m = m_window->document()->solution()->at(6.0);
    QImage image = canvas->grab().toImage();
    double dpr = image.devicePixelRatio();
    auto colourAt = [&](double x, double y) {
        QPointF p = canvas->toPixel(QPointF(x, y)) * dpr;
        return image.pixelColor(p.toPoint());
    };
    // inside the controlled board, between the knife and the centre of mass (a = 0.5 ahead of P):
    // blue; inside the free ghost: pale red; far from both: white
    double ahead = 0.25;
    QColor body = colourAt(m.x + ahead * std::cos(m.phi) + 0.3 * -std::sin(m.phi),
                           m.y + ahead * std::sin(m.phi) + 0.3 * std::cos(m.phi));
    QVERIFY2(body.blue() > body.red() + 60, qPrintable(body.name()));
    QColor ghost = colourAt(m.free.x + ahead * std::cos(m.free.phi) + 0.3 * -std::sin(m.free.phi),
                            m.free.y + ahead * std::sin(m.free.phi) + 0.3 * std::cos(m.free.phi));
    QVERIFY2(ghost.red() > ghost.blue() + 20, qPrintable(ghost.name()));
    QCOMPARE(canvas->toWorld(canvas->toPixel(QPointF(1.25, -0.5))), QPointF(1.25, -0.5));
    // the arrow keys pan by a tenth of the view
    QPointF before = canvas->toPixel(QPointF(1.0, 1.0));
    QTest::keyClick(canvas, Qt::Key_Right);
    QPointF after = canvas->toPixel(QPointF(1.0, 1.0));
    QVERIFY(std::abs(before.x() - after.x() - 0.1 * canvas->width()) < 1e-6);
    QVERIFY(std::abs(before.y() - after.y()) < 1e-9);
    // following the body puts it in the middle of the canvas
    m_window->followAction()->trigger();
    QVERIFY(canvas->followsBody());
    QPointF centre = canvas->toPixel(QPointF(m.x, m.y));
    QVERIFY(std::abs(centre.x() - canvas->width() / 2.0) < 1);
    QVERIFY(std::abs(centre.y() - canvas->height() / 2.0) < 1);
}

void TestMainWindow::typedParametricPath() {
    PathPanel* panel = m_window->pathPanel();
    panel->parametricButton()->click();
    QVERIFY(!panel->graphEdit()->isEnabled());
    typeInto(panel->xOfUEdit(), QStringLiteral("3*cos(u)"));
    typeInto(panel->yOfUEdit(), QStringLiteral("3*sin(u)"));
    panel->fromSpin()->setValue(0);
    panel->toSpin()->setValue(M_PI);
    panel->applyButton()->click();
    m_window->document()->flush();
    QVERIFY2(panel->errorText().isEmpty(), qPrintable(panel->errorText()));
    const auto& solution = m_window->document()->solution();
    QCOMPARE(solution->scene().path.kind, PathKind::Parametric);
    // half a circle of radius 3 (the range box keeps the whole double of pi)
    QCOMPARE(solution->scene().path.to, M_PI);
    QVERIFY(std::abs(solution->path()->length() - 3 * M_PI) < 1e-9);
    // a typed error stays while a parameter changes; the path fields keep the user's text
    typeInto(panel->yOfUEdit(), QStringLiteral("3*sin(u"));
    panel->applyButton()->click();
    QTRY_VERIFY(!panel->errorText().isEmpty());
    m_window->parametersPanel()->spinBox(QStringLiteral("m"))->setValue(2.0);
    m_window->document()->flush();
    QCOMPARE(panel->yOfUEdit()->text(), QStringLiteral("3*sin(u"));
    QCOMPARE(m_window->document()->solution()->system().mass, 2.0);
    QVERIFY(std::abs(m_window->document()->solution()->path()->length() - 3 * M_PI) < 1e-9);
}

void TestMainWindow::sliderDragCoalesces() {
    QSlider* slider = m_window->parametersPanel()->slider(QStringLiteral("speed"));
    QVERIFY(slider);
    QSignalSpy solved(m_window->document(), &SceneDocument::solutionChanged);
    for (int v = 200; v <= 400; v += 10)
        slider->setValue(v); // one drag, no event processing in between
    QTRY_COMPARE(solved.count(), 1);
    double speed = m_window->document()->solution()->scene().speed;
    QVERIFY(std::abs(speed - (0.05 + 4.95 * 400 / 1000.0)) < 1e-9);
    QCOMPARE(m_window->undoStack()->count(), 1); // the drag is one undo step
}

void TestMainWindow::invalidParameterKeepsSolution() {
    auto before = m_window->document()->solution();
    NumberField* b = m_window->parametersPanel()->spinBox(QStringLiteral("b"));
    b->setValue(0.2); // below a = 0.5
    m_window->document()->flush();
    QVERIFY(m_window->parametersPanel()->errorText().contains(QStringLiteral("b")));
    QCOMPARE(m_window->document()->solution(), before);
    QCOMPARE(m_window->document()->solution()->system().b, 1.0);
    b->setValue(1.2);
    m_window->document()->flush();
    QVERIFY(m_window->parametersPanel()->errorText().isEmpty());
    QCOMPARE(m_window->document()->solution()->system().b, 1.2);
}

void TestMainWindow::systemSwitch() {
    auto* combo = m_window->parametersPanel()->findChild<QComboBox*>();
    QVERIFY(combo);
    combo->setFocus();
    combo->setCurrentIndex(1);
    emit combo->activated(1);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().system.kind, SystemKind::Disk);
    QVERIFY(m_window->parametersPanel()->spinBox(QStringLiteral("I2")));
    QVERIFY(!m_window->parametersPanel()->spinBox(QStringLiteral("b")));
    QCOMPARE(m_window->document()->solution()->system().a, 0.0);
    m_window->canvas()->grab(); // the disk paints
    // back to the sleigh (same number of parameters as the disk), then the carriage, then undo
    combo->setCurrentIndex(0);
    emit combo->activated(0);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution()->system().b, 1.0);
    QVERIFY(m_window->parametersPanel()->spinBox(QStringLiteral("b")));
    QVERIFY(!m_window->parametersPanel()->spinBox(QStringLiteral("R")));
    combo->setCurrentIndex(2);
    emit combo->activated(2);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().system.kind, SystemKind::Carriage);
    QCOMPARE(m_window->parametersPanel()->spinBox(QStringLiteral("M"))->value(), 2.0);
    m_window->canvas()->grab();
    m_window->undoStack()->undo();
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution()->scene().system.kind, SystemKind::Disk);
    QVERIFY(m_window->parametersPanel()->spinBox(QStringLiteral("I1")));
    QCOMPARE(combo->currentIndex(), 1);
}

void TestMainWindow::gyrationAndModeSwitch() {
    ParametersPanel* panel = m_window->parametersPanel();
    auto combos = panel->findChildren<QComboBox*>();
    QCOMPARE(combos.size(), 3); // system, gyration, mode
    QComboBox* gyration = combos[1];
    gyration->setCurrentIndex(1);
    emit gyration->activated(1);
    m_window->document()->flush();
    // I = m (b^2 - a^2) = 1 * (1 - 0.25)
    QVERIFY(panel->spinBox(QStringLiteral("I")));
    QVERIFY(!panel->spinBox(QStringLiteral("b")));
    QCOMPARE(panel->spinBox(QStringLiteral("I"))->value(), 0.75);
    panel->spinBox(QStringLiteral("I"))->setValue(3.0);
    m_window->document()->flush();
    QVERIFY(std::abs(m_window->document()->solution()->system().b - std::sqrt(0.25 + 3.0)) < 1e-12);
    QComboBox* mode = combos[2];
    mode->setCurrentIndex(1);
    emit mode->activated(1);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution()->scene().mode, SpeedMode::Speed);
    // constant speed: sdot = v_s everywhere, so the time to traverse is length / v_s
    const auto& solution = m_window->document()->solution();
    QVERIFY(std::abs(solution->duration() - solution->path()->length() / solution->scene().speed) <
            1e-9);
}

void TestMainWindow::playPauseSeek() {
    Playback* playback = m_window->playback();
    playback->seek(2.0);
    QCOMPARE(m_window->canvas()->time(), 2.0);
    QCOMPARE(m_window->plotsPanel()->cursorTime(), 2.0);
    QVERIFY(m_window->timeline()->timeLabel()->text().contains(QStringLiteral("2.00")));
    QCustomPlot* psi = m_window->plotsPanel()->plot(0);
    psi->replot();
    double x2 = psi->axisRect()->axis(QCPAxis::atBottom)->coordToPixel(2.0);
    QVERIFY(std::abs(m_window->plotsPanel()->cursor(0)->geometry().center().x() - x2) <= 1.5);
    QVERIFY(m_window->plotsPanel()->cursor(0)->isVisible());
    int sliderAt2 = m_window->timeline()->slider()->value();
    QVERIFY(sliderAt2 > 0);
    QTest::keyClick(m_window.get(), Qt::Key_Space);
    QVERIFY(playback->isPlaying());
    QTRY_VERIFY_WITH_TIMEOUT(playback->time() > 2.1, 3000);
    QTest::keyClick(m_window.get(), Qt::Key_Space);
    QVERIFY(!playback->isPlaying());
    double paused = playback->time();
    QTest::qWait(100);
    QCOMPARE(playback->time(), paused);
    m_window->timeline()->stepForwardAction()->trigger();
    QVERIFY(std::abs(playback->time() - (paused + playback->stepSize())) < 1e-12);
    // scrubbing the slider seeks
    m_window->timeline()->slider()->setValue(1000);
    QVERIFY(std::abs(playback->time() - playback->tEnd() / 2) < 1e-9);
    // the end stops unless looping
    playback->seek(playback->tEnd() - 0.01);
    playback->play();
    QTRY_VERIFY_WITH_TIMEOUT(!playback->isPlaying(), 3000);
    QCOMPARE(playback->time(), playback->tEnd());
}

void TestMainWindow::clickingPlotSeeks() {
    QCustomPlot* plot = m_window->plotsPanel()->plot(3);
    plot->replot();
    QCPAxis* t = plot->axisRect()->axis(QCPAxis::atBottom);
    int x = int(std::lround(t->coordToPixel(5.0)));
    int y = plot->axisRect()->center().y();
    QTest::mouseClick(plot, Qt::LeftButton, {}, QPoint(x, y));
    // once the double-click interval has passed: a double click does not seek
    QTRY_VERIFY2(std::abs(m_window->playback()->time() - 5.0) < 0.1,
                 qPrintable(QString::number(m_window->playback()->time())));
    QVERIFY(std::abs(m_window->canvas()->time() - m_window->playback()->time()) < 1e-12);
    // dragging with the button down scrubs
    QPoint to(int(std::lround(t->coordToPixel(8.0))), y);
    QTest::mousePress(plot, Qt::LeftButton, {}, QPoint(x, y));
    QMouseEvent drag(QEvent::MouseMove, to, plot->mapToGlobal(to), Qt::NoButton, Qt::LeftButton,
                     {});
    QApplication::sendEvent(plot, &drag);
    QVERIFY(std::abs(m_window->playback()->time() - 8.0) < 0.1);
    QTest::mouseRelease(plot, Qt::LeftButton, {}, to);
}

void TestMainWindow::spaceTypesInTextFields() {
    QLineEdit* edit = m_window->pathPanel()->graphEdit();
    edit->setFocus();
    QTRY_VERIFY(edit->hasFocus());
    edit->end(false);
    QTest::keyClick(edit, Qt::Key_Space);
    QVERIFY(!m_window->playback()->isPlaying());
    QCOMPARE(edit->text(), QStringLiteral("-sin(x) "));
    // elsewhere Space plays and pauses
    m_window->canvas()->setFocus();
    QTest::keyClick(m_window->canvas(), Qt::Key_Space);
    QVERIFY(m_window->playback()->isPlaying());
    QTest::keyClick(m_window->canvas(), Qt::Key_Space);
    QVERIFY(!m_window->playback()->isPlaying());
}

void TestMainWindow::undoRedo() {
    QUndoStack* undo = m_window->undoStack();
    PathPanel* panel = m_window->pathPanel();
    typeInto(panel->graphEdit(), QStringLiteral("0.5*sin(2*x)"));
    QTest::keyClick(panel->graphEdit(), Qt::Key_Return);
    m_window->document()->flush();
    m_window->parametersPanel()->spinBox(QStringLiteral("m"))->setValue(3.0);
    m_window->document()->flush();
    QCOMPARE(undo->count(), 2);
    QCOMPARE(m_window->document()->solution()->system().mass, 3.0);
    undo->undo();
    m_window->document()->flush();
    QCOMPARE(m_window->document()->solution()->system().mass, 1.0);
    QCOMPARE(m_window->parametersPanel()->spinBox(QStringLiteral("m"))->value(), 1.0);
    undo->undo();
    m_window->document()->flush();
    QCOMPARE(QString::fromStdString(m_window->document()->scene().path.y),
             QStringLiteral("-sin(x)"));
    QCOMPARE(panel->graphEdit()->text(), QStringLiteral("-sin(x)"));
    undo->redo();
    undo->redo();
    m_window->document()->flush();
    QCOMPARE(QString::fromStdString(m_window->document()->solution()->scene().path.y),
             QStringLiteral("0.5*sin(2*x)"));
    QCOMPARE(m_window->document()->solution()->system().mass, 3.0);
}

void TestMainWindow::saveLoadRoundTrip() {
    m_window->parametersPanel()->spinBox(QStringLiteral("a"))->setValue(0.25);
    m_window->parametersPanel()->spinBox(QStringLiteral("speed"))->setValue(1.5);
    m_window->document()->flush();
    Scene saved = m_window->document()->scene();
    QString file = m_dir.filePath(QStringLiteral("scene.json"));
    QVERIFY(m_window->saveFile(file));
    QVERIFY(loadSceneFile(file.toStdString()) == saved);
    MainWindow other(false);
    QVERIFY(other.openFile(file));
    other.document()->flush();
    QVERIFY(other.document()->scene() == saved);
    QCOMPARE(other.document()->solution()->system().a, 0.25);
    QCOMPARE(other.parametersPanel()->spinBox(QStringLiteral("speed"))->value(), 1.5);
    QCOMPARE(other.document()->fileName(), file);
}

void TestMainWindow::openBadFileKeepsScene() {
    QString file = m_dir.filePath(QStringLiteral("bad.json"));
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("{\"version\": 1, \"system\": ");
    f.close();
    Scene before = m_window->document()->scene();
    QVERIFY(!m_window->openFile(file));
    QVERIFY(m_window->lastFileError().contains(QStringLiteral("scene file")));
    QVERIFY(m_window->document()->scene() == before);
}

void TestMainWindow::exportFilesValid() {
    QString dir = m_dir.filePath(QStringLiteral("plots"));
    QVERIFY(m_window->exportPlotsTo(
        dir, {QStringLiteral("png"), QStringLiteral("pdf"), QStringLiteral("svg")}));
    QImage png(dir + QStringLiteral("/psi.png"));
    QVERIFY(!png.isNull());
    QVERIFY(png.width() >= 900);
    QFile pdf(dir + QStringLiteral("/energy.pdf"));
    QVERIFY(pdf.open(QIODevice::ReadOnly));
    QVERIFY(pdf.read(5).startsWith("%PDF"));
    QSvgRenderer svg(dir + QStringLiteral("/lambda.svg"));
    QVERIFY(svg.isValid());
    QString csv = m_dir.filePath(QStringLiteral("run.csv"));
    QVERIFY(m_window->exportCsvTo(csv));
    QFile c(csv);
    QVERIFY(c.open(QIODevice::ReadOnly));
    // one header row and the rows, nothing a spreadsheet would show as a row of its own
    QVERIFY(c.readLine().startsWith("t,s,x,y,phi,psi,chi,lambda,energy,free_x"));
    int rows = 0;
    while (!c.atEnd()) {
        const QByteArray line = c.readLine().trimmed();
        QVERIFY2(!line.startsWith('#'), line.constData());
        rows += line.isEmpty() ? 0 : 1;
    }
    QCOMPARE(rows, 501);
    // the parameters the comment line held are in the summary beside it
    QFile summary(m_dir.filePath(QStringLiteral("run.summary.json")));
    QVERIFY(summary.open(QIODevice::ReadOnly));
    const QJsonObject s = QJsonDocument::fromJson(summary.readAll()).object();
    QCOMPARE(s.value(QStringLiteral("preset")).toString(), QStringLiteral("sinusoid"));
    QCOMPARE(s.value(QStringLiteral("b")).toDouble(), 1.0);
    QCOMPARE(s.value(QStringLiteral("parameters")).toObject().value(QStringLiteral("m")).toDouble(),
             1.0);
}

// the line preset's y, psi and lambda are zeros that arithmetic makes negative: written as 0
void TestMainWindow::exportedCsvHasNoNegativeZero() {
    const auto names = presetNames();
    m_window->choosePresetNumber(
        int(std::find(names.begin(), names.end(), "line") - names.begin()));
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().preset, std::string("line"));
    const QString csv = m_dir.filePath(QStringLiteral("line.csv"));
    QVERIFY(m_window->exportCsvTo(csv));
    QFile c(csv);
    QVERIFY(c.open(QIODevice::ReadOnly));
    int zeros = 0;
    while (!c.atEnd()) {
        const QList<QByteArray> fields = c.readLine().trimmed().split(',');
        for (const QByteArray& f : fields) {
            QVERIFY2(f != "-0", "a -0 in the CSV");
            zeros += f == "0";
        }
    }
    QVERIFY(zeros > 1000);
}

void TestMainWindow::screenshotMode() {
    QString file = m_dir.filePath(QStringLiteral("shot.png"));
    QByteArray f = file.toUtf8();
    const char* args[] = {"chaplygin-lab", "--screenshot", f.constData(), "--preset", "circle",
                          "--at",          "2.5",          "--size",      "1024x700"};
    QCOMPARE(runScreenshot(9, const_cast<char**>(args)), 0);
    QImage image(file);
    QVERIFY(!image.isNull());
    QCOMPARE(image.size(), QSize(1024, 700));
    // the canvas is not blank: the path and the body put colour on it
    int coloured = 0;
    for (int y = 0; y < image.height(); y += 4)
        for (int x = 0; x < image.width(); x += 4) {
            QColor c = image.pixelColor(x, y);
            coloured += c.saturation() > 80 ? 1 : 0;
        }
    QVERIFY(coloured > 200);
    const char* bad[] = {"chaplygin-lab", "--screenshot", f.constData(), "--path",
                         "y=sin(",        "--x-range",    "0,3"};
    QCOMPARE(runScreenshot(7, const_cast<char**>(bad)), 2);
    const char* late[] = {"chaplygin-lab", "--screenshot", f.constData(), "--preset",
                          "line",          "--at",         "1000"};
    QCOMPARE(runScreenshot(7, const_cast<char**>(late)), 2);
    const char* badSize[] = {"chaplygin-lab", "--screenshot", f.constData(), "--size", "big"};
    QCOMPARE(runScreenshot(5, const_cast<char**>(badSize)), 2);
}

void TestMainWindow::settingsKeepRecentFilesAndLayout() {
    // only this test writes settings (the other windows are made without them)
    QCoreApplication::setApplicationName(QStringLiteral("ui_tests_settings"));
    QSettings().clear();
    QString file = m_dir.filePath(QStringLiteral("recent.json"));
    {
        MainWindow window(true);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.resize(1000, 700);
        QVERIFY(window.saveFile(file));
        QCOMPARE(window.recentMenu()->actions().size(), 1);
        window.findChild<QDockWidget*>(QStringLiteral("plotsDock"))->hide();
        window.close();
    }
    MainWindow again(true);
    QCOMPARE(again.recentMenu()->actions().size(), 1);
    QCOMPARE(again.recentMenu()->actions().first()->toolTip(), QFileInfo(file).absoluteFilePath());
    QCOMPARE(again.size(), QSize(1000, 700));
    QVERIFY(!again.findChild<QDockWidget*>(QStringLiteral("plotsDock"))->isVisibleTo(&again));
    QSettings().clear();
}

QTEST_MAIN(TestMainWindow)
#include "test_main_window.moc"
