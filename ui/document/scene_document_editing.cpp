// The editing half of SceneDocument: the undo steps, loading and saving, the recent files and
// the autosaved copy. Kept apart from the recompute in scene_document.cpp.
#include "common/input_error.h"
#include "document/pin_set.h"
#include "document/scene_command.h"
#include "document/scene_document.h"
#include "document/scene_files.h"
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

void SceneDocument::install(const Scene& loaded, const QString& description) {
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
    } else {
        loadKnown(scene, description);
    }
    flush();
    emit annotationsLoaded(loaded.annotations);
}

void SceneDocument::load(const Scene& scene, LoadOptions options) {
    requestPath(scene.path, [this, scene, options = std::move(options)](const QString& error) {
        SceneError refusal = error.isEmpty() ? SceneError() : SceneError::ofPath(error);
        if (refusal.isEmpty()) {
            try {
                install(scene, options.description);
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
    install(scene, description);
}

void SceneDocument::edit(const Scene& scene, const QString& description, const QString& mergeKey) {
    if (m_applied && scene == m_scene)
        return;
    m_undo->push(new SceneCommand(
        description, m_scene, scene, [this](const Scene& s) { apply(s); }, mergeKey));
}

void SceneDocument::loadKnown(const Scene& scene, const QString& description) {
    if (m_applied && scene == m_scene)
        return;
    const bool wasClean = m_undo->isClean();
    auto* step =
        new SceneCommand(description, m_scene, scene, [this](const Scene& s) { apply(s); });
    step->setFileNames(m_fileName, {}, [this](const QString& name) { setFileName(name); });
    m_undo->push(step);
    if (wasClean)
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

void SceneDocument::restore(const Autosave::Orphan& orphan) {
    loadNow(Autosave::readOrphan(orphan));
    setFileName(orphan.fileName);
    m_undo->resetClean();
    keepCopy();
}

// the copy on disk follows the modified state: written after a change, gone when clean
void SceneDocument::keepCopy() {
    if (!m_autosave)
        return;
    if (m_undo->isClean())
        m_autosave->discard();
    else
        m_autosave->sceneChanged(m_scene, m_fileName);
}

} // namespace chaplygin::ui
