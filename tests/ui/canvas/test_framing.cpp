// Framing that shows the lesson and bodies that do not hide it: the default fit frames the path
// (checked against the exact curves), Shift+F frames everything that moves, a stroke or a moved
// point keeps the view, the automatic body display, presentation mode's share of the screen and
// its docks, and the bottom docks' layout after the Methods tab. Offscreen, real widgets.
#include "canvas/body_painter.h"
#include "canvas/scene_canvas.h"
#include "document/pin_set.h"
#include "lab/gallery.h"
#include "panels/notes_panel.h"
#include "panels/path_panel.h"
#include "scene/presets.h"
#include "shell/body_display_menu.h"
#include "shell/playback.h"
#include "shell/presentation_mode.h"
#include "shell/timeline_bar.h"
#include "window_fixture.h"

#include <QLabel>
#include <QMenuBar>
#include <QtTest>

#include <cmath>
#include <functional>
#include <numbers>
#include <tuple>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

// the exact paths: the closed forms of resources/scenes/presets/*.json and gallery/cusp.json
struct ExactPath {
    const char* name;
    std::function<QPointF(double)> at;
    double from, to;
};
const ExactPath kPaths[] = {
    {"circle", [](double u) { return QPointF(2 * std::cos(u), 2 * std::sin(u)); }, 0,
     2 * std::numbers::pi},
    {"catenary", [](double u) { return QPointF(std::sqrt(u * u + 1), std::asinh(u)); }, 0, 5},
    {"sinusoid", [](double x) { return QPointF(x, -std::sin(x)); }, 0, 4 * std::numbers::pi},
    {"cusp", [](double u) { return QPointF(u * u, u * u * u); }, -1, 1},
};

// the exact path's box [px] in the canvas's widget
QRectF exactPixels(const SceneCanvas& canvas, const ExactPath& path) {
    QRectF box;
    for (int k = 0; k < 400; ++k) {
        const QPointF p = canvas.toPixel(path.at(path.from + (path.to - path.from) * k / 399));
        box = box.isNull() ? QRectF(p, QSizeF(1e-9, 1e-9)) : box.united(QRectF(p, QSizeF()));
    }
    return box;
}

// how much of the drawing area the box fills in the direction that limits it
double fill(const SceneCanvas& canvas, const QRectF& pixels) {
    const QRectF area = canvas.drawingArea();
    return std::max(pixels.width() / area.width(), pixels.height() / area.height());
}

// the box [px] of the exact path and the outlines of the bodies shown at the current time
QRectF lessonPixels(const SceneCanvas& canvas, const ExactPath& path, const Solution& solution,
                    double t) {
    const MotionSample m = solution.at(t);
    const QPainterPath shape = bodyShape(solution.scene().system, solution.system());
    QRectF box = exactPixels(canvas, path);
    for (auto [x, y, phi] :
         {std::tuple{m.x, m.y, m.phi}, std::tuple{m.free.x, m.free.y, m.free.phi},
          std::tuple{m.vak.x, m.vak.y, m.vak.phi}}) {
        QTransform place;
        place.translate(x, y);
        place.rotate(phi * 180 / std::numbers::pi);
        box = box.united((place * canvas.worldToPixel()).map(shape).boundingRect());
    }
    return box;
}

// Fit the path: the path fills at least 70 % of the drawing area, or, where the bodies shown
// now would then be cut, the path and the bodies fill at least 85 % of it (a margin of 5 % on
// each side of what holds them)
bool fitsTheLesson(const SceneCanvas& canvas, const ExactPath& path, const Solution& solution,
                   double t) {
    return fill(canvas, exactPixels(canvas, path)) >= 0.7 ||
           fill(canvas, lessonPixels(canvas, path, solution, t)) >= 0.85;
}

} // namespace

class TestFraming : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_framing_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void defaultFitFramesThePath();
    void shiftFFramesEverythingThatMoves();
    void strokeAndMovedPointKeepTheView();
    void automaticBodyDisplayShowsThePath();
    void presentationGivesTheCanvasTheScreen();
    void presentationAt1024KeepsTheNoteToAQuarter();
    void followKeepsWorkingInPresentation();
    void plotsRecoverAfterMethodsAndLayoutResets();
    void plotsRecoverAtTheNextStart();
    void pinKeyStaysClearOfTheDrawHint();

  private:
    void load(const ExactPath& path) {
        if (std::string(path.name) == "cusp")
            QVERIFY(m_window->loadGalleryEntry(QStringLiteral("cusp")));
        else
            choosePreset(path.name);
        m_window->document()->flush();
        QCoreApplication::processEvents();
    }
};

