#pragma once
#include "scene/scene.h"

#include <QString>
#include <QUndoCommand>

#include <functional>

namespace chaplygin::ui {

/// One undoable scene change (a path or a parameter): it stores the scene before and after and
/// applies either through a callback. Consecutive edits with the same non-empty merge key (one
/// slider drag) merge into one step. A step that loads a known scene (a preset, a gallery scene)
/// also changes the document's file name and the pen's marks, and gives the old ones back when
/// undone.
class SceneCommand : public QUndoCommand {
  public:
    using Apply = std::function<void(const Scene&)>;
    SceneCommand(const QString& text, Scene before, Scene after, Apply apply,
                 QString mergeKey = {});
    using SetFileName = std::function<void(const QString&)>;
    /// The step also sets the file name: after on redo, before on undo.
    void setFileNames(QString before, QString after, SetFileName setFileName);
    using SetMarks = std::function<void(const PenMarks&)>;
    /// The step also sets the pen's marks: after on redo, before (those it took away) on undo.
    void setMarks(PenMarks before, PenMarks after, SetMarks setMarks);

    void undo() override;
    void redo() override;
    int id() const override { return m_mergeKey.isEmpty() ? -1 : 1; }
    bool mergeWith(const QUndoCommand* other) override;

  private:
    Scene m_before, m_after;
    Apply m_apply;
    QString m_mergeKey;
    QString m_fileBefore, m_fileAfter;
    SetFileName m_setFileName;
    PenMarks m_marksBefore, m_marksAfter;
    SetMarks m_setMarks;
};

} // namespace chaplygin::ui
