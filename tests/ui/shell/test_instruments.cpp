// GUI tests of the teaching instruments: arrows on the bodies, pinned runs, notes and the
// Equations panel, driven through the real window under the offscreen platform.
#include "canvas/scene_canvas.h"
#include "canvas/vector_painter.h"
#include "desktop_entry.h"
#include "document/pin_set.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "lab/gallery.h"
#include "panels/equations_panel.h"
#include "panels/notes_panel.h"
#include "plots/plots_panel.h"
#include "scene/body_vectors.h"
#include "scene/presets.h"
#include "scene/scene_json.h"
#include "shell/instruments.h"
#include "shell/main_window.h"
#include "shell/playback.h"

#include <QDockWidget>
#include <QPlainTextEdit>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QUndoStack>
#include <QtTest>
#include <qcustomplot.h>

#include <cmath>
#include <memory>
#include <numbers>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

Scene pivotScene() {
    Scene s;
    s.path.kind = PathKind::Polyline;
    s.path.points = {{0, 0}, {1, 0}, {1, 1}};
    s.path.corners = CornerMode::Pivot;
    return s;
}

double distance(QPointF a, QPointF b) {
    return std::hypot(a.x() - b.x(), a.y() - b.y());
}

const ArrowShape* findArrow(const VectorShapes& shapes, VectorKind kind) {
    for (const ArrowShape& a : shapes.arrows)
        if (a.kind == kind)
            return &a;
    return nullptr;
}

bool near(const QColor& a, const QColor& b, int tolerance) {
    return std::abs(a.red() - b.red()) <= tolerance &&
           std::abs(a.green() - b.green()) <= tolerance &&
           std::abs(a.blue() - b.blue()) <= tolerance;
}

} // namespace

class TestInstruments : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase();
    void init();
    void cleanup();

    void knifeVelocityArrowDrawnAtP();
    void forcesAndCoupleOnCatenary();
    void pivotShowsCoupleAlone();
    void vectorsSavedLoadedAndUndone();
    void pinsUpToFiveOnCanvasAndPlots();
    void pinsSavedLoadedClearedAndUndone();
    void notesEditedSavedLoadedAndShown();
    void galleryNoteShown();
    void equationsFollowTimeSystemAndMode();
    void equationsInBackgroundTabWaitUntilRaised();
    void equationsDotsSetInAFaceThatPlacesThem();
    void equationsWhileBackingUpThroughACusp();
    void screenshotShowsArrowsAndEquations();

  private:
    void showVector(VectorKind kind, bool on = true);
    void setB(double b);
    VectorsMenu* vectorsMenu() const { return m_window->findChild<VectorsMenu*>(); }
    CompareMenu* compareMenu() const { return m_window->findChild<CompareMenu*>(); }

    std::unique_ptr<MainWindow> m_window;
    QTemporaryDir m_dir;
};

void TestInstruments::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_instruments_tests"));
}

void TestInstruments::init() {
    m_window = test::showTestWindow();
    QVERIFY(m_window && m_window->document()->solution());
    QVERIFY(vectorsMenu() && compareMenu());
}

void TestInstruments::cleanup() {
    m_window.reset();
}

void TestInstruments::showVector(VectorKind kind, bool on) {
    QAction* a = vectorsMenu()->toggle(int(kind));
    if (a->isChecked() != on)
        a->trigger();
    m_window->document()->flush();
}

void TestInstruments::setB(double b) {
    Scene s = m_window->document()->scene();
    s.system.params["b"] = b;
    m_window->editScene(s, QStringLiteral("b"));
    m_window->document()->flush();
}