void TestFraming::defaultFitFramesThePath() {
    SceneCanvas* canvas = m_window->canvas();
    for (BodyDisplay display : {BodyDisplay::Marker, BodyDisplay::Automatic}) {
        CanvasStyle style = canvas->canvasStyle();
        style.body = display;
        canvas->setCanvasStyle(style);
        for (const ExactPath& path : kPaths) {
            load(path);
            const QRectF pixels = exactPixels(*canvas, path);
            const QString what = QStringLiteral("%1, display %2: fill %3")
                                     .arg(QLatin1String(path.name))
                                     .arg(int(display))
                                     .arg(fill(*canvas, pixels));
            // the path fills at least 70 % of the drawing area (or with the bodies shown now,
            // 85 %) and lies inside it
            QVERIFY2(fitsTheLesson(*canvas, path, *m_window->document()->solution(),
                                   m_window->playback()->time()),
                     qPrintable(what));
            QVERIFY2(canvas->drawingArea().contains(pixels), qPrintable(what));
            // F after a zoom frames it again
            canvas->zoomBy(0.3);
            QVERIFY(fill(*canvas, exactPixels(*canvas, path)) < 0.5);
            canvas->setFocus();
            QTest::keyClick(canvas, Qt::Key_F);
            QVERIFY2(std::abs(fill(*canvas, exactPixels(*canvas, path)) - fill(*canvas, pixels)) <
                         1e-9,
                     qPrintable(what));
        }
    }
}

void TestFraming::shiftFFramesEverythingThatMoves() {
    // the sinusoid's free ghost and vakonomic body run far from the path
    SceneCanvas* canvas = m_window->canvas();
    const double pathScale = canvas->scale();
    auto outside = [&] {
        const Solution& solution = *m_window->document()->solution();
        const QRectF area = canvas->drawingArea().adjusted(-1, -1, 1, 1);
        int n = 0;
        for (int i = 0; i <= 400; ++i) {
            const MotionSample m = solution.at(solution.tEnd() * i / 400);
            for (QPointF p :
                 {QPointF(m.x, m.y), QPointF(m.free.x, m.free.y), QPointF(m.vak.x, m.vak.y)})
                n += area.contains(canvas->toPixel(p)) ? 0 : 1;
        }
        return n;
    };
    QVERIFY(outside() > 0); // the default fit leaves the far bodies out
    // Shift+F on the canvas, and the View menu's action with its shortcut
    canvas->setFocus();
    QTest::keyClick(canvas, Qt::Key_F, Qt::ShiftModifier);
    QVERIFY(canvas->fitsEverything());
    QCOMPARE(outside(), 0);
    QVERIFY(canvas->scale() < pathScale);
    QTest::keyClick(canvas, Qt::Key_F);
    QVERIFY(!canvas->fitsEverything());
    QCOMPARE(canvas->scale(), pathScale);
    auto* action = m_window->menuBar()->findChild<QAction*>(QStringLiteral("fitEverythingAction"));
    QVERIFY(action);
    QCOMPARE(action->shortcut(), QKeySequence(QStringLiteral("Shift+F")));
    action->trigger();
    QCOMPARE(outside(), 0);
    // a resize keeps framing everything
    m_window->resize(1100, 760);
    QCoreApplication::processEvents();
    QCOMPARE(outside(), 0);
}

