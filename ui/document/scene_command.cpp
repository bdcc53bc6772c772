#include "document/scene_command.h"

#include <utility>

namespace chaplygin::ui {

SceneCommand::SceneCommand(const QString& text, Scene before, Scene after, Apply apply,
                           QString mergeKey)
    : m_before(std::move(before)), m_after(std::move(after)), m_apply(std::move(apply)),
      m_mergeKey(std::move(mergeKey)) {
    setText(text);
}

void SceneCommand::setFileNames(QString before, QString after, SetFileName setFileName) {
    m_fileBefore = std::move(before);
    m_fileAfter = std::move(after);
    m_setFileName = std::move(setFileName);
}

void SceneCommand::setMarks(PenMarks before, PenMarks after, SetMarks setMarks) {
    m_marksBefore = std::move(before);
    m_marksAfter = std::move(after);
    m_setMarks = std::move(setMarks);
}

void SceneCommand::undo() {
    m_apply(m_before);
    if (m_setFileName)
        m_setFileName(m_fileBefore);
    if (m_setMarks)
        m_setMarks(m_marksBefore);
}

void SceneCommand::redo() {
    m_apply(m_after);
    if (m_setFileName)
        m_setFileName(m_fileAfter);
    if (m_setMarks)
        m_setMarks(m_marksAfter);
}

bool SceneCommand::mergeWith(const QUndoCommand* other) {
    const auto* o = dynamic_cast<const SceneCommand*>(other);
    if (!o || o->m_mergeKey != m_mergeKey || m_setFileName || o->m_setFileName || m_setMarks ||
        o->m_setMarks)
        return false;
    m_after = o->m_after;
    return true;
}

} // namespace chaplygin::ui
