// The editing half of SceneDocument: the undo steps, loading and saving, the recent files and
// the autosaved copy. Kept apart from the recompute in scene_document.cpp.
#include "common/input_error.h"
#include "document/pin_set.h"
#include "document/scene_command.h"
#include "document/scene_document.h"
#include "document/scene_files.h"
#include "scene/scene_json.h"
#include "scene/scene_plan.h"
#include "systems/system.h"

#include <exception>

namespace chaplygin::ui {

void SceneDocument::apply(const Scene& scene, bool whole) {
    // a parameter change leaves the path's views alone (with any unfinished typing in them); a
    // new document is new to every view, even with the path it had
    const bool pathChanged =
        whole || !m_applied || scene.path != m_scene.path || scene.preset != m_scene.preset;
    m_applied = true;
    setScene(scene);
    emit sceneApplied(scene, pathChanged);
}

void SceneDocument::install(const Scene& loaded, const QString& description,
                            const PenMarks& marks) {
    // the pen's marks go to the pen: the document's scene, its undo steps, its link and its
    // summary never hold them
    Scene scene = loaded;
    scene.annotations.clear();
    check(scene);   // a scene that does not solve never replaces the current one
    if (scene.plan) // nor one whose chosen motion does not exist (docs/physics.md §10)
        planOf(*scene.plan, *m_checked);
    PinSet::check(*this, scene);
    if (description.isEmpty()) {
        m_undo->clear();
        apply(scene, true);
        loadPenMarks(marks);
    } else {
        loadKnown(scene, description, marks);
    }
    flush();
}

void SceneDocument::loadPenMarks(const PenMarks& marks) {
    m_penMarks = marks;
    emit penMarksLoaded(marks);
    keepCopy();
}

void SceneDocument::setPenMarks(const PenMarks& marks) {
    if (marks == m_penMarks)
        return;
    m_penMarks = marks;
    keepCopy();
}

void SceneDocument::load(const Scene& scene, LoadOptions options) {
    requestPath(scene.path, [this, scene, options = std::move(options)](const QString& error) {
        SceneError refusal = error.isEmpty() ? SceneError() : SceneError::ofPath(error);
        if (refusal.isEmpty()) {
            try {
                install(scene, options.description,
                        PenMarks::ofFile(scene.annotations, m_penMarks.savedWithScene));
            } catch (const InputError& e) {
                refusal = SceneError::of(e);
            }
        }
        if (!refusal.isEmpty()) {
            if (options.refused)
                options.refused(refusal);
        } else if (options.loaded) {
            options.loaded();
        }
    });
}

void SceneDocument::loadNow(const Scene& scene, const QString& description) {
    pathFor(scene.path);
    install(scene, description, PenMarks::ofFile(scene.annotations, m_penMarks.savedWithScene));
}

void SceneDocument::edit(const Scene& scene, const QString& description, const QString& mergeKey) {
    if (m_applied && scene == m_scene)
        return;
    m_undo->push(new SceneCommand(
        description, m_scene, scene, [this](const Scene& s) { apply(s); }, mergeKey));
}

void SceneDocument::loadKnown(const Scene& scene, const QString& description,
                              const PenMarks& marks) {
    if (m_applied && scene == m_scene)
        return;
    // marks to be saved and not yet saved are an unsaved change a step back, as the scene's are
    const bool keepClean = m_undo->isClean() && !m_penMarks.unsaved();
    auto* step =
        new SceneCommand(description, m_scene, scene, [this](const Scene& s) { apply(s); });
    step->setFileNames(m_fileName, {}, [this](const QString& name) { setFileName(name); });
    step->setMarks(m_penMarks, marks, [this](const PenMarks& m) { loadPenMarks(m); });
    m_undo->push(step);
    if (keepClean)
        m_undo->setClean();
}

QString SceneDocument::editParameters(const Scene& scene, const QString& description,
                                      const QString& mergeKey) {
    try {
        // derived once: the recompute solves with it
        m_vetted = std::make_pair(scene.system, deriveSystem(scene.system));
    } catch (const InputError& e) {
        return QString::fromStdString(e.what());
    }
    edit(scene, description, mergeKey);
    return {};
}

void SceneDocument::markSavedAs(const QString& path) {
    setFileName(path);
    m_undo->setClean();
    if (m_persistent) {
        addRecentFile(path);
        emit recentFilesChanged();
    }
}

void SceneDocument::open(const QString& path) {
    loadNow(openSceneFile(path));
    markSavedAs(path);
}

void SceneDocument::save(const QString& path, const std::vector<AnnotationMark>& annotations) {
    flush();
    if (!m_error.isEmpty())
        throw InputError(tr("cannot save '%1'").arg(path).toStdString(),
                         tr("the scene does not solve (%1); fix it or undo first")
                             .arg(m_error.message)
                             .toStdString());
    Scene written = m_scene;
    written.annotations = annotations;
    saveSceneFile(path, written);
    markSavedAs(path);
}

void SceneDocument::exportCsv(const QString& path) const {
    exportCsvFile(path, *m_solution);
}

QStringList SceneDocument::recentFiles() const {
    return m_persistent ? chaplygin::ui::recentFiles() : QStringList();
}

QString SceneDocument::restore(const Autosave::Orphan& orphan) {
    const SceneSparingMarks copy = Autosave::readOrphan(orphan);
    // the marks the scene's own file holds now, as opening it would give them: what File > Save
    // would change, and whether the option to save them is ticked
    std::vector<AnnotationMark> inFile;
    if (!orphan.fileName.isEmpty()) {
        try {
            inFile = openSceneFile(orphan.fileName).annotations;
        } catch (const std::exception&) {
            // gone or damaged since: it holds no marks of its own
        }
    }
    PenMarks marks = PenMarks::ofFile(std::move(inFile), m_penMarks.savedWithScene);
    marks.shown = copy.scene.annotations;
    pathFor(copy.scene.path);
    install(copy.scene, {}, marks);
    setFileName(orphan.fileName);
    m_undo->resetClean();
    keepCopy();
    return copy.marksError ? QString::fromStdString(copy.marksError->what()) : QString();
}

// the copy on disk follows the modified state and the pen's marks: written after a change, gone
// when the scene is clean and the scene's file holds the marks shown
void SceneDocument::keepCopy() {
    if (!m_autosave)
        return;
    if (m_undo->isClean() && !m_penMarks.outsideFile()) {
        m_autosave->discard();
        return;
    }
    Scene copy = m_scene;
    copy.annotations = m_penMarks.shown;
    m_autosave->sceneChanged(copy, m_fileName);
}

} // namespace chaplygin::ui
