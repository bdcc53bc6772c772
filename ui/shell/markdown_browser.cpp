#include "shell/markdown_browser.h"

#include <QTextDocument>

namespace chaplygin::ui {

MarkdownBrowser::MarkdownBrowser(QWidget* parent) : QTextBrowser(parent) {}

void MarkdownBrowser::doSetSource(const QUrl& name, QTextDocument::ResourceType type) {
    QUrl file = name.adjusted(QUrl::RemoveFragment);
    const bool markdown = type == QTextDocument::MarkdownResource ||
                          (type == QTextDocument::UnknownResource &&
                           file.path().endsWith(QLatin1String(".md"), Qt::CaseInsensitive));
    if (!markdown || file.isEmpty()) {
        QTextBrowser::doSetSource(name, type);
        return;
    }
    if (file != m_file || !m_parsed) {
        const QVariant data = loadResource(QTextDocument::MarkdownResource, file);
        if (!data.isValid()) { // as QTextBrowser does with a missing file
            QTextBrowser::doSetSource(name, type);
            return;
        }
        const QString text = data.userType() == QMetaType::QString
                                 ? data.toString()
                                 : QString::fromUtf8(data.toByteArray());
        auto* parsed = new QTextDocument(this); // its images load through this browser
        parsed->setMarkdown(text);
        setDocument(parsed);
        delete m_parsed;
        m_parsed = parsed;
        m_file = file;
    }
    if (name.hasFragment())
        scrollToAnchor(name.fragment());
    emit sourceChanged(name);
}

} // namespace chaplygin::ui
