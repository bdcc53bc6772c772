#include "shell/pen_actions.h"

#include "canvas/pen_tool.h"
#include "canvas/scene_canvas.h"
#include "document/scene_document.h"
#include "shell/main_window.h"
#include "shell/timeline_bar.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>

namespace chaplygin::ui {

void installSaveAnnotationsAction(MainWindow* window, QMenu& fileMenu) {
    PenTool* pen = window->canvas()->penTool();
    QAction* save = fileMenu.addAction(MainWindow::tr("Save anno&tations with the scene"));
    save->setObjectName(QStringLiteral("saveAnnotationsAction"));
    save->setCheckable(true);
    save->setChecked(pen->savesWithScene());
    save->setStatusTip(MainWindow::tr("File > Save also writes the pen's marks into the scene "
                                      "file; the scene's link and its computation are unchanged"));
    QObject::connect(save, &QAction::toggled, pen, &PenTool::setSavesWithScene);
    QObject::connect(pen, &PenTool::savesWithSceneChanged, save, &QAction::setChecked);
    // the marks of a scene that came in (a file saved with its marks is saved with them again),
    // and those a known scene's undo step gives back; the document knows the pen's for its copy
    // on disk and for those steps
    SceneDocument* document = window->document();
    QObject::connect(document, &SceneDocument::penMarksLoaded, pen, &PenTool::setPenMarks);
    auto tell = [pen, document] { document->setPenMarks(pen->penMarks()); };
    QObject::connect(pen, &PenTool::marksChanged, document, tell);
    QObject::connect(pen, &PenTool::savesWithSceneChanged, document, tell);
    tell();
}

void installPenActions(MainWindow* window, QMenu& editMenu, QAction& sceneUndo) {
    SceneCanvas* canvas = window->canvas();
    PenTool* pen = canvas->penTool();
    QAction* on = editMenu.addAction(MainWindow::tr("P&en (draw over the canvas)"));
    on->setObjectName(QStringLiteral("penAction"));
    on->setCheckable(true);
    on->setShortcut(QKeySequence(MainWindow::tr("Ctrl+Shift+D")));
    on->setIconText(MainWindow::tr("Pen"));
    on->setToolTip(MainWindow::tr(
        "Pen (P on the canvas): drag to draw over the canvas, Shift+drag for an arrow; C: next "
        "colour, A: arrows; Ctrl+Z undoes the last mark, E or Delete clears them all. The marks "
        "follow zoom and pan; the scene is not changed"));
    QObject::connect(on, &QAction::toggled, canvas, &SceneCanvas::setPenMode);
    QObject::connect(canvas, &SceneCanvas::penModeChanged, on, &QAction::setChecked);
    window->timeline()->addAction(on);

    QMenu* marks = editMenu.addMenu(MainWindow::tr("Pen mar&ks"));
    marks->setObjectName(QStringLiteral("penMenu"));
    QAction* arrows = marks->addAction(MainWindow::tr("&Arrows (A on the canvas)"));
    arrows->setObjectName(QStringLiteral("penArrowsAction"));
    arrows->setCheckable(true);
    QObject::connect(arrows, &QAction::toggled, pen, [pen](bool checked) {
        pen->setKind(checked ? MarkKind::Arrow : MarkKind::Freehand);
    });
    QObject::connect(pen, &PenTool::kindChanged, arrows,
                     [arrows](MarkKind kind) { arrows->setChecked(kind == MarkKind::Arrow); });
    marks->addSeparator();
    auto* colours = new QActionGroup(marks);
    for (int c = 0; c < kMarkColours; ++c) {
        QAction* colour = marks->addAction(PenTool::colourName(c));
        colour->setObjectName(QStringLiteral("penColour%1").arg(c));
        colour->setCheckable(true);
        colour->setChecked(c == pen->colour());
        colour->setActionGroup(colours);
        QPixmap swatch(16, 16);
        swatch.fill(PenTool::colourOf(c));
        colour->setIcon(QIcon(swatch));
        QObject::connect(colour, &QAction::triggered, pen, [pen, c] { pen->setColour(c); });
    }
    QObject::connect(pen, &PenTool::colourChanged, colours,
                     [colours](int c) { colours->actions().value(c)->setChecked(true); });
    marks->addSeparator();
    QAction* undo = marks->addAction(MainWindow::tr("&Undo last mark"));
    undo->setObjectName(QStringLiteral("penUndoAction"));
    QObject::connect(undo, &QAction::triggered, pen, &PenTool::undoLast);
    QAction* clear = marks->addAction(MainWindow::tr("&Clear marks"));
    clear->setObjectName(QStringLiteral("penClearAction"));
    QObject::connect(clear, &QAction::triggered, pen, &PenTool::clear);
    // the menu's keys reach the window wherever the focus is, with the menu bar hidden too
    window->addAction(undo);
    window->addAction(clear);
    // while the pen is on, Ctrl+Z is the pen's, and E and Delete clear its marks
    const QKeySequence undoKey = sceneUndo.shortcut();
    const QList<QKeySequence> clearKeys{QKeySequence(Qt::Key_Delete), QKeySequence(Qt::Key_E)};
    auto update = [=, &sceneUndo] {
        const bool drawing = canvas->penMode();
        sceneUndo.setShortcut(drawing ? QKeySequence() : undoKey);
        undo->setShortcut(drawing ? undoKey : QKeySequence());
        clear->setShortcuts(drawing ? clearKeys : QList<QKeySequence>());
        undo->setEnabled(!pen->marks().empty());
        clear->setEnabled(!pen->marks().empty());
    };
    QObject::connect(canvas, &SceneCanvas::penModeChanged, undo, update);
    QObject::connect(pen, &PenTool::marksChanged, undo, update);
    update();
}

} // namespace chaplygin::ui
