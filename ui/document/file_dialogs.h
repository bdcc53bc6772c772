#pragma once
#include "scene/scene.h"

#include <QString>

#include <functional>

class QWidget;

namespace chaplygin::ui {

/// File dialogs that propose a name, add the chosen filter's extension and remember the last
/// folder per purpose ("scene", "csv", "plots", "plot", "animation").

/// path with the first extension of selectedFilter ("Scenes (*.json)") appended when its suffix
/// matches none of the filter's patterns; unchanged for "All files (*)" or an empty path.
QString withFilterExtension(const QString& path, const QString& selectedFilter);

/// A file stem from a scene: its file's base name, its preset, or its path kind
/// ("graph-sin", "parametric", "drawn"); letters, digits, '-' and '_' only.
QString sceneFileStem(const Scene& scene, const QString& fileName = {});

/// A folder that exists: the one last used for purpose (QSettings "dialogs/<purpose>"); when
/// there is none or it is gone, the last one used for any purpose; else the documents folder,
/// else home.
QString lastFolder(const QString& purpose);
void rememberFolder(const QString& purpose, const QString& fileOrFolder);

/// What a save dialog returns: the chosen path and filter (empty path: cancelled).
struct DialogChoice {
    QString path;
    QString filter;
};
/// Replaces the real dialogs (tests and the randomized GUI test): receives the caption, the
/// proposed path and the filters, returns the user's choice. An empty function restores them.
using DialogHook = std::function<DialogChoice(const QString& caption, const QString& proposed,
                                              const QString& filters)>;
void setDialogHook(DialogHook hook);

/// Save dialog proposing lastFolder(purpose)/stem.<first filter's extension>; the result has the
/// chosen filter's extension and its folder is remembered. Empty when cancelled.
QString chooseSaveFile(QWidget* parent, const QString& caption, const QString& purpose,
                       const QString& stem, const QString& filters);
/// Open dialog starting in lastFolder(purpose); remembers the folder.
QString chooseOpenFile(QWidget* parent, const QString& caption, const QString& purpose,
                       const QString& filters);
/// Folder dialog starting in lastFolder(purpose); remembers it.
QString chooseFolder(QWidget* parent, const QString& caption, const QString& purpose);
/// A line of text asked for (File > Open link), proposing `proposed`, in a dialog wide enough for
/// a long link; the hook answers in its place when set. Empty when cancelled.
QString askForText(QWidget* parent, const QString& caption, const QString& label,
                   const QString& proposed);

} // namespace chaplygin::ui
