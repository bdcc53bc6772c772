#pragma once
#include "document/autosave.h"
#include "document/plot_series.h"
#include "document/scene_error.h"
#include "scene/scene.h"
#include "scene/solution.h"

#include <QElapsedTimer>
#include <QFuture>
#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <QThreadPool>
#include <QTimer>
#include <QUndoStack>

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace chaplygin::ui {

/// The open scene and its latest valid Solution, shared by every view, and everything that
/// changes it: the undo stack and its edits, loading and saving, the modified state, the recent
/// files and the autosaved copy (docs/architecture.md, ui/: the desktop application). Scene changes
/// are coalesced: setScene() only marks the document dirty, and one recompute runs with the latest
/// scene on the next turn of the event loop, at most one per 16 ms frame while a slider moves. A
/// scene that fails leaves the last valid Solution in place and reports the InputError.
class PinSet;

class SceneDocument : public QObject {
    Q_OBJECT
  public:
    /// The scene's pinned runs, solved lazily.
    PinSet* pins() const { return m_pins; }
    /// persistent: the program's own window, which keeps the recent files in QSettings and a copy
    /// of the unsaved scene on disk (Autosave); off for tests and screenshots.
    explicit SceneDocument(QObject* parent = nullptr, bool persistent = false);
    ~SceneDocument() override;

    // Editing (scene_document_editing.cpp)

    /// Every change of the scene, one undoable step each.
    QUndoStack* undoStack() const { return m_undo; }
    /// Whether the scene differs from its file (or from the scene it was loaded as).
    bool isModified() const { return !m_undo->isClean(); }
    /// How a whole scene comes in (load, loadNow).
    struct LoadOptions {
        /// The undo step's text for a known scene (a preset, a gallery scene): one step that is
        /// no modification (see loadKnown). Empty: a new document (File > New and Open, a scene
        /// given at start), its undo history cleared.
        QString description;
        /// Called when the scene is the document's, solved.
        std::function<void()> loaded;
        /// Called with the reason when the scene is refused; the current scene stays.
        std::function<void(const SceneError&)> refused;
    };
    /// The one use case of a whole scene coming in: presets, gallery scenes, files. Its path is
    /// built on the path worker as a typed path's is (a quick one before this returns); the
    /// scene is then vetted (solved with its pins: a scene that does not solve never replaces
    /// the current one), installed and solved, and `loaded` is called, or `refused`. A newer
    /// load or path request supersedes an older one, whose callbacks are never called.
    void load(const Scene& scene, LoadOptions options);
    /// load() finished before this returns, for the callers that report a refusal to their own
    /// caller (a file, a scene given at start, a gallery entry whose refusal is its lesson):
    /// throws InputError naming the place and changes nothing.
    void loadNow(const Scene& scene, const QString& description = {});
    /// Changes the scene as one undo step (latest value wins for the recompute); consecutive
    /// edits with the same non-empty mergeKey merge into one step (one slider drag). A scene
    /// equal to the current one is no step.
    void edit(const Scene& scene, const QString& description, const QString& mergeKey = {});

    /// A change of the system's parameters: checked first (deriveSystem), so that an impossible
    /// value is refused with its message (returned) and never becomes an undo step.
    QString editParameters(const Scene& scene, const QString& description,
                           const QString& mergeKey = {});

    /// File > Open: the file's scene as a new document, clean, first in the recent files.
    /// Throws InputError naming the file or the place in it.
    void open(const QString& path);
    /// File > Save: written atomically, then clean, with the pen's marks when given (File > Save
    /// annotations with the scene). A scene that does not solve would not open again and is
    /// refused (InputError); a failed write throws IoError and keeps the old file.
    void save(const QString& path, const std::vector<AnnotationMark>& annotations = {});
    /// File > Export CSV of the current solution; throws IoError.
    void exportCsv(const QString& path) const;
    /// File > Open Recent (empty unless persistent).
    QStringList recentFiles() const;

    /// The copy of the unsaved scene on disk (null unless persistent).
    Autosave* autosave() const { return m_autosave; }
    /// Loads a copy a killed program left as the document, modified, with the scene's own file
    /// name, and its marks to the pen (penMarksLoaded): those of the copy shown, beside those the
    /// scene's own file holds now, the option to save them as opening that file would set it.
    /// Throws InputError when the scene is damaged; returns the refusal of a damaged
    /// "annotations" member, which costs the marks only ("" when they were good).
    QString restore(const Autosave::Orphan& orphan);

    /// The pen's marks as the window shows them (they are the pen's, never the scene's): kept
    /// in the autosaved copy, and carried by the undo step of a known scene that takes them away.
    const PenMarks& penMarks() const { return m_penMarks; }
    /// The pen's marks changed: the copy on disk follows.
    void setPenMarks(const PenMarks& marks);

    /// Free-motion samples for the live plots and the ghost's trail (each costs a Solution::at).
    static constexpr int kFreeSamples = 400;

    /// The scene as the user last set it (may be the one that failed).
    const Scene& scene() const { return m_scene; }
    /// The last valid solution, or null before the first one.
    const std::shared_ptr<const Solution>& solution() const { return m_solution; }
    /// What the plots draw, gathered once per recompute.
    const PlotSeries& series() const { return m_series; }
    /// The message of the last failed recompute; empty when the scene is valid.
    const QString& error() const { return m_error.message; }
    /// The latest scene's error with the part of the scene at fault.
    const SceneError& sceneError() const { return m_error; }

    /// Marks the scene for a coalesced recompute (latest value wins).
    void setScene(const Scene& scene);
    /// Recomputes now (for tests, the screenshot mode and file loading).
    void setSceneNow(const Scene& scene);
    /// Waits for a requested path (see requestPath), then runs a pending recompute now, if any.
    void flush();

    /// Builds and caches the path of a source; throws InputError. Cheap when cached.
    std::shared_ptr<const Path> pathFor(const PathSource& source);
    /// Called with an empty message when the path is built and cached, else with the error.
    using PathDone = std::function<void(const QString& error)>;
    /// Builds the path of a source on the path worker and calls done on the UI thread; a cached
    /// path, or one built within half a frame, answers before this returns. A newer request
    /// supersedes an older one, whose done is never called (latest wins).
    void requestPath(const PathSource& source, PathDone done);
    /// Whether a requested path is still being built.
    bool pathPending() const;

    /// Solves a scene without installing it (to vet a file before it replaces the current
    /// scene); throws InputError naming the place. The path is cached for the real recompute.
    void check(const Scene& scene);

    /// The file this scene was loaded from or saved to; empty if none.
    const QString& fileName() const { return m_fileName; }
    void setFileName(const QString& name);

  signals:
    /// A new valid solution (and series) is in place.
    void solutionChanged();
    /// error is empty when the latest scene solved.
    void errorChanged(const chaplygin::ui::SceneError& error);
    void fileNameChanged(const QString& name);
    /// The scene was set by an edit, an undo or redo, or a load; pathChanged when its path (or
    /// preset) differs from the one before, so that views showing the path refresh.
    void sceneApplied(const Scene& scene, bool pathChanged);
    void modifiedChanged(bool modified);
    void recentFilesChanged();
    /// A whole scene came in (a file, a preset, a gallery or lecture scene, a restored copy) with
    /// these marks of the pen (none for most), or the undo step of a known scene was undone or
    /// redone: the pen shows them; the document's scene holds none.
    void penMarksLoaded(const chaplygin::PenMarks& marks);

  private:
    /// A preset or a gallery scene as one undo step that is no modification: the document is
    /// then that known scene, untitled, with `marks`, and clean if it was clean before; unsaved
    /// changes made before it (the scene's or the pen's marks') stay a step back, and the
    /// document stays modified. Undo gives the scene, the file name and the pen's marks back. A
    /// scene equal to the current one is no step, and leaves the marks alone.
    void loadKnown(const Scene& scene, const QString& description, const PenMarks& marks);
    /// Sets the scene from an edit, an undo or a load; emits sceneApplied, with pathChanged for
    /// a new document (whole) as for a new path.
    void apply(const Scene& scene, bool whole = false);
    /// The end of a load, its path built: vets the scene, installs it as a new document or as
    /// a known scene (description) with the pen's `marks`, solves it; throws InputError and
    /// changes nothing.
    void install(const Scene& scene, const QString& description, const PenMarks& marks);
    /// The pen's marks now: those given (penMarksLoaded).
    void loadPenMarks(const PenMarks& marks);
    /// The document is now the file at path: clean, and first in the recent files.
    void markSavedAs(const QString& path);
    void keepCopy();

    struct PathJob {
        std::shared_ptr<const Path> path;
        QString error;
    };
    void recompute();
    std::shared_ptr<const Path> cachedPath(const PathSource& source);
    void cachePath(const PathSource& source, std::shared_ptr<const Path> path);
    /// Hands a finished path request to its caller (once).
    void takePath();

    bool m_persistent;
    QUndoStack* m_undo;
    PinSet* m_pins;
    Autosave* m_autosave = nullptr;
    bool m_applied = false; // whether a scene has been applied yet
    Scene m_scene;
    bool m_dirty = false;
    QTimer m_timer;
    QElapsedTimer m_lastRecompute;
    std::shared_ptr<const Solution> m_solution;
    PlotSeries m_series;
    SceneError m_error;
    QString m_fileName;
    PenMarks m_penMarks;
    std::vector<std::pair<PathSource, std::shared_ptr<const Path>>> m_pathCache;
    std::shared_ptr<const Solution> m_checked; // solved by check(), taken by the next recompute
    // the system editParameters vetted, with its derivation: the recompute solves with it
    std::optional<std::pair<SystemSpec, DerivedSystem>> m_vetted;
    // the latest path request; the pool is declared last so that it is joined first
    std::shared_ptr<std::atomic<quint64>> m_pathLatest = std::make_shared<std::atomic<quint64>>(0);
    PathSource m_pathSource;
    PathDone m_pathDone;
    QFuture<PathJob> m_pathFuture;
    bool m_pathTaken = true;
    QFutureWatcher<PathJob> m_pathWatcher;
    QThreadPool m_pathPool;
};

} // namespace chaplygin::ui