void TestFraming::strokeAndMovedPointKeepTheView() {
    SceneCanvas* canvas = m_window->canvas();
    canvas->setDrawMode(true);
    const QRectF area = canvas->drawingArea();
    const double scale = canvas->scale();
    // the world point at the widget's centre (the status bar's message may resize the canvas)
    auto middle = [canvas] {
        return canvas->toWorld(QPointF(canvas->width() / 2.0, canvas->height() / 2.0));
    };
    const QPointF centre = middle();
    // a stroke over the middle third of the drawing area
    const QPoint start = (area.center() + QPointF(-area.width() / 6, 0)).toPoint();
    QTest::mousePress(canvas, Qt::LeftButton, {}, start);
    for (int i = 1; i <= 20; ++i)
        QTest::mouseMove(canvas, start + QPoint(int(area.width() / 3 * i / 20),
                                                int(area.height() / 5 * std::sin(i / 3.0))));
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, start + QPoint(int(area.width() / 3), 0));
    QTRY_VERIFY(m_window->document()->scene().path.kind == PathKind::Polyline);
    m_window->document()->flush();
    QCoreApplication::processEvents();
    QCOMPARE(canvas->scale(), scale);
    QVERIFY2(QLineF(middle(), centre).length() * scale < 1e-6,
             qPrintable(QString::number(QLineF(middle(), centre).length() * scale)));
    // a point dragged: the view stays under the mouse
    const auto points = m_window->document()->scene().path.points;
    const QPoint from = canvas->toPixel({points[5].first, points[5].second}).toPoint();
    QTest::mousePress(canvas, Qt::LeftButton, {}, from);
    QTest::mouseMove(canvas, from + QPoint(0, 30));
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, from + QPoint(0, 30));
    QTRY_VERIFY(m_window->document()->scene().path.points != points);
    m_window->document()->flush();
    QCoreApplication::processEvents();
    QCOMPARE(canvas->scale(), scale);
    QVERIFY2(QLineF(middle(), centre).length() * scale < 1e-6,
             qPrintable(QString::number(QLineF(middle(), centre).length() * scale)));
    // an edit that takes the path out of the view refits it
    auto far = m_window->document()->scene().path.points;
    for (auto& [x, y] : far)
        x += 50 * area.width() / scale;
    emit canvas->pointsEdited(far);
    QTRY_VERIFY(m_window->document()->scene().path.points == far);
    m_window->document()->flush();
    QCoreApplication::processEvents();
    const QRectF path = canvas->pathBounds();
    QVERIFY(
        canvas->drawingArea()
            .adjusted(-1, -1, 1, 1)
            .contains(QRectF(canvas->toPixel(path.topLeft()), canvas->toPixel(path.bottomRight()))
                          .normalized()));
}

void TestFraming::automaticBodyDisplayShowsThePath() {
    // the sleigh of the presets (a = 0.5, b = 1, its board 3.1 m long): to scale beside the
    // sinusoid, an outline on the circle and the catenary, a marker on the cusp, where the board
    // is longer than the path is wide
    SceneCanvas* canvas = m_window->canvas();
    QCOMPARE(canvas->canvasStyle().body, BodyDisplay::Automatic);
    QAction* automatic = m_window->bodyDisplayMenu()->displayAction(BodyDisplay::Automatic);
    QVERIFY(automatic && automatic->isChecked());
    const std::pair<const char*, BodyDisplay> expected[] = {{"circle", BodyDisplay::Outline},
                                                            {"catenary", BodyDisplay::Outline},
                                                            {"sinusoid", BodyDisplay::ToScale},
                                                            {"cusp", BodyDisplay::Marker}};
    for (const auto& [name, display] : expected) {
        for (const ExactPath& path : kPaths)
            if (std::string(path.name) == name)
                load(path);
        QCOMPARE(canvas->shownBodyDisplay(), display);
        // the rule: the circle that holds the body against the path's larger side
        const Solution& s = *m_window->document()->solution();
        const QRectF box = canvas->pathBounds();
        const double ratio =
            2 * bodyExtent(s.scene().system, s.system()) / std::max(box.width(), box.height());
        QCOMPARE(display, ratio <= kAutoToScale   ? BodyDisplay::ToScale
                          : ratio <= kAutoOutline ? BodyDisplay::Outline
                                                  : BodyDisplay::Marker);
        // the user's explicit choice is kept
        for (BodyDisplay chosen :
             {BodyDisplay::ToScale, BodyDisplay::Outline, BodyDisplay::Marker}) {
            CanvasStyle style = canvas->canvasStyle();
            style.body = chosen;
            canvas->setCanvasStyle(style);
            QCOMPARE(canvas->shownBodyDisplay(), chosen);
        }
        CanvasStyle style = canvas->canvasStyle();
        style.body = BodyDisplay::Automatic;
        canvas->setCanvasStyle(style);
    }
}

