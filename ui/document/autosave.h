#pragma once
#include "scene/scene.h"
#include "scene/scene_json.h"

#include <QDateTime>
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

namespace chaplygin::ui {

/// A copy of the unsaved scene on disk, so that a killed program or a power cut loses nothing
/// (docs/robustness.md, Crash recovery). Each running window writes its own file a few seconds
/// after each change (atomically, as File > Save does) into the XDG state folder and holds a lock
/// beside it while it runs; the file goes when the scene is saved, made clean again or the window
/// closes normally. A file whose lock is stale was left by a program that ended abnormally.
class Autosave : public QObject {
    Q_OBJECT
  public:
    /// How long after the last change the copy is written.
    static constexpr int kDelayMs = 2000;

    /// directory: where the copies live (defaultDirectory() unless a test gives its own).
    explicit Autosave(QObject* parent = nullptr, const QString& directory = defaultDirectory());
    ~Autosave() override;

    /// $XDG_STATE_HOME/chaplygin-lab/autosave (by default ~/.local/state/chaplygin-lab/autosave).
    static QString defaultDirectory();

    /// The scene, or the pen's marks it carries, changed and differ from its file: write it
    /// kDelayMs from now (a later change restarts the wait). fileName: the file it was loaded
    /// from or saved to, if any.
    void sceneChanged(const Scene& scene, const QString& fileName);
    /// The scene is saved or back to its saved state: nothing to keep.
    void discard();
    /// Writes the pending copy now (also done when the wait ends). Returns false, keeping the
    /// last copy, when it cannot be written.
    bool writeNow();
    /// This window's copy ("" before the first write).
    QString file() const;

    /// A copy left by a program that ended abnormally.
    struct Orphan {
        QString file;
        QDateTime written;
        QString fileName; ///< the scene's own file when it had one
    };
    /// The copies in the folder whose program is no longer running, newest first.
    std::vector<Orphan> orphans() const;
    /// Reads an orphan's scene and its pen marks ("annotations", as a scene file holds them); a
    /// damaged annotations member costs the marks only (sceneFromJsonSparingMarks). Throws
    /// InputError when the copy cannot be read or its scene is damaged.
    static SceneSparingMarks readOrphan(const Orphan& orphan);
    /// Removes an orphan's copy (restored or declined).
    static void removeOrphan(const Orphan& orphan);

  private:
    QString path(const QString& suffix) const;

    QString m_directory;
    QString m_id; // this window's name in the folder
    std::unique_ptr<QLockFile> m_lock;
    std::optional<Scene> m_pending;
    QString m_pendingFileName;
    QTimer m_timer;
    bool m_written = false;
};

} // namespace chaplygin::ui