void TestInstruments::knifeVelocityArrowDrawnAtP() {
    SceneCanvas* canvas = m_window->canvas();
    QVERIFY(canvas->vectorLayer().controlledShapes().arrows.empty());
    showVector(VectorKind::KnifeVelocity);
    QVERIFY(m_window->document()->scene().vectors.knifeVelocity.shown);
    const double t = 6.0;
    m_window->playback()->seek(t);
    QImage image = canvas->grab().toImage();
    const auto& solution = m_window->document()->solution();
    MotionSample m = solution->at(t);
    const ArrowShape* arrow =
        findArrow(canvas->vectorLayer().controlledShapes(), VectorKind::KnifeVelocity);
    QVERIFY(arrow);
    // the tail is P; the arrow points along s-hat with length sdot x scale
    QVERIFY(distance(arrow->tail, canvas->toPixel({m.x, m.y})) < 0.5);
    double k = canvas->vectorLayer().scales(
        solution, m_window->document()->scene().vectors)[std::size_t(VectorKind::KnifeVelocity)];
    QPointF head = canvas->toPixel(
        {m.x + k * m.control.sdot * std::cos(m.phi), m.y + k * m.control.sdot * std::sin(m.phi)});
    QVERIFY2(distance(arrow->head, head) < 0.5, qPrintable(QStringLiteral("%1,%2 vs %3,%4")
                                                               .arg(arrow->head.x())
                                                               .arg(arrow->head.y())
                                                               .arg(head.x())
                                                               .arg(head.y())));
    QCOMPARE(arrow->value, m.control.sdot);
    QVERIFY(distance(arrow->head, arrow->tail) > 20); // visible
    // the shaft is painted in the arrow's colour (sampled 60% of the way along)
    QPointF mid = (arrow->tail + 0.6 * (arrow->head - arrow->tail)) * image.devicePixelRatio();
    QColor ink = image.pixelColor(mid.toPoint());
    QVERIFY2(near(ink, vectorColor(VectorKind::KnifeVelocity), 60), qPrintable(ink.name()));
    // the free ghost has its own, from its own knife point
    const ArrowShape* ghost =
        findArrow(canvas->vectorLayer().freeShapes(), VectorKind::KnifeVelocity);
    QVERIFY(ghost && ghost->ghost);
    QVERIFY(distance(ghost->tail, canvas->toPixel({m.free.x, m.free.y})) < 0.5);
    // hiding it removes it
    showVector(VectorKind::KnifeVelocity, false);
    canvas->grab();
    QVERIFY(canvas->vectorLayer().controlledShapes().arrows.empty());
}

void TestInstruments::forcesAndCoupleOnCatenary() {
    m_window->loadScene(presetScene("catenary"));
    for (VectorKind k : {VectorKind::AxialForce, VectorKind::LateralReaction,
                         VectorKind::ControlCouple, VectorKind::CmVelocity})
        showVector(k);
    SceneCanvas* canvas = m_window->canvas();
    const auto& solution = m_window->document()->solution();
    const double t = 0.3 * solution->tEnd();
    m_window->playback()->seek(t);
    canvas->grab();
    MotionSample m = solution->at(t);
    const VectorShapes& shapes = canvas->vectorLayer().controlledShapes();
    VectorScales k = canvas->vectorLayer().scales(solution, m_window->document()->scene().vectors);
    const double a = solution->system().a;
    QPointF c = canvas->toPixel({m.x + a * std::cos(m.phi), m.y + a * std::sin(m.phi)});
    // N acts at P along n-hat = (-sin phi, cos phi)
    const ArrowShape* n = findArrow(shapes, VectorKind::LateralReaction);
    QVERIFY(n);
    double N = m.control.knifeReaction;
    QVERIFY(std::fabs(N) > 1e-3);
    QPointF nHead =
        canvas->toPixel({m.x - k[2] * N * std::sin(m.phi), m.y + k[2] * N * std::cos(m.phi)});
    QVERIFY(distance(n->tail, canvas->toPixel({m.x, m.y})) < 0.5);
    QVERIFY(distance(n->head, nHead) < 0.5);
    // f_s acts at the centre of mass along s-hat
    const ArrowShape* fs = findArrow(shapes, VectorKind::AxialForce);
    QVERIFY(fs);
    QVERIFY(distance(fs->tail, c) < 0.5);
    QCOMPARE(fs->value, std::fabs(m.control.forceAxial));
    // the couple: an arc about C whose span is tau x scale, counter-clockwise for tau > 0
    QCOMPARE(int(canvas->vectorLayer().controlledShapes().couples.size()), 1);
    const CoupleShape& couple = shapes.couples.front();
    QVERIFY(distance(couple.centre, c) < 0.5);
    double tau = m.control.controlCouple;
    QVERIFY(std::fabs(tau) > 1e-3);
    QCOMPARE(couple.value, tau);
    QVERIFY(std::fabs(couple.spanDeg - tau * k[3] * 180 / std::numbers::pi) < 1e-9);
    QVERIFY(std::fabs(couple.spanDeg) > 20);
    // the centre of mass velocity: sdot s-hat + a phidot n-hat
    const ArrowShape* vc = findArrow(shapes, VectorKind::CmVelocity);
    QVERIFY(vc);
    QCOMPARE(vc->value, std::hypot(m.control.sdot, a * m.control.phidot));
    // the free ghost carries no control force or couple, but its knife's reaction
    const VectorShapes& free = canvas->vectorLayer().freeShapes();
    QVERIFY(findArrow(free, VectorKind::LateralReaction));
    const ArrowShape* freeFs = findArrow(free, VectorKind::AxialForce);
    QVERIFY(!freeFs || freeFs->value == 0);
}

