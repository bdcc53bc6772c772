// The main window's scene links: File > Copy link and File > Open link, and a link given as the
// window's argument (a click on a chaplygin-lab: link in a browser or a chat).
#include "shell/main_window.h"

#include "canvas/scene_canvas.h"
#include "document/file_dialogs.h"
#include "document/scene_document.h"
#include "scene/scene_link.h"
#include "shell/playback.h"

#include <QClipboard>
#include <QGuiApplication>
#include <QStatusBar>

#include <exception>

namespace chaplygin::ui {

bool MainWindow::openLink(const QString& link) {
    try {
        // read whole before anything changes: a damaged link never replaces the scene
        const Scene scene = sceneFromLink(link.toStdString());
        m_document->loadNow(scene);
    } catch (const std::exception& e) {
        showFileError(tr("Cannot open the link: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
    m_document->setFileName({});
    m_playback->seek(0);
    m_canvas->fitScene();
    return true;
}

bool MainWindow::copyLink() {
    m_document->flush();
    if (!m_document->error().isEmpty()) {
        showFileError(tr("The scene does not solve (%1); fix it or undo before copying its link")
                          .arg(m_document->error()));
        return false;
    }
    QString link;
    try {
        link = QString::fromStdString(sceneToLink(m_document->scene()));
    } catch (const std::exception& e) {
        showFileError(QString::fromStdString(e.what()));
        return false;
    }
    QGuiApplication::clipboard()->setText(link);
    statusBar()->showMessage(tr("Link copied: %n character(s)", nullptr, int(link.size())), 6000);
    return true;
}

void MainWindow::openLinkDialog() {
    if (!maybeSave())
        return;
    // a link on the clipboard is offered
    const QString clipboard = QGuiApplication::clipboard()->text().trimmed();
    const QString link = askForText(this, tr("Open link"), tr("A chaplygin-lab: link:"),
                                    isSceneLink(clipboard.toStdString()) ? clipboard : QString());
    if (!link.trimmed().isEmpty())
        openLink(link);
}

} // namespace chaplygin::ui
