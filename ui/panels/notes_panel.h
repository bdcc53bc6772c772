#pragma once
#include <QWidget>

class QLabel;
class QPlainTextEdit;
class QTextBrowser;
class QToolButton;

namespace chaplygin::ui {

/// The Notes dock: the scene's Markdown note rendered (QTextDocument's Markdown), and an editor
/// shown by the Edit button. Each edit is reported (the window makes it a scene change).
class NotesPanel : public QWidget {
    Q_OBJECT
  public:
    explicit NotesPanel(QWidget* parent = nullptr);

    /// Shows a note; the editor keeps its cursor when it already holds the same text.
    void setNote(const QString& markdown);
    QString note() const;
    /// Enlarges the text (presentation mode): 1 is the normal size.
    void setFontScale(double scale);
    double fontScale() const { return m_scale; }
    void setEditing(bool on);
    bool editing() const;
    /// Presenting: the note alone, without the editing hint and the Edit button above it (a
    /// lecture hall reads the note).
    void setPresenting(bool on);
    bool hintShown() const;

    QTextBrowser* view() const { return m_view; }
    QPlainTextEdit* editor() const { return m_editor; }

  signals:
    void noteEdited(const QString& markdown);

  private:
    void render();

    QTextBrowser* m_view;
    QPlainTextEdit* m_editor;
    QToolButton* m_edit;
    QLabel* m_hint;
    double m_scale = 1;
    double m_basePoints = 0;
    bool m_setting = false;
};

} // namespace chaplygin::ui
