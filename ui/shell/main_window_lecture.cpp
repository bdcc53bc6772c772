// The main window's lecture: the Lecture menu and dock, lecture files, and Page Up / Page Down
// through the open lecture (the gallery when none is open). Kept apart from main_window.cpp.
#include "shell/main_window.h"

#include "canvas/scene_canvas.h"
#include "common/atomic_file.h"
#include "common/input_error.h"
#include "document/file_dialogs.h"
#include "document/scene_document.h"
#include "document/scene_files.h"
#include "document/scene_texts.h"
#include "lab/gallery.h"
#include "scene/lecture.h"
#include "shell/dock_layout.h"
#include "shell/lecture_panel.h"
#include "shell/presentation_mode.h"

#include <QAction>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QTimer>

namespace chaplygin::ui {
namespace {

// the title a scene added to a lecture gets: its note's heading (a first line "# ..."), its
// file's name or its preset's; empty (the list says "Scene N") when it has none
std::string titleOf(const Scene& scene, const QString& fileName) {
    QString line = QString::fromStdString(scene.note).section(QLatin1Char('\n'), 0, 0).trimmed();
    if (line.startsWith(QLatin1Char('#'))) {
        while (line.startsWith(QLatin1Char('#')))
            line.remove(0, 1);
        line = line.trimmed();
        if (line.size() > 80)
            line = line.left(79) + QStringLiteral("\u2026");
        if (!line.isEmpty())
            return line.toStdString();
    }
    if (!fileName.isEmpty())
        return QFileInfo(fileName).completeBaseName().toStdString();
    if (!scene.preset.empty())
        return sceneText(scene.preset).toStdString();
    return {};
}

} // namespace

void MainWindow::buildLectureMenu() {
    m_lecture = new LecturePanel;
    m_lectureDock = new QDockWidget(tr("Lecture"), this);
    m_lectureDock->setObjectName(QStringLiteral("lectureDock"));
    m_lectureDock->setWidget(m_lecture);
    addDockWidget(Qt::LeftDockWidgetArea, m_lectureDock);
    tabifyDockWidget(m_docks.parameters, m_lectureDock);
    m_lectureDock->hide(); // until a lecture is made or opened
    m_presentation->addHiddenDock(m_lectureDock);
    m_lecturePosition = new QLabel;
    m_lecturePosition->setObjectName(QStringLiteral("lecturePosition"));
    statusBar()->addPermanentWidget(m_lecturePosition);

    QMenu* menu = menuBar()->addMenu(tr("&Lecture"));
    menu->setObjectName(QStringLiteral("lectureMenu"));
    auto action = [this, menu](const QString& text, const char* name, auto slot) {
        QAction* a = menu->addAction(text, this, slot);
        a->setObjectName(QString::fromLatin1(name));
        return a;
    };
    action(tr("&New lecture"), "newLectureAction", [this] { newLecture(); });
    action(tr("&Open lecture\u2026"), "openLectureAction", [this] { openLectureDialog(); });
    action(tr("Start from the &gallery"), "galleryLectureAction", [this] {
        if (!maybeSaveLecture())
            return;
        Lecture gallery = galleryLecture();
        gallery.title = tr("Gallery").toStdString();
        m_lecture->open(std::move(gallery), {});
        bringDockForward(this, m_lectureDock);
    })->setStatusTip(tr("A new lecture with the gallery's scenes, to reorder and add to"));
    action(tr("&Save lecture"), "saveLectureAction", [this] { saveLectureDialog(false); });
    action(tr("Save lecture &as\u2026"), "saveLectureAsAction",
           [this] { saveLectureDialog(true); });
    action(tr("&Close lecture"), "closeLectureAction", [this] {
        if (!maybeSaveLecture())
            return;
        m_lecture->close();
        m_lectureDock->hide();
    })->setStatusTip(tr("Page Down then steps through the gallery again"));
    menu->addSeparator();
    QAction* add =
        action(tr("A&dd the current scene"), "addToLectureAction", [this] { addSceneToLecture(); });
    add->setShortcut(QKeySequence(tr("Ctrl+L")));
    add->setIconText(tr("Add"));
    add->setToolTip(tr("Add the current scene after the highlighted one (Ctrl+L)"));
    QAction* replace =
        action(tr("&Replace with the current scene"), "replaceInLectureAction", [this] {
            m_document->flush();
            m_lecture->replaceCurrent(m_document->scene());
        });
    replace->setStatusTip(tr("The highlighted entry becomes the scene as it is now"));
    QAction* remove = action(tr("Re&move from the lecture"), "removeFromLectureAction",
                             [this] { m_lecture->removeCurrent(); });
    remove->setIconText(tr("Remove"));
    QAction* up =
        action(tr("Move &up"), "moveLectureUpAction", [this] { m_lecture->moveCurrent(-1); });
    up->setIconText(tr("Up"));
    QAction* down =
        action(tr("Move do&wn"), "moveLectureDownAction", [this] { m_lecture->moveCurrent(1); });
    down->setIconText(tr("Down"));
    menu->addSeparator();
    // keyboard control of a demo: Page Down and Page Up, the gallery when no lecture is open
    QAction* next = action(tr("Ne&xt scene"), "nextSceneAction", [this] { stepScene(1); });
    next->setShortcut(QKeySequence(Qt::Key_PageDown));
    next->setStatusTip(tr("The lecture's next scene, or the gallery's when no lecture is open"));
    QAction* previous =
        action(tr("Pre&vious scene"), "previousSceneAction", [this] { stepScene(-1); });
    previous->setShortcut(QKeySequence(Qt::Key_PageUp));
    menu->addSeparator();
    menu->addAction(m_lectureDock->toggleViewAction());
    m_lecture->addButtons({add, remove, up, down});

    auto enable = [=, this] {
        const bool entry = m_lecture->current() >= 0;
        replace->setEnabled(entry);
        remove->setEnabled(entry);
        up->setEnabled(entry && m_lecture->current() > 0);
        down->setEnabled(entry &&
                         m_lecture->current() + 1 < int(m_lecture->lecture().entries.size()));
        showLecturePosition();
    };
    connect(m_lecture, &LecturePanel::changed, this, enable);
    connect(m_lecture, &LecturePanel::entryActivated, this,
            [this](int index) { showLectureEntry(index); });
    enable();
}

QString MainWindow::lecturePosition() const {
    if (!m_lecture || !m_lecture->isOpen() || m_lecture->current() < 0)
        return {};
    return tr("scene %1 of %2")
        .arg(m_lecture->current() + 1)
        .arg(m_lecture->lecture().entries.size());
}

void MainWindow::showLecturePosition() {
    const QString position = lecturePosition();
    m_lecturePosition->setText(position.isEmpty() ? QString() : tr("Lecture: %1").arg(position));
    QString title = tr("Lecture");
    if (m_lecture->isOpen()) {
        const QString name = m_lecture->fileName().isEmpty()
                                 ? tr("untitled")
                                 : QFileInfo(m_lecture->fileName()).fileName();
        title = tr("Lecture: %1%2")
                    .arg(name, m_lecture->isModified() ? QStringLiteral("*") : QString());
    }
    m_lectureDock->setWindowTitle(title);
    // presenting, the status bar is hidden: the notes beside the scene say where the lecture is
    if (auto* notes = findChild<QDockWidget*>(QStringLiteral("notesDock")))
        notes->setWindowTitle(position.isEmpty() ? tr("Notes") : tr("Notes (%1)").arg(position));
    updateTitle();
}

void MainWindow::stepScene(int direction) {
    if (!m_lecture->isOpen()) {
        stepGallery(direction);
        return;
    }
    const int index = m_lecture->stepFrom(direction);
    if (index < 0) {
        statusBar()->showMessage(
            tr("The lecture has no scenes yet: Lecture \u25b8 Add the current scene (Ctrl+L)"),
            8000);
        return;
    }
    showLectureEntry(index);
}

bool MainWindow::showLectureEntry(int index) {
    if (index < 0 || index >= int(m_lecture->lecture().entries.size()))
        return false;
    // Page Down goes on from here, whether the scene came or not
    m_lecture->setCurrent(index);
    const Scene scene = m_lecture->lecture().entries[std::size_t(index)].scene;
    try {
        m_document->loadNow(scene, tr("Lecture: %1").arg(m_lecture->entryLabel(index)));
    } catch (const InputError& e) {
        const QString message = tr("The lecture's scene %1 does not run: %2")
                                    .arg(index + 1)
                                    .arg(QString::fromStdString(e.what()));
        m_lastFileError = message;
        statusBar()->showMessage(message, 10000);
        return false;
    }
    statusBar()->clearMessage();
    startNewScene();
    m_canvas->fitScene();
    if (!scene.note.empty() && !m_presentation->isActive()) {
        if (auto* notes = findChild<QDockWidget*>(QStringLiteral("notesDock")))
            bringDockForward(this, notes);
    }
    showLecturePosition();
    return true;
}

void MainWindow::addSceneToLecture() {
    m_document->flush();
    if (!m_lecture->isOpen())
        m_lecture->open({}, {});
    if (m_lecture->lecture().entries.size() >= kMaxLectureScenes) {
        statusBar()->showMessage(
            tr("A lecture has at most %1 scenes; this one is full").arg(kMaxLectureScenes), 8000);
        return;
    }
    const Scene& scene = m_document->scene();
    const int at = m_lecture->add({titleOf(scene, m_document->fileName()), scene});
    if (!m_lectureDock->isVisible())
        bringDockForward(this, m_lectureDock);
    statusBar()->showMessage(tr("Added to the lecture as scene %1 of %2")
                                 .arg(at + 1)
                                 .arg(m_lecture->lecture().entries.size()),
                             4000);
}

void MainWindow::newLecture() {
    if (!maybeSaveLecture())
        return;
    m_lecture->open({}, {});
    bringDockForward(this, m_lectureDock);
    statusBar()->showMessage(
        tr("A new lecture: add scenes to it with Lecture \u25b8 Add the current scene (Ctrl+L)"),
        8000);
}

bool MainWindow::openLecture(const QString& path) {
    Lecture lecture;
    try {
        lecture = loadLectureFile(path.toStdString());
    } catch (const std::exception& e) {
        showFileError(QStringLiteral("%1: %2").arg(path, QString::fromStdString(e.what())));
        return false;
    }
    if (!maybeSaveLecture())
        return false;
    m_lecture->open(std::move(lecture), path);
    rememberFolder(QStringLiteral("lecture"), path);
    if (m_useSettings) {
        addRecentFile(path);
        rebuildRecentMenu();
    }
    bringDockForward(this, m_lectureDock);
    if (!isVisible()) // given at start: in front once the window's docks are laid out
        QTimer::singleShot(0, this, [this] {
            if (m_lecture->isOpen())
                bringDockForward(this, m_lectureDock);
        });
    if (!m_lecture->lecture().entries.empty())
        showLectureEntry(0);
    return true;
}

bool MainWindow::saveLecture(const QString& path) {
    try {
        saveLectureFile(path.toStdString(), m_lecture->lecture());
    } catch (const std::exception& e) {
        showFileError(QString::fromStdString(e.what()));
        return false;
    }
    m_lecture->markSaved(path);
    if (m_useSettings) {
        addRecentFile(path);
        rebuildRecentMenu();
    }
    statusBar()->showMessage(tr("Saved the lecture in %1").arg(path), 4000);
    return true;
}

void MainWindow::openLectureDialog() {
    const QString path = chooseOpenFile(this, tr("Open lecture"), QStringLiteral("lecture"),
                                        tr("Lectures (*.json);;All files (*)"));
    if (!path.isEmpty())
        openLecture(path);
}

bool MainWindow::saveLectureDialog(bool askName) {
    if (!m_lecture->isOpen()) {
        statusBar()->showMessage(tr("No lecture is open: Lecture \u25b8 New lecture"), 6000);
        return false;
    }
    QString path = m_lecture->fileName();
    if (askName || path.isEmpty()) {
        const QString stem = m_lecture->lecture().title.empty()
                                 ? tr("lecture")
                                 : QString::fromStdString(m_lecture->lecture().title);
        path = chooseSaveFile(this, tr("Save lecture"), QStringLiteral("lecture"), stem,
                              tr("Lectures (*.json)"));
    }
    return !path.isEmpty() && saveLecture(path);
}

bool MainWindow::maybeSaveLecture() {
    if (!m_useSettings || !m_lecture->isOpen() || !m_lecture->isModified())
        return true;
    const auto answer = QMessageBox::question(
        this, tr("Chaplygin Lab"), tr("The lecture has unsaved changes. Save them?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save)
        return saveLectureDialog(false);
    return answer == QMessageBox::Discard;
}

} // namespace chaplygin::ui
