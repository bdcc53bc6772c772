#pragma once

class QAction;
class QMenu;

namespace chaplygin::ui {

class MainWindow;

/// File > Save annotations with the scene: whether File > Save writes the pen's marks into the
/// scene file (off unless asked, or unless the opened file had marks). The pen and the document
/// keep each other's marks: those of a scene that comes in go to the pen, the pen's to the
/// document (its autosaved copy, the undo step of a preset or gallery scene). Called once, by the
/// window, with its File menu.
void installSaveAnnotationsAction(MainWindow* window, QMenu& fileMenu);

/// Edit > Pen and Edit > Pen marks: the canvas's pen (docs/user-guide.md, Drawing over the lesson)
/// in the Edit menu, on the time line's toolbar and on keys (Ctrl+Shift+D; P on the canvas), its
/// arrows, colours, Undo last mark and Clear marks. While the pen is on, Ctrl+Z undoes the last
/// mark and never a scene edit (`sceneUndo` gives up the key meanwhile; Edit > Undo in the menu
/// still undoes the scene). The marks of a scene loaded with them come to the pen. Called once,
/// by the window, with its Edit menu.
void installPenActions(MainWindow* window, QMenu& editMenu, QAction& sceneUndo);

} // namespace chaplygin::ui