void TestInstruments::pivotShowsCoupleAlone() {
    m_window->loadScene(pivotScene());
    for (int i = 0; i < kVectorKinds; ++i)
        showVector(VectorKind(i));
    SceneCanvas* canvas = m_window->canvas();
    // to scale, framed with the whole body: the couple's circle around the centre of mass, half
    // a metre ahead of P on a path 1 m wide, stays in view
    CanvasStyle style = canvas->canvasStyle();
    style.body = BodyDisplay::ToScale;
    canvas->setCanvasStyle(style);
    canvas->fitEverything();
    // on the first straight side (t < 1 s) the knife velocity is drawn
    m_window->playback()->seek(0.5);
    canvas->grab();
    QVERIFY(findArrow(canvas->vectorLayer().controlledShapes(), VectorKind::KnifeVelocity));
    // turning in place at the corner (1 s < t < 1 + b pi/2 / v_T): the couple alone
    m_window->playback()->seek(1.5);
    QImage image = canvas->grab().toImage();
    const VectorShapes& shapes = canvas->vectorLayer().controlledShapes();
    QVERIFY(shapes.arrows.empty());
    QCOMPARE(int(shapes.couples.size()), 1);
    QVERIFY(shapes.couples.front().pivot);
    // the couple's circle is drawn around the centre of mass
    const CoupleShape& c = shapes.couples.front();
    QPointF rim = (c.centre + QPointF(c.radius, 0)) * image.devicePixelRatio();
    bool inked = false;
    for (int dx = -2; dx <= 2 && !inked; ++dx)
        for (int dy = -2; dy <= 2 && !inked; ++dy)
            inked = near(image.pixelColor(rim.toPoint() + QPoint(dx, dy)),
                         vectorColor(VectorKind::ControlCouple), 70);
    QVERIFY(inked);
}

void TestInstruments::vectorsSavedLoadedAndUndone() {
    showVector(VectorKind::LateralReaction);
    QAction* longer = nullptr;
    for (QAction* a : vectorsMenu()->actions())
        if (a->text().contains(QStringLiteral("Longer")))
            longer = a;
    QVERIFY(longer);
    m_window->canvas()->grab();
    longer->trigger();
    m_window->document()->flush();
    double scale = m_window->document()->scene().vectors.lateralReaction.scale;
    QVERIFY(scale > 0);
    QString path = m_dir.filePath(QStringLiteral("vectors.json"));
    QVERIFY(m_window->saveFile(path));
    m_window->loadScene(presetScene("line"));
    QVERIFY(!vectorsMenu()->toggle(int(VectorKind::LateralReaction))->isChecked());
    QVERIFY(m_window->openFile(path));
    QVERIFY(vectorsMenu()->toggle(int(VectorKind::LateralReaction))->isChecked());
    QCOMPARE(m_window->document()->scene().vectors.lateralReaction.scale, scale);
    // a toggle is an undo step
    showVector(VectorKind::ControlCouple);
    QVERIFY(m_window->document()->scene().vectors.controlCouple.shown);
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QVERIFY(!m_window->document()->scene().vectors.controlCouple.shown);
    QVERIFY(!vectorsMenu()->toggle(int(VectorKind::ControlCouple))->isChecked());
}