void TestFraming::presentationGivesTheCanvasTheScreen() {
    m_window->resize(1920, 1080);
    QCoreApplication::processEvents();
    PresentationMode* presentation = m_window->presentation();
    presentation->setFullScreen(false);
    presentation->setActive(true);
    QTest::qWait(50);
    SceneCanvas* canvas = m_window->canvas();
    auto check = [&](const QString& what) {
        QCoreApplication::processEvents();
        const double share = double(canvas->width()) * canvas->height() /
                             (double(m_window->width()) * m_window->height());
        QVERIFY2(share >= 0.55, qPrintable(QStringLiteral("%1: %2").arg(what).arg(share)));
        for (const char* name : {"accuracyDock", "equationsDock", "pathDock", "parametersDock",
                                 "methodsDock", "sweepDock"})
            QVERIFY2(!dock(name)->isVisible(), qPrintable(what + QLatin1String(name)));
        // the Notes dock only with a note
        const bool note = !m_window->document()->scene().note.empty();
        QVERIFY2(dock("notesDock")->isVisible() == note, qPrintable(what));
        // the time read-out is whole, inside the window
        auto* label = m_window->timeline()->findChild<QLabel*>();
        QVERIFY(label && label->isVisible());
        QVERIFY2(label->fontMetrics().horizontalAdvance(label->text()) <=
                     label->contentsRect().width(),
                 qPrintable(label->text()));
        const QRect shown(label->mapTo(m_window.get(), QPoint(0, 0)), label->size());
        QVERIFY2(m_window->rect().contains(shown), qPrintable(what));
    };
    check(QStringLiteral("sinusoid"));
    for (int i = 0; i < 4; ++i) {
        QTest::keyClick(m_window.get(), Qt::Key_PageDown);
        m_window->document()->flush();
        check(QString::fromStdString(m_window->document()->scene().path.xOfU));
    }
    for (const ExactPath& path : kPaths) {
        load(path);
        check(QLatin1String(path.name));
        QVERIFY(fitsTheLesson(*canvas, path, *m_window->document()->solution(),
                              m_window->playback()->time()));
    }
    // leaving gives the docks back
    presentation->setActive(false);
    QVERIFY(dock("accuracyDock")->isVisible() || dock("notesDock")->isVisible() ||
            dock("equationsDock")->isVisible());
}

void TestFraming::presentationAt1024KeepsTheNoteToAQuarter() {
    // the pushed bodies' gallery scene has a note and six plots: on a 1024 x 768 projector the
    // note takes at most a quarter of the width (it took 365 px), the canvas most of the rest;
    // both when the note comes with the next scene and when presentation mode starts with it
    m_window->resize(1024, 768);
    QCoreApplication::processEvents();
    PresentationMode* presentation = m_window->presentation();
    presentation->setFullScreen(false);
    QVERIFY(m_window->document()->scene().note.empty());
    presentation->setActive(true);
    QTest::qWait(50);
    QVERIFY(!dock("notesDock")->isVisible());
    SceneCanvas* canvas = m_window->canvas();
    auto* notes = m_window->findChild<NotesPanel*>();
    QVERIFY(notes);
    auto check = [&](const char* what) {
        QVERIFY2(dock("notesDock")->isVisible(), what);
        QVERIFY2(dock("notesDock")->width() <= 1024 / 4 + 2,
                 qPrintable(QStringLiteral("%1: %2").arg(what).arg(dock("notesDock")->width())));
        const double share = double(canvas->width()) * canvas->height() / (1024.0 * 768.0);
        QVERIFY2(share >= 0.40, qPrintable(QStringLiteral("%1: %2").arg(what).arg(share)));
        // the note alone: its editing hint is not for the lecture hall
        QVERIFY2(!notes->hintShown(), what);
    };
    QVERIFY(m_window->loadGalleryEntry(QStringLiteral("pushed-off-path")));
    m_window->document()->flush();
    QTest::qWait(50);
    check("the note came with the scene");
    presentation->setActive(false);
    QTest::qWait(50);
    QVERIFY(notes->hintShown());
    presentation->setActive(true);
    QTest::qWait(50);
    check("presenting a scene with a note");
}

void TestFraming::followKeepsWorkingInPresentation() {
    SceneCanvas* canvas = m_window->canvas();
    m_window->followAction()->setChecked(true);
    m_window->presentation()->setFullScreen(false);
    m_window->presentation()->setActive(true);
    QCoreApplication::processEvents();
    QVERIFY(canvas->followsBody());
    for (double t : {0.5, 3.0}) {
        m_window->playback()->seek(t);
        const MotionSample m = m_window->document()->solution()->at(t);
        const QPointF p = canvas->toPixel({m.x, m.y});
        QVERIFY(std::abs(p.x() - canvas->width() / 2.0) <= 1);
        QVERIFY(std::abs(p.y() - canvas->height() / 2.0) <= 1);
    }
    m_window->presentation()->setActive(false);
    QVERIFY(canvas->followsBody());
}

void TestFraming::plotsRecoverAfterMethodsAndLayoutResets() {
    QDockWidget* plots = dock("plotsDock");
    QTest::qWait(50);
    const int before = plots->height();
    m_window->showMethodsDock();
    QTRY_VERIFY(dock("methodsDock")->height() > before + 50);
    plots->raise();
    QTRY_VERIFY2(std::abs(plots->height() - before) <= 8,
                 qPrintable(QStringLiteral("%1 then %2").arg(before).arg(plots->height())));
    // View > Reset layout: a floating dock and a closed one come back, the plots balanced
    dock("pathDock")->setFloating(true);
    plots->close();
    auto* reset = m_window->menuBar()->findChild<QAction*>(QStringLiteral("resetLayoutAction"));
    QVERIFY(reset);
    reset->trigger();
    QVERIFY(!dock("pathDock")->isFloating());
    QVERIFY(plots->isVisible());
    QCOMPARE(m_window->dockWidgetArea(plots), Qt::BottomDockWidgetArea);
    QTRY_VERIFY2(std::abs(plots->height() - balancedPlotsHeight(m_window->height())) <= 8,
                 qPrintable(QString::number(plots->height())));
}

