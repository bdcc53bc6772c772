#pragma once
#include <QTextBrowser>
#include <QUrl>

namespace chaplygin::ui {

/// A QTextBrowser that opens Markdown documents (setSource, a clicked link) by parsing them into
/// a new QTextDocument and then showing it. QTextBrowser parses into the document it shows, whose
/// layout follows every insertion: the 70 kB numerics notes took 3-4 s to open that way and take
/// about 0.15 s this way (docs/numerics.md, The help window). Other resources open as in
/// QTextBrowser.
class MarkdownBrowser : public QTextBrowser {
    Q_OBJECT
  public:
    explicit MarkdownBrowser(QWidget* parent = nullptr);

    /// The Markdown file shown (without a fragment); empty before the first.
    QUrl markdownFile() const { return m_file; }

  protected:
    void doSetSource(const QUrl& name, QTextDocument::ResourceType type) override;

  private:
    QUrl m_file;
    QTextDocument* m_parsed = nullptr; // the document shown, owned here
};

} // namespace chaplygin::ui
