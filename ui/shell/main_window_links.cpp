// The main window's scene links: File > Copy link and File > Open link, and a link given as the
// window's argument (a click on a chaplygin-lab: link in a browser or a chat).
#include "shell/main_window.h"

#include "canvas/scene_canvas.h"
#include "document/scene_document.h"
#include "scene/scene_link.h"
#include "shell/playback.h"

#include <QClipboard>
#include <QGuiApplication>
#include <QInputDialog>
#include <QStatusBar>

#include <algorithm>
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
    QInputDialog dialog(this);
    dialog.setWindowTitle(tr("Open link"));
    dialog.setLabelText(tr("A chaplygin-lab: link:"));
    // a link on the clipboard is offered
    const QString clipboard = QGuiApplication::clipboard()->text().trimmed();
    if (isSceneLink(clipboard.toStdString()))
        dialog.setTextValue(clipboard);
    // wide enough to show that it is a link and where it ends being one
    dialog.resize(std::max(dialog.sizeHint().width(), fontMetrics().averageCharWidth() * 70),
                  dialog.sizeHint().height());
    if (dialog.exec() == QDialog::Accepted && !dialog.textValue().trimmed().isEmpty())
        openLink(dialog.textValue());
}

} // namespace chaplygin::ui
