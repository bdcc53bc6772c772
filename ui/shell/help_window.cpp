#include "shell/help_window.h"

#include <QFile>
#include <QHBoxLayout>
#include <QListWidget>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>

// the resources live in a static library: they are registered by name before first use
static void initHelpResources() {
    Q_INIT_RESOURCE(chaplygin_help);
}

namespace chaplygin::ui {

namespace {
struct Doc {
    const char* file;
    const char* title;
};
constexpr Doc kDocs[] = {
    {"user-guide.md", QT_TRANSLATE_NOOP("chaplygin::ui::HelpWindow", "User guide")},
    {"physics.md", QT_TRANSLATE_NOOP("chaplygin::ui::HelpWindow", "Physics notes")},
    {"numerics.md", QT_TRANSLATE_NOOP("chaplygin::ui::HelpWindow", "Numerical methods")},
    {"robustness.md", QT_TRANSLATE_NOOP("chaplygin::ui::HelpWindow", "Robustness")},
    {"architecture.md", QT_TRANSLATE_NOOP("chaplygin::ui::HelpWindow", "Architecture")}};
} // namespace

QStringList HelpWindow::documents() {
    QStringList names;
    for (const Doc& d : kDocs)
        names << QString::fromLatin1(d.file);
    return names;
}

HelpWindow::HelpWindow(QWidget* parent) : QWidget(parent, Qt::Window) {
    initHelpResources();
    setObjectName(QStringLiteral("helpWindow"));
    setWindowTitle(tr("Chaplygin Lab help"));
    m_list = new QListWidget;
    m_list->setAccessibleName(tr("Help documents"));
    for (const Doc& d : kDocs) {
        auto* item = new QListWidgetItem(tr(d.title), m_list);
        item->setData(Qt::UserRole, QString::fromLatin1(d.file));
    }
    m_list->setMaximumWidth(m_list->sizeHintForColumn(0) + 24);
    m_browser = new QTextBrowser;
    m_browser->setAccessibleName(tr("Help text"));
    m_browser->setOpenExternalLinks(true);
    m_browser->setSearchPaths({QStringLiteral(":/help")});
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(m_list);
    layout->addWidget(m_browser, 1);
    connect(m_list, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row >= 0 && m_list->item(row)->data(Qt::UserRole).toString() != m_current)
            showTopic(m_list->item(row)->data(Qt::UserRole).toString());
    });
    // links between the documents ("physics.md#...") stay in the window
    connect(m_browser, &QTextBrowser::sourceChanged, this, [this](const QUrl& url) {
        m_current = url.fileName();
        int row = documents().indexOf(m_current);
        if (row >= 0 && m_list->currentRow() != row)
            m_list->setCurrentRow(row);
    });
    resize(900, 700);
    showTopic(QStringLiteral("user-guide.md"));
}

bool HelpWindow::showTopic(const QString& document, const QString& section) {
    const QString path = QStringLiteral(":/help/") + document;
    if (!documents().contains(document) || !QFile::exists(path))
        return false;
    if (document != m_current || m_browser->document()->isEmpty())
        m_browser->setSource(QUrl(QStringLiteral("qrc") + path), QTextDocument::MarkdownResource);
    m_current = document;
    if (section.isEmpty()) {
        m_browser->moveCursor(QTextCursor::Start);
        return true;
    }
    // Markdown headings carry no anchors: find the heading block and scroll to it
    for (QTextBlock b = m_browser->document()->begin(); b.isValid(); b = b.next()) {
        if (b.blockFormat().headingLevel() > 0 && b.text().contains(section, Qt::CaseInsensitive)) {
            QTextCursor c(b);
            m_browser->setTextCursor(c);
            m_browser->ensureCursorVisible();
            return true;
        }
    }
    return false;
}

} // namespace chaplygin::ui
