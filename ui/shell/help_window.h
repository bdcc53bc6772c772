#pragma once
#include <QString>
#include <QWidget>

class QListWidget;
class QTextBrowser;

namespace chaplygin::ui {

/// The help window: the user guide and the physics and numerics notes (docs/*.md, compiled
/// into the program as Qt resources under :/help) rendered by QTextBrowser's Markdown support,
/// with a list of the documents and links between them.
class HelpWindow : public QWidget {
    Q_OBJECT
  public:
    explicit HelpWindow(QWidget* parent = nullptr);

    /// The documents, as resource file names ("user-guide.md", "physics.md", ...).
    static QStringList documents();
    /// The resource that shows document: its translation into the catalogue's language
    /// (":/help/user-guide.pt_BR.md") when there is one, else the English one.
    static QString resourcePath(const QString& document);
    /// Shows document (a name from documents()) scrolled to the heading that contains section
    /// (case-insensitive; empty: the top). Returns false when either is not found (the document
    /// is shown from the top when it exists).
    bool showTopic(const QString& document, const QString& section = {});

    QTextBrowser* browser() const { return m_browser; }
    QString currentDocument() const { return m_current; }

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    /// Scales the pictures wider than the text area down to its width.
    void fitPictures();
    void scrollToBlock(int blockNumber);

    QListWidget* m_list;
    QTextBrowser* m_browser;
    QString m_current;
    int m_headingBlock = -1; // kept at the top until the reader scrolls
};

} // namespace chaplygin::ui