void TestInstruments::pinsUpToFiveOnCanvasAndPlots() {
    QAction* pin = compareMenu()->pinAction();
    const double bs[] = {1.0, 0.6, 1.4, 1.8, 2.2};
    for (double b : bs) {
        setB(b);
        QVERIFY(pin->isEnabled());
        pin->trigger();
        m_window->document()->flush();
        QVERIFY(!pin->isEnabled()); // this run is pinned already
    }
    setB(0.55); // the live body runs ahead of every pin
    QCOMPARE(int(m_window->document()->scene().pins.size()), 5);
    QVERIFY(!pin->isEnabled()); // five is the most
    pin->trigger();
    QCOMPARE(int(m_window->document()->scene().pins.size()), 5);
    PinSet* pins = m_window->document()->pins();
    QCOMPARE(pins->count(), 5);
    QCOMPARE(pins->label(0), QStringLiteral("b = 1 m"));
    QCOMPARE(pins->label(1), QStringLiteral("b = 0.6 m"));
    // each pinned run is its own motion: b = 0.6 runs the sinusoid sooner than b = 2.2
    QVERIFY(pins->run(1).solution->tEnd() < pins->run(4).solution->tEnd());
    // the plots: one graph per pin, named by what differs, in the pin's colour
    QCustomPlot* psi = m_window->plotsPanel()->plot(0);
    int found = 0;
    for (int g = 0; g < psi->graphCount(); ++g) {
        QString name = psi->graph(g)->name();
        for (int i = 0; i < 5; ++i) {
            if (name == pins->label(i)) {
                ++found;
                QCOMPARE(psi->graph(g)->pen().color().rgb(), PinSet::color(i).rgb());
                QCOMPARE(psi->graph(g)->dataCount(), pins->run(i).series.t.size());
            }
        }
    }
    QCOMPARE(found, 5);
    // the canvas: each pin's body sits where its run is at t, drawn in the pin's colour
    const double t = 5.0;
    m_window->playback()->seek(t);
    SceneCanvas* canvas = m_window->canvas();
    canvas->setFollowBody(true); // close up on the live body, with the pins behind it
    canvas->zoomBy(4);
    QImage image = canvas->grab().toImage();
    // (the pins' dots are checked where no free or vakonomic body is drawn over them)
    MotionSample live = m_window->document()->solution()->at(t);
    int checked = 0;
    for (int i = 0; i < 5; ++i) {
        MotionSample m = pins->run(i).solution->at(t);
        bool covered = false;
        // (the live body, b = 0.55, runs ahead: its small board covers only a pin right at P)
        for (QPointF other : {QPointF(live.free.x, live.free.y), QPointF(live.vak.x, live.vak.y)})
            covered = covered || std::hypot(m.x - other.x(), m.y - other.y()) < 3.0;
        covered = covered || std::hypot(m.x - live.x, m.y - live.y) < 0.3;
        QPointF px = canvas->toPixel({m.x, m.y}) * image.devicePixelRatio();
        for (int j = 0; j < 5; ++j) {
            // another pin's dot within reach would paint over this one
            MotionSample o = pins->run(j).solution->at(t);
            QPointF q = canvas->toPixel({o.x, o.y}) * image.devicePixelRatio();
            covered = covered || (j != i && distance(px, q) < 10 * image.devicePixelRatio());
        }
        if (covered)
            continue;
        QColor c = image.pixelColor(px.toPoint());
        QVERIFY2(near(c, PinSet::color(i), 40),
                 qPrintable(QStringLiteral("pin %1: %2").arg(i).arg(c.name())));
        ++checked;
    }
    QVERIFY(checked > 0);
}

