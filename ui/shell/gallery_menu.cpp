#include "shell/gallery_menu.h"

#include "document/scene_texts.h"
#include "lab/gallery.h"

namespace chaplygin::ui {

GalleryMenu::GalleryMenu(QWidget* parent) : QMenu(tr("&Gallery"), parent) {
    setToolTipsVisible(true);
    for (const GalleryEntry& e : galleryEntries()) {
        const QString name = QString::fromStdString(e.name);
        QString title = sceneText(e.title);
        if (e.rejected)
            title += tr(" (refused)");
        QAction* action = addAction(title, this, [this, name] { emit entryChosen(name); });
        action->setObjectName(QStringLiteral("gallery-") + name);
        action->setStatusTip(sceneText(e.scene.note));
        action->setToolTip(sceneText(e.scene.note));
    }
}

} // namespace chaplygin::ui
