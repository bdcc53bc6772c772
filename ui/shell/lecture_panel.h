#pragma once
// The Lecture dock's contents: the open lecture's title and its scenes in order, the current one
// highlighted, with buttons to add, remove and move them.
#include "scene/lecture.h"

#include <QList>
#include <QString>
#include <QWidget>

class QAction;
class QLineEdit;
class QListWidget;
class QToolBar;

namespace chaplygin::ui {

/// The open lecture (Lecture menu): a list of scenes the window steps through with Page Up and
/// Page Down. It holds the lecture, the entry shown last (current) and its file; the window loads
/// the scenes. Double click or Enter on an entry asks for it (entryActivated); F2 renames it.
class LecturePanel : public QWidget {
    Q_OBJECT
  public:
    explicit LecturePanel(QWidget* parent = nullptr);

    /// Whether a lecture is open (else Page Down steps through the gallery).
    bool isOpen() const { return m_open; }
    const Lecture& lecture() const { return m_lecture; }
    /// The entry shown last, -1 before the first.
    int current() const { return m_current; }
    /// The lecture's file; empty until saved.
    const QString& fileName() const { return m_fileName; }
    /// Whether the lecture differs from its file (or, untitled, has entries).
    bool isModified() const { return m_modified; }

    /// Opens a lecture, no entry current; clean when it comes from a file.
    void open(Lecture lecture, const QString& fileName);
    /// No lecture open any more.
    void close();
    void setCurrent(int index);
    /// Inserts after the current entry (at the end when none) and makes it current.
    int add(LectureEntry entry);
    /// Removes the current entry; the one after it (or before, at the end) becomes current.
    void removeCurrent();
    /// Moves the current entry by one place up (-1) or down (+1); it stays current.
    void moveCurrent(int by);
    /// The current entry's scene replaced (its title kept).
    void replaceCurrent(const Scene& scene);
    void markSaved(const QString& fileName);
    /// The entry Page Down (+1) or Page Up (-1) shows, going round at the ends; the first (or
    /// the last) when none is current; -1 when the lecture is empty.
    int stepFrom(int direction) const;
    /// The entry's title, or "Scene N" when it has none.
    QString entryLabel(int index) const;

    QListWidget* list() const { return m_list; }
    /// The buttons under the list.
    void addButtons(const QList<QAction*>& actions);

  signals:
    void entryActivated(int index);
    /// The lecture, its current entry, its file or its modified state changed.
    void changed();

  private:
    void refresh();
    void setModified();

    QLineEdit* m_title;
    QListWidget* m_list;
    QToolBar* m_buttons;
    Lecture m_lecture;
    int m_current = -1;
    QString m_fileName;
    bool m_modified = false;
    bool m_open = false;
    bool m_refreshing = false;
};

} // namespace chaplygin::ui
