#include "shell/help_window.h"

#include "document/math_text.h"
#include "shell/markdown_browser.h"

#include <QAbstractTextDocumentLayout>
#include <QFile>
#include <QHBoxLayout>
#include <QImage>
#include <QListWidget>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTextDocument>

#include <algorithm>
#include <cmath>

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

// a document in the language of the window's catalogue when it has a translation: the
// catalogue names its language ("pt_BR") and docs/user-guide.pt_BR.md is the guide in it
static QString languageCode() {
    return HelpWindow::tr("en",
                          "the language code of this catalogue, as in docs/user-guide.CODE.md");
}

QString HelpWindow::resourcePath(const QString& document) {
    const QString code = languageCode();
    if (code != QLatin1String("en") && document.endsWith(QLatin1String(".md"))) {
        QString translated = QStringLiteral(":/help/") + document;
        translated.insert(translated.size() - 3, u'.' + code);
        if (QFile::exists(translated))
            return translated;
    }
    return QStringLiteral(":/help/") + document;
}

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
    m_browser = new MarkdownBrowser;
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
        setDottedSymbolFont(*m_browser->document()); // φ̇ with its dot on the φ
        // user-guide.pt_BR.md is the document user-guide.md
        QString name = url.fileName();
        const QString translated = u'.' + languageCode() + QStringLiteral(".md");
        if (name.endsWith(translated))
            name = name.left(name.size() - translated.size()) + QStringLiteral(".md");
        m_current = name;
        int row = documents().indexOf(m_current);
        if (row >= 0 && m_list->currentRow() != row)
            m_list->setCurrentRow(row);
    });
    // the text area's width changes: the pictures follow it, the heading stays at the top
    m_browser->viewport()->installEventFilter(this);
    connect(m_browser->verticalScrollBar(), &QScrollBar::actionTriggered, this,
            [this] { m_headingBlock = -1; });
    resize(900, 700);
    showTopic(QStringLiteral("user-guide.md"));
}

bool HelpWindow::showTopic(const QString& document, const QString& section) {
    const QString path = resourcePath(document);
    if (!documents().contains(document) || !QFile::exists(path))
        return false;
    if (document != m_current || m_browser->document()->isEmpty()) {
        m_browser->setSource(QUrl(QStringLiteral("qrc") + path), QTextDocument::MarkdownResource);
        fitPictures();
    }
    m_current = document;
    m_headingBlock = -1;
    if (section.isEmpty()) {
        m_browser->moveCursor(QTextCursor::Start);
        return true;
    }
    // Markdown headings carry no anchors: find the heading block and scroll to it
    for (QTextBlock b = m_browser->document()->begin(); b.isValid(); b = b.next()) {
        if (b.blockFormat().headingLevel() > 0 && b.text().contains(section, Qt::CaseInsensitive)) {
            m_browser->setTextCursor(QTextCursor(b));
            m_headingBlock = b.blockNumber();
            scrollToBlock(m_headingBlock);
            return true;
        }
    }
    return false;
}

void HelpWindow::scrollToBlock(int blockNumber) {
    // the heading at the top of the view, the section below it
    QTextDocument* doc = m_browser->document();
    QTextBlock block = doc->findBlockByNumber(blockNumber);
    if (block.isValid())
        m_browser->verticalScrollBar()->setValue(
            int(doc->documentLayout()->blockBoundingRect(block).top()));
}

void HelpWindow::fitPictures() {
    QTextDocument* doc = m_browser->document();
    const double room =
        std::max(50.0, m_browser->viewport()->width() - 2 * doc->documentMargin() - 4);
    for (QTextBlock b = doc->begin(); b.isValid(); b = b.next()) {
        for (auto it = b.begin(); !it.atEnd(); ++it) {
            const QTextFragment fragment = it.fragment();
            if (!fragment.charFormat().isImageFormat())
                continue;
            QTextImageFormat image = fragment.charFormat().toImageFormat();
            const QImage picture =
                doc->resource(QTextDocument::ImageResource, QUrl(image.name())).value<QImage>();
            if (picture.isNull())
                continue;
            const double width = std::min(double(picture.width()), room);
            if (std::abs(image.width() - width) < 0.5)
                continue;
            image.setWidth(width);
            image.setHeight(width * picture.height() / picture.width());
            QTextCursor c(doc);
            c.setPosition(fragment.position());
            c.setPosition(fragment.position() + fragment.length(), QTextCursor::KeepAnchor);
            c.setCharFormat(image);
        }
    }
}

bool HelpWindow::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_browser->viewport() && event->type() == QEvent::Resize) {
        // after the browser has laid the text out at its new width
        QMetaObject::invokeMethod(
            this,
            [this] {
                fitPictures();
                if (m_headingBlock >= 0)
                    scrollToBlock(m_headingBlock);
            },
            Qt::QueuedConnection);
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace chaplygin::ui