void TestInstruments::pinsSavedLoadedClearedAndUndone() {
    QAction* pin = compareMenu()->pinAction();
    for (double b : {0.5, 1.0, 1.5}) {
        setB(b);
        pin->trigger();
        m_window->document()->flush();
    }
    QCOMPARE(int(m_window->document()->scene().pins.size()), 3);
    QString path = m_dir.filePath(QStringLiteral("pins.json"));
    QVERIFY(m_window->saveFile(path));
    // the file keeps the pinned scenes' parameters
    Scene onDisk = loadSceneFile(path.toStdString());
    QCOMPARE(int(onDisk.pins.size()), 3);
    QCOMPARE(onDisk.pins[0].system.params.at("b"), 0.5);
    compareMenu()->clearAction()->trigger();
    m_window->document()->flush();
    QCOMPARE(m_window->document()->pins()->count(), 0);
    QVERIFY(!compareMenu()->clearAction()->isEnabled());
    // clearing is one undo step
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QCOMPARE(m_window->document()->pins()->count(), 3);
    m_window->undoStack()->redo();
    m_window->document()->flush();
    QCOMPARE(m_window->document()->pins()->count(), 0);
    // loading recomputes them
    QVERIFY(m_window->openFile(path));
    PinSet* pins = m_window->document()->pins();
    QCOMPARE(pins->count(), 3);
    QVERIFY(pins->run(0).solution);
    QCOMPARE(pins->run(0).solution->system().b, 0.5);
    // a file whose pin does not solve is refused with the place, and the scene stays
    onDisk.pins[1].system.params["b"] = 0.1; // b < |a| = 0.5
    QString bad = m_dir.filePath(QStringLiteral("bad_pin.json"));
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(QByteArray::fromStdString(sceneToJson(onDisk)));
    f.close();
    QVERIFY(!m_window->openFile(bad));
    QVERIFY2(m_window->lastFileError().contains(QStringLiteral("/pins/1")),
             qPrintable(m_window->lastFileError()));
    QCOMPARE(m_window->document()->pins()->count(), 3);
}

void TestInstruments::notesEditedSavedLoadedAndShown() {
    auto* notes = m_window->findChild<NotesPanel*>();
    QVERIFY(notes);
    notes->setEditing(true);
    QTest::keyClicks(notes->editor(), QStringLiteral("# Sinusoid"));
    QTest::keyClick(notes->editor(), Qt::Key_Return);
    QTest::keyClick(notes->editor(), Qt::Key_Return);
    QTest::keyClicks(notes->editor(), QStringLiteral("The sleigh **slows** in bends."));
    m_window->document()->flush();
    QCOMPARE(QString::fromStdString(m_window->document()->scene().note),
             QStringLiteral("# Sinusoid\n\nThe sleigh **slows** in bends."));
    // rendered as Markdown: the heading is a heading, the emphasis bold, no asterisks
    QString shown = notes->view()->toPlainText();
    QVERIFY2(shown.contains(QStringLiteral("The sleigh slows in bends.")), qPrintable(shown));
    QVERIFY(!shown.contains(QStringLiteral("**")));
    QVERIFY(notes->view()->toHtml().contains(QStringLiteral("font-weight:700")) ||
            notes->view()->toHtml().contains(QStringLiteral("font-weight:600")));
    // the typing is one undo step
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QVERIFY(m_window->document()->scene().note.empty());
    QVERIFY(notes->note().isEmpty());
    m_window->undoStack()->redo();
    m_window->document()->flush();
    QString path = m_dir.filePath(QStringLiteral("note.json"));
    QVERIFY(m_window->saveFile(path));
    m_window->loadScene(presetScene("line"));
    QVERIFY(notes->note().isEmpty());
    QVERIFY(m_window->openFile(path));
    QVERIFY(notes->view()->toPlainText().contains(QStringLiteral("slows in bends")));
    // a note too long to load again is not kept, and the window says why
    std::string kept = m_window->document()->scene().note;
    notes->editor()->setPlainText(QString(int(kMaxNoteBytes) + 1, u'x'));
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene().note, kept);
    QVERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("at most")));
    notes->editor()->setPlainText(QString::fromStdString(kept));
    // presentation mode enlarges the text
    double before = notes->view()->font().pointSizeF();
    notes->setFontScale(2.5);
    QVERIFY(std::fabs(notes->view()->font().pointSizeF() - 2.5 * before) < 0.01);
}

void TestInstruments::galleryNoteShown() {
    auto* notes = m_window->findChild<NotesPanel*>();
    QVERIFY(m_window->loadGalleryEntry(QStringLiteral("corner-pivot")));
    const GalleryEntry& e = galleryEntry("corner-pivot");
    QVERIFY(!e.scene.note.empty());
    QCOMPARE(notes->note(), QString::fromStdString(e.scene.note));
    QVERIFY(notes->view()->toPlainText().contains(QStringLiteral("pivot")) ||
            notes->view()->toPlainText().contains(QStringLiteral("turns about")));
}