void TestFraming::plotsRecoverAtTheNextStart() {
    // a window closed with the tall Methods tab in front of the plots: at the next start the
    // layout is restored as it was, and bringing the plots to the front gives them about their
    // balanced height again, not the Methods tab's (334 px here)
    m_window.reset();
    // a first start maximises the window on the small offscreen screen: 1280 x 800 instead
    auto first = std::make_unique<MainWindow>(true);
    first->setWindowState(Qt::WindowNoState);
    first->resize(1280, 800);
    first->show();
    QVERIFY(QTest::qWaitForWindowExposed(first.get()));
    first->document()->flush();
    QTest::qWait(50);
    auto* plots = first->findChild<QDockWidget*>(QStringLiteral("plotsDock"));
    auto* methods = first->findChild<QDockWidget*>(QStringLiteral("methodsDock"));
    QVERIFY(plots && methods);
    const int before = plots->height();
    first->showMethodsDock();
    QTRY_VERIFY(methods->height() > before + 50);
    first->close(); // saves the layout
    first.reset();

    auto next = std::make_unique<MainWindow>(true);
    QCOMPARE(next->size(), QSize(1280, 800));
    next->show();
    QVERIFY(QTest::qWaitForWindowExposed(next.get()));
    next->document()->flush();
    QTest::qWait(50);
    plots = next->findChild<QDockWidget*>(QStringLiteral("plotsDock"));
    methods = next->findChild<QDockWidget*>(QStringLiteral("methodsDock"));
    const int balanced = balancedPlotsHeight(next->height());
    // restored as it was left: the tall Methods tab in front
    QVERIFY2(methods->height() > balanced + 50,
             qPrintable(QStringLiteral("%1 px, balanced %2").arg(methods->height()).arg(balanced)));
    plots->raise();
    // within a tab bar's height of the balanced height (the restored bottom area keeps its tabs)
    QTRY_VERIFY2(
        plots->height() <= balanced + 30,
        qPrintable(QStringLiteral("%1 px, balanced %2").arg(plots->height()).arg(balanced)));
    next.reset();
    QSettings().clear();
}

void TestFraming::pinKeyStaysClearOfTheDrawHint() {
    // draw mode writes its hint under the time line, where the pins' key starts
    Scene scene = presetScene("sinusoid");
    PinnedRun pin{scene.path, scene.system, scene.mode, scene.speed, scene.tEnd};
    pin.system.params["b"] = 2.2;
    scene.pins.push_back(pin);
    scene.pins.push_back(pin);
    m_window->loadScene(scene);
    m_window->document()->flush();
    QCOMPARE(m_window->document()->pins()->count(), 2);
    SceneCanvas* canvas = m_window->canvas();
    for (QSize size : {QSize(1024, 768), QSize(1280, 800), QSize(1920, 1080)}) {
        m_window->resize(size);
        QCoreApplication::processEvents();
        canvas->setDrawMode(false);
        QVERIFY(canvas->drawHintBounds().isEmpty());
        const QRectF key = canvas->pinKeyBounds();
        QVERIFY(!key.isEmpty());
        canvas->setDrawMode(true);
        const QRectF hint = canvas->drawHintBounds(), moved = canvas->pinKeyBounds();
        QVERIFY(!hint.isEmpty());
        // the hint is whole: wrapped inside the canvas, not cut at its right edge
        QVERIFY2(hint.left() >= 0 && hint.right() <= canvas->width(),
                 qPrintable(QStringLiteral("hint %1..%2 px of %3")
                                .arg(hint.left())
                                .arg(hint.right())
                                .arg(canvas->width())));
        QVERIFY2(!hint.intersects(moved), qPrintable(QStringLiteral("hint %1..%2 px, key %3..%4 px")
                                                         .arg(hint.top())
                                                         .arg(hint.bottom())
                                                         .arg(moved.top())
                                                         .arg(moved.bottom())));
        // it keeps its size, and stays in the drawing area
        QCOMPARE(moved.size(), key.size());
        QVERIFY(canvas->drawingArea().contains(moved));
        canvas->setDrawMode(false);
    }
}

QTEST_MAIN(TestFraming)
#include "test_framing.moc"
