#include "shell/export_report.h"

#include "shell/elided_label.h"

#include <QDesktopServices>
#include <QDir>
#include <QHBoxLayout>
#include <QStatusBar>
#include <QToolButton>

#include <algorithm>

namespace chaplygin::ui {

namespace {

ExportReport::OpenUrl& openUrlHook() {
    static ExportReport::OpenUrl hook;
    return hook;
}

} // namespace

void ExportReport::setOpenUrlHook(OpenUrl hook) {
    openUrlHook() = std::move(hook);
}

ExportReport::ExportReport(QStatusBar* bar) : QWidget(bar) {
    setObjectName(QStringLiteral("exportReport"));
    m_text = new ElidedLabel; // a long path is elided, and whole in the tooltip
    m_open = new QToolButton;
    m_open->setText(tr("Open folder"));
    m_open->setToolTip(tr("Show the written files in the file manager"));
    m_close = new QToolButton;
    m_close->setText(QStringLiteral("\u00d7"));
    m_close->setAutoRaise(true);
    m_close->setToolTip(tr("Dismiss"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_text);
    layout->addWidget(m_open);
    layout->addWidget(m_close);
    connect(m_open, &QToolButton::clicked, this, [this] {
        const QUrl url = QUrl::fromLocalFile(m_folder);
        if (openUrlHook())
            openUrlHook()(url);
        else
            QDesktopServices::openUrl(url);
    });
    connect(m_close, &QToolButton::clicked, this, &QWidget::hide);
    bar->addPermanentWidget(this);
    hide();
}

void ExportReport::report(const QString& message, const QString& folder) {
    m_folder = QDir(folder).absolutePath();
    m_text->setFullText(message);
    // as wide as the words up to a third of the bar; the rest elided (the whole in the tooltip)
    const int bar = parentWidget() ? parentWidget()->width() : 900;
    m_text->setMinimumWidth(
        std::min(m_text->fontMetrics().horizontalAdvance(m_text->fullText()) + 4, bar / 3));
    show();
}

QString ExportReport::text() const {
    return m_text->fullText();
}

} // namespace chaplygin::ui
