// The classroom parts of the main window: help and About, and keyboard control of a demo (the
// paper's presets on 1 ... 4, the gallery on Page Up/Down). Kept apart from main_window.cpp.
#include "shell/main_window.h"

#include "canvas/scene_canvas.h"
#include "lab/gallery.h"
#include "panels/methods_panel.h"
#include "scene/presets.h"
#include "shell/help_window.h"
#include "shell/timeline_bar.h"
#include "shell/window_layout.h"
#include "version.h"

#include <QApplication>
#include <QDockWidget>

namespace chaplygin::ui {

QString MainWindow::aboutText() {
    return tr("<h3>Chaplygin Lab %1</h3>"
              "<p>Control of nonholonomic Chaplygin systems for teaching: the sleigh, the rolling "
              "disk and the two-wheeled carriage follow a prescribed path, beside the free "
              "motion from the same start.</p>"
              "<p><b>Paper:</b> Antunes, Sigaud, de Moraes, <i>Controlling nonholonomic "
              "Chaplygin systems</i>, Brazilian Journal of Physics (2009).</p>"
              "<p><b>Licence:</b> GNU General Public License, version 3 or later (the file "
              "COPYING). Components keep their own licences: Qt %2 (LGPL v3), QCustomPlot "
              "(GPL v3), GiNaC (GPL v2 or later), GSL (GPL v3), muparser (BSD).</p>"
              "<p><b>Credits:</b> the Chaplygin Lab contributors; the equations of motion after "
              "the paper above, re-derived in the physics notes (Help).</p>")
        .arg(QStringLiteral(CHAPLYGIN_LAB_VERSION), QString::fromLatin1(qVersion()));
}

HelpWindow* MainWindow::showHelp(const QString& document, const QString& section) {
    const bool first = !m_help;
    if (first)
        m_help = new HelpWindow(this);
    if (!document.isEmpty())
        m_help->showTopic(document, section);
    m_help->show();
    if (first) // shown, its frame is known
        placeOnScreen(m_help, m_help->size(), this);
    m_help->raise();
    return m_help;
}

void MainWindow::showContextHelp() {
    // the section of the user guide about the part of the window that has the focus; the
    // translation of a section's name is its heading in the translated guide
    QWidget* w = QApplication::focusWidget();
    auto inside = [w](QWidget* area) { return w && area && (w == area || area->isAncestorOf(w)); };
    QString section;
    if (inside(m_docks.parameters))
        section = tr("The system and its parameters");
    else if (inside(m_docks.path))
        section = tr("Choosing a path");
    else if (inside(m_docks.methods) || inside(m_docks.accuracy))
        section = tr("Methods and accuracy");
    else if (inside(m_docks.plots))
        section = tr("Plots");
    else if (inside(m_canvas) || inside(m_timeline))
        section = tr("Animation");
    showHelp(QStringLiteral("user-guide.md"), section);
}

void MainWindow::choosePresetNumber(int index) {
    const std::vector<std::string> presets = presetNames();
    if (index >= 0 && index < int(presets.size()))
        choosePreset(QString::fromStdString(presets[std::size_t(index)]));
}

void MainWindow::stepGallery(int direction) {
    // refused entries are lessons of their own: they are skipped here, they stay in the menu
    const auto& entries = galleryEntries();
    const int n = int(entries.size());
    for (int tries = 0; tries < n; ++tries) {
        m_galleryIndex = ((m_galleryIndex + direction) % n + n) % n;
        if (!entries[std::size_t(m_galleryIndex)].rejected) {
            loadGalleryEntry(QString::fromStdString(entries[std::size_t(m_galleryIndex)].name));
            return;
        }
    }
}

} // namespace chaplygin::ui
