#include "shell/instruments.h"

#include "canvas/scene_canvas.h"
#include "canvas/vector_painter.h"
#include "document/pin_set.h"
#include "document/scene_document.h"
#include "document/scene_texts.h"
#include "panels/equations_panel.h"
#include "panels/notes_panel.h"
#include "scene/pinned_runs.h"
#include "shell/main_window.h"
#include "shell/playback.h"
#include "shell/presentation_mode.h"

#include <QDockWidget>
#include <QMenuBar>
#include <QStatusBar>

namespace chaplygin::ui {

VectorsMenu::VectorsMenu(MainWindow* window) : QMenu(tr("&Vectors"), window), m_window(window) {
    setObjectName(QStringLiteral("vectorsMenu"));
    for (int i = 0; i < kVectorKinds; ++i) {
        auto kind = VectorKind(i);
        QAction* a = addAction(vectorName(kind));
        a->setCheckable(true);
        a->setObjectName(QStringLiteral("vector_") + vectorSymbol(kind));
        connect(a, &QAction::triggered, this, [this, kind](bool on) {
            Scene next = m_window->document()->scene();
            (next.vectors.*vectorToggle(kind)).shown = on;
            m_window->editScene(next, on ? tr("Show %1").arg(vectorName(kind))
                                         : tr("Hide %1").arg(vectorName(kind)));
        });
        m_toggles[i] = a;
    }
    addSeparator();
    addAction(tr("&Longer arrows"), this, [this] { rescale(2); });
    addAction(tr("&Shorter arrows"), this, [this] { rescale(0.5); });
    addAction(tr("&Automatic lengths"), this, [this] { rescale(0); });
    connect(window->document(), &SceneDocument::solutionChanged, this, &VectorsMenu::sync);
}

void VectorsMenu::sync() {
    const VectorOverlay& o = m_window->document()->scene().vectors;
    for (int i = 0; i < kVectorKinds; ++i)
        m_toggles[i]->setChecked((o.*vectorToggle(VectorKind(i))).shown);
}

void VectorsMenu::rescale(double factor) {
    SceneDocument* doc = m_window->document();
    if (!doc->solution())
        return;
    Scene next = doc->scene();
    VectorScales now = m_window->canvas()->vectorLayer().scales(doc->solution(), next.vectors);
    for (int i = 0; i < kVectorKinds; ++i) {
        VectorToggle& t = next.vectors.*vectorToggle(VectorKind(i));
        if (t.shown || factor == 0)
            t.scale = factor * now[std::size_t(i)];
    }
    m_window->editScene(next, factor == 0 ? tr("Automatic arrow lengths")
                                          : tr("Arrow lengths \u00d7%1").arg(factor));
}

CompareMenu::CompareMenu(MainWindow* window) : QMenu(tr("&Compare"), window), m_window(window) {
    setObjectName(QStringLiteral("compareMenu"));
    m_pin = addAction(tr("&Pin this run"), QKeySequence(tr("Ctrl+Shift+P")), this, [this] {
        Scene next = m_window->document()->scene();
        if (next.pins.size() >= kMaxPinnedRuns) {
            m_window->statusBar()->showMessage(
                tr("At most %1 pinned runs: clear them first").arg(kMaxPinnedRuns), 6000);
            return;
        }
        next.pins.push_back(pinOf(next));
        m_window->editScene(next, tr("Pin this run"));
    });
    m_pin->setStatusTip(tr("Keep this motion as a faint overlay on the canvas and the plots"));
    m_clear = addAction(tr("&Clear pins"), this, [this] {
        Scene next = m_window->document()->scene();
        next.pins.clear();
        m_window->editScene(next, tr("Clear pins"));
    });
    connect(window->document(), &SceneDocument::solutionChanged, this, &CompareMenu::sync);
    connect(window->document(), &SceneDocument::errorChanged, this, &CompareMenu::sync);
}

void CompareMenu::sync() {
    const Scene& s = m_window->document()->scene();
    bool pinned = false;
    for (const PinnedRun& p : s.pins)
        pinned = pinned || p == pinOf(s);
    m_pin->setEnabled(s.pins.size() < kMaxPinnedRuns && !pinned &&
                      m_window->document()->error().isEmpty());
    m_clear->setEnabled(!s.pins.empty());
}

void installInstruments(MainWindow* window, QMenu& viewMenu, QDockWidget& accuracyDock) {
    SceneDocument* doc = window->document();
    auto* notes = new NotesPanel;
    auto* notesDock = new QDockWidget(MainWindow::tr("Notes"), window);
    notesDock->setObjectName(QStringLiteral("notesDock"));
    notesDock->setWidget(notes);
    auto* equations = new EquationsPanel(doc);
    auto* equationsDock = new QDockWidget(MainWindow::tr("Equations"), window);
    equationsDock->setObjectName(QStringLiteral("equationsDock"));
    equationsDock->setWidget(equations);
    window->addDockWidget(Qt::RightDockWidgetArea, notesDock);
    window->addDockWidget(Qt::RightDockWidgetArea, equationsDock);
    window->tabifyDockWidget(&accuracyDock, notesDock);
    window->tabifyDockWidget(notesDock, equationsDock);
    accuracyDock.raise();
    QObject::connect(doc, &SceneDocument::solutionChanged, notes,
                     [doc, notes] { notes->setNote(sceneText(doc->scene().note)); });
    // presenting: the equations are not needed, the notes only when the scene has one
    PresentationMode* presentation = window->presentation();
    presentation->addHiddenDock(equationsDock);
    presentation->addDockWhile(notesDock, [doc] { return !doc->scene().note.empty(); });
    QObject::connect(doc, &SceneDocument::solutionChanged, presentation,
                     &PresentationMode::updateDocks);
    QObject::connect(presentation, &PresentationMode::activeChanged, notes,
                     &NotesPanel::setPresenting);
    QObject::connect(notes, &NotesPanel::noteEdited, window, [window, doc](const QString& text) {
        Scene next = doc->scene();
        next.note = text.toStdString();
        if (next.note.size() > kMaxNoteBytes) {
            // a longer note would save a file that does not open again
            window->statusBar()->showMessage(
                MainWindow::tr("The note is %1 bytes; a note is at most %2 bytes (not kept)")
                    .arg(next.note.size())
                    .arg(kMaxNoteBytes),
                10000);
            return;
        }
        window->editScene(next, MainWindow::tr("Edit the note"), QStringLiteral("note"));
    });
    QObject::connect(window->playback(), &Playback::timeChanged, equations,
                     &EquationsPanel::setTime);
    // its tab brought to the front: the page catches up with the time
    QObject::connect(equationsDock, &QDockWidget::visibilityChanged, equations,
                     [equations](bool on) {
                         if (on)
                             equations->html();
                     });

    QMenu* view = &viewMenu;
    QAction* first = view->actions().value(0);
    view->insertAction(first, notesDock->toggleViewAction());
    view->insertAction(first, equationsDock->toggleViewAction());
    view->addSeparator();
    view->addMenu(new VectorsMenu(window));
    auto* compare = new CompareMenu(window);
    QList<QAction*> menus = window->menuBar()->actions();
    window->menuBar()->insertMenu(menus.isEmpty() ? nullptr : menus.last(), compare);
}

} // namespace chaplygin::ui