void TestInstruments::equationsWhileBackingUpThroughACusp() {
    auto* panel = m_window->findChild<EquationsPanel*>();
    QVERIFY(m_window->loadGalleryEntry(QStringLiteral("cusp")));
    const auto& solution = m_window->document()->solution();
    QCOMPARE(solution->path()->pieces().size(), std::size_t(2));
    // before the cusp: the forward branch; after it: sdot < 0 and Psi < 0, shown as atan2(sdot, b
    // phidot)
    m_window->playback()->seek(1.0);
    QVERIFY(panel->html().contains(QStringLiteral("atan2(1, b\u03ba)")));
    const double after = 0.75 * solution->duration();
    m_window->playback()->seek(after);
    MotionSample m = solution->at(after);
    QVERIFY(m.control.sdot < 0 && m.control.psi < 0);
    const QString html = panel->html();
    QVERIFY2(html.contains(QStringLiteral("atan2(\u1e61, b\u03c6\u0307)")), qPrintable(html));
    QString psi = QString::number(m.control.psi, 'g', 4).replace(u'-', QStringLiteral("\u2212"));
    QVERIFY2(html.contains(QStringLiteral("<b>= %1</b>").arg(psi)), qPrintable(html));
    // dt/ds is the time per metre travelled: positive while backing up
    QString rate = QString::number(1 / std::fabs(m.control.sdot), 'g', 4);
    QVERIFY2(html.contains(QStringLiteral("<b>= %1</b>").arg(rate)), qPrintable(html));
}

void TestInstruments::equationsFollowTimeSystemAndMode() {
    auto* panel = m_window->findChild<EquationsPanel*>();
    QVERIFY(panel);
    m_window->playback()->seek(1.0);
    QCOMPARE(panel->time(), 1.0);
    QString at1 = panel->html();
    const auto& solution = m_window->document()->solution();
    MotionSample m = solution->at(1.0);
    // energy mode: (34), (35), the corrected dt/ds, lambda with its substitution
    for (const char* text :
         {"(34)", "(35)", "(45)", "(51)", "(25), (33)", "(D15)", "atan2(1, b\u03ba)"})
        QVERIFY2(at1.contains(QString::fromUtf8(text)), text);
    QVERIFY(!at1.contains(QStringLiteral("(C16)")));
    // the live values are the Solution's at t
    QVERIFY(
        at1.contains(QStringLiteral("<b>= %1</b>").arg(QString::number(m.control.psi, 'g', 4))));
    QString lambda =
        QString::number(m.control.lambda, 'g', 4).replace(u'-', QStringLiteral("\u2212"));
    QVERIFY(at1.contains(QStringLiteral("<b>= %1</b>").arg(lambda)));
    m_window->playback()->seek(5.0);
    QString at5 = panel->html();
    QVERIFY(at5 != at1);
    QVERIFY(at5.contains(QStringLiteral("t = <b>5 s</b>")));
    // speed mode: App. C
    Scene s = m_window->document()->scene();
    s.mode = SpeedMode::Speed;
    m_window->editScene(s, QStringLiteral("mode"));
    m_window->document()->flush();
    QString speed = panel->html();
    QVERIFY(speed.contains(QStringLiteral("(C16)")) && speed.contains(QStringLiteral("(C15)")));
    QVERIFY(!speed.contains(QStringLiteral("(34)")));
    // the disk: its reduction (A14)
    s.mode = SpeedMode::Energy;
    s.system.kind = SystemKind::Disk;
    s.system.params = defaultSystemParams(SystemKind::Disk);
    m_window->editScene(s, QStringLiteral("disk"));
    m_window->document()->flush();
    QString disk = panel->html();
    QVERIFY(disk.contains(QStringLiteral("(A14)")));
    QVERIFY(disk.contains(QStringLiteral("Rolling disk")));
    // shown in its dock, rendered
    auto* dock = m_window->findChild<QDockWidget*>(QStringLiteral("equationsDock"));
    QVERIFY(dock);
    dock->show();
    dock->raise();
    QVERIFY(panel->view()->toPlainText().contains(QStringLiteral("Rolling disk")));
    // presentation mode enlarges it
    double points = panel->view()->font().pointSizeF();
    panel->setFontScale(2);
    QVERIFY(std::fabs(panel->view()->font().pointSizeF() - 2 * points) < 0.01);
}

