#include "shell/lecture_panel.h"

#include "document/scene_texts.h"

#include <QLineEdit>
#include <QListWidget>
#include <QSignalBlocker>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>
#include <utility>

namespace chaplygin::ui {

LecturePanel::LecturePanel(QWidget* parent)
    : QWidget(parent), m_title(new QLineEdit), m_list(new QListWidget), m_buttons(new QToolBar) {
    m_title->setObjectName(QStringLiteral("lectureTitle"));
    m_title->setPlaceholderText(tr("Title of the lecture"));
    m_title->setMaxLength(int(kMaxLectureTitleBytes / 4));
    m_list->setObjectName(QStringLiteral("lectureList"));
    m_list->setEditTriggers(QAbstractItemView::EditKeyPressed);
    m_list->setToolTip(tr("The lecture's scenes in order: Page Down and Page Up step through "
                          "them; double click shows one, F2 renames it"));
    m_buttons->setToolButtonStyle(Qt::ToolButtonTextOnly);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_title);
    layout->addWidget(m_list, 1);
    layout->addWidget(m_buttons);
    connect(m_title, &QLineEdit::textEdited, this, [this](const QString& text) {
        m_lecture.title = text.toStdString();
        m_modified = true;
        emit changed();
    });
    connect(m_list, &QListWidget::itemActivated, this,
            [this](QListWidgetItem* item) { emit entryActivated(m_list->row(item)); });
    // a click highlights an entry: the buttons act on it, Page Down goes on from it
    connect(m_list, &QListWidget::currentRowChanged, this, [this](int row) {
        if (!m_refreshing && row != m_current && row < int(m_lecture.entries.size())) {
            m_current = row;
            emit changed();
        }
    });
    connect(m_list, &QListWidget::itemChanged, this, [this](QListWidgetItem* item) {
        const int row = m_list->row(item);
        if (m_refreshing || row < 0 || row >= int(m_lecture.entries.size()))
            return;
        std::string title = item->text().trimmed().toStdString();
        if (title.size() > kMaxLectureTitleBytes)
            title.resize(kMaxLectureTitleBytes);
        if (title != m_lecture.entries[std::size_t(row)].title) {
            m_lecture.entries[std::size_t(row)].title = title;
            m_modified = true;
            // the list is rebuilt once the edited item is no longer in use ("Scene N" for none)
            QMetaObject::invokeMethod(this, &LecturePanel::refresh, Qt::QueuedConnection);
        }
    });
    refresh();
}

void LecturePanel::open(Lecture lecture, const QString& fileName) {
    m_lecture = std::move(lecture);
    m_fileName = fileName;
    m_current = -1;
    m_open = true;
    m_modified = false;
    refresh();
}

void LecturePanel::close() {
    m_lecture = {};
    m_fileName.clear();
    m_current = -1;
    m_open = false;
    m_modified = false;
    refresh();
}

void LecturePanel::setCurrent(int index) {
    if (index >= -1 && index < int(m_lecture.entries.size()) && index != m_current) {
        m_current = index;
        refresh();
    }
}

int LecturePanel::add(LectureEntry entry) {
    const int at = m_current < 0 ? int(m_lecture.entries.size()) : m_current + 1;
    m_lecture.entries.insert(m_lecture.entries.begin() + at, std::move(entry));
    m_current = at;
    m_open = true;
    setModified();
    return at;
}

void LecturePanel::removeCurrent() {
    if (m_current < 0)
        return;
    m_lecture.entries.erase(m_lecture.entries.begin() + m_current);
    m_current = std::min(m_current, int(m_lecture.entries.size()) - 1);
    setModified();
}

void LecturePanel::moveCurrent(int by) {
    const int to = m_current + by;
    if (m_current < 0 || to < 0 || to >= int(m_lecture.entries.size()))
        return;
    std::swap(m_lecture.entries[std::size_t(m_current)], m_lecture.entries[std::size_t(to)]);
    m_current = to;
    setModified();
}

void LecturePanel::replaceCurrent(const Scene& scene) {
    if (m_current < 0 || m_lecture.entries[std::size_t(m_current)].scene == scene)
        return;
    m_lecture.entries[std::size_t(m_current)].scene = scene;
    setModified();
}

void LecturePanel::markSaved(const QString& fileName) {
    m_fileName = fileName;
    m_modified = false;
    refresh();
}

int LecturePanel::stepFrom(int direction) const {
    const int n = int(m_lecture.entries.size());
    if (n == 0)
        return -1;
    if (m_current < 0)
        return direction > 0 ? 0 : n - 1;
    return ((m_current + direction) % n + n) % n;
}

QString LecturePanel::entryLabel(int index) const {
    const std::string& title = m_lecture.entries[std::size_t(index)].title;
    return title.empty() ? tr("Scene %1").arg(index + 1) : sceneText(title);
}

void LecturePanel::addButtons(const QList<QAction*>& actions) {
    m_buttons->addActions(actions);
}

void LecturePanel::setModified() {
    m_modified = true;
    refresh();
}

void LecturePanel::refresh() {
    m_refreshing = true;
    {
        const QSignalBlocker blocker(m_list);
        m_list->clear();
        for (int i = 0; i < int(m_lecture.entries.size()); ++i) {
            auto* item = new QListWidgetItem(entryLabel(i), m_list);
            item->setFlags(item->flags() | Qt::ItemIsEditable);
            item->setToolTip(tr("Scene %1 of %2").arg(i + 1).arg(m_lecture.entries.size()));
        }
        m_list->setCurrentRow(m_current);
    }
    if (m_title->text() != QString::fromStdString(m_lecture.title))
        m_title->setText(QString::fromStdString(m_lecture.title));
    m_title->setEnabled(m_open);
    m_list->setEnabled(m_open);
    m_refreshing = false;
    emit changed();
}

} // namespace chaplygin::ui
