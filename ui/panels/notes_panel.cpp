#include "panels/notes_panel.h"

#include "document/math_text.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QTextBrowser>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace chaplygin::ui {

NotesPanel::NotesPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* bar = new QHBoxLayout;
    m_hint = new QLabel(tr("What to say about this scene (Markdown, saved with it)"));
    m_hint->setWordWrap(true);
    m_edit = new QToolButton;
    m_edit->setText(tr("Edit"));
    m_edit->setCheckable(true);
    m_edit->setObjectName(QStringLiteral("editNote"));
    bar->addWidget(m_hint, 1);
    bar->addWidget(m_edit);
    layout->addLayout(bar);
    m_editor = new QPlainTextEdit;
    m_editor->setObjectName(QStringLiteral("noteEditor"));
    m_editor->setPlaceholderText(tr("# Title\n\nWhat the students should notice\u2026"));
    m_editor->setTabChangesFocus(true);
    m_editor->hide();
    layout->addWidget(m_editor, 1);
    m_view = new QTextBrowser;
    m_view->setObjectName(QStringLiteral("noteView"));
    m_view->setOpenExternalLinks(true);
    layout->addWidget(m_view, 2);
    m_basePoints = m_view->font().pointSizeF();
    connect(m_edit, &QToolButton::toggled, this, &NotesPanel::setEditing);
    connect(m_editor, &QPlainTextEdit::textChanged, this, [this] {
        render();
        if (!m_setting)
            emit noteEdited(m_editor->toPlainText());
    });
    render();
}

void NotesPanel::setPresenting(bool on) {
    m_hint->setVisible(!on);
    if (on)
        setEditing(false);
    m_edit->setVisible(!on);
}

bool NotesPanel::hintShown() const {
    return !m_hint->isHidden();
}

void NotesPanel::setNote(const QString& markdown) {
    if (markdown == m_editor->toPlainText())
        return;
    m_setting = true;
    m_editor->setPlainText(markdown);
    m_setting = false;
    render();
}

QString NotesPanel::note() const {
    return m_editor->toPlainText();
}

void NotesPanel::render() {
    QString text = m_editor->toPlainText();
    if (text.trimmed().isEmpty())
        m_view->setHtml(tr("<p style='color:#777'>No note for this scene. Click <b>Edit</b> to "
                           "write one; it is saved with the scene.</p>"));
    else {
        m_view->setMarkdown(text);
        setDottedSymbolFont(*m_view->document()); // φ̇ with its dot on the φ
    }
}

void NotesPanel::setFontScale(double scale) {
    m_scale = std::clamp(scale, 0.5, 6.0);
    QFont f = m_view->font();
    f.setPointSizeF(m_basePoints * m_scale);
    m_view->setFont(f);
    m_view->document()->setDefaultFont(f);
    render();
}

void NotesPanel::setEditing(bool on) {
    m_edit->setChecked(on);
    m_editor->setVisible(on);
    if (on)
        m_editor->setFocus();
}

bool NotesPanel::editing() const {
    return m_edit->isChecked();
}

} // namespace chaplygin::ui