void TestInstruments::equationsInBackgroundTabWaitUntilRaised() {
    // the Equations dock starts as a tab behind Accuracy: Qt moves it out of the window
    auto* panel = m_window->findChild<EquationsPanel*>();
    auto* dock = m_window->findChild<QDockWidget*>(QStringLiteral("equationsDock"));
    auto* accuracy = m_window->findChild<QDockWidget*>(QStringLiteral("accuracyDock"));
    QVERIFY(panel && dock && accuracy);
    accuracy->raise();
    QCoreApplication::processEvents();
    QVERIFY(panel->visibleRegion().isEmpty());
    // playing does not lay out a page nobody sees
    m_window->playback()->seek(2.0);
    QVERIFY(!panel->view()->toPlainText().contains(QStringLiteral("t = 2 s")));
    // raised, it shows the current time at once, and follows the time from then on
    dock->raise();
    QCoreApplication::processEvents();
    QVERIFY(!panel->visibleRegion().isEmpty());
    QVERIFY(panel->view()->toPlainText().contains(QStringLiteral("t = 2 s")));
    m_window->playback()->seek(3.0);
    QVERIFY(panel->view()->toPlainText().contains(QStringLiteral("t = 3 s")));
    // behind another tab again, it waits again
    accuracy->raise();
    QCoreApplication::processEvents();
    m_window->playback()->seek(4.0);
    QVERIFY(!panel->view()->toPlainText().contains(QStringLiteral("t = 4 s")));
    QVERIFY(panel->html().contains(QStringLiteral("t = <b>4 s</b>")));
}

void TestInstruments::equationsDotsSetInAFaceThatPlacesThem() {
    // the page's φ̇ and Ψ̇ are set in the face whose dot sits on a Greek letter (document/
    // math_text.h); the letters without a dot keep the page's face
    auto* panel = m_window->findChild<EquationsPanel*>();
    auto* dock = m_window->findChild<QDockWidget*>(QStringLiteral("equationsDock"));
    QVERIFY(panel && dock);
    dock->raise();
    QCoreApplication::processEvents();
    QTextDocument* doc = panel->view()->document();
    int dotted = 0;
    for (const QString& symbol : {QStringLiteral("\u03c6\u0307"), QStringLiteral("\u03a8\u0307")})
        for (QTextCursor c = doc->find(symbol); !c.isNull(); c = doc->find(symbol, c)) {
            QVERIFY2(c.charFormat().fontFamilies().toStringList().contains(
                         QStringLiteral("DejaVu Serif")),
                     qPrintable(symbol));
            ++dotted;
        }
    QVERIFY2(dotted >= 4, qPrintable(QString::number(dotted)));
    QTextCursor plain = doc->find(QStringLiteral("\u03ba"));
    QVERIFY(!plain.isNull());
    QVERIFY(
        !plain.charFormat().fontFamilies().toStringList().contains(QStringLiteral("DejaVu Serif")));
}

void TestInstruments::screenshotShowsArrowsAndEquations() {
    // a scene file with the knife's reaction shown, rendered by the screenshot mode
    Scene s = presetScene("catenary");
    s.vectors.lateralReaction.shown = true;
    QString scene = m_dir.filePath(QStringLiteral("arrows.json"));
    QFile f(scene);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(QByteArray::fromStdString(sceneToJson(s)));
    f.close();
    QString shot = m_dir.filePath(QStringLiteral("arrows.png"));
    QByteArray sceneArg = scene.toUtf8(), shotArg = shot.toUtf8();
    const char* args[] = {
        "chaplygin-lab", "--screenshot", shotArg.constData(), "--scene",  sceneArg.constData(),
        "--at",          "0.8",          "--panel",           "equations"};
    QCOMPARE(runScreenshot(9, const_cast<char**>(args)), 0);
    QImage image(shot);
    QVERIFY(!image.isNull());
    int magenta = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            magenta += near(image.pixelColor(x, y), vectorColor(VectorKind::LateralReaction), 30);
    QVERIFY2(magenta > 40, qPrintable(QString::number(magenta))); // the arrow and its scale bar
    const char* bad[] = {"chaplygin-lab", "--screenshot", shotArg.constData(), "--preset",
                         "line",          "--panel",      "nonsense"};
    QCOMPARE(runScreenshot(7, const_cast<char**>(bad)), 2);
}

QTEST_MAIN(TestInstruments)
#include "test_instruments.moc"
