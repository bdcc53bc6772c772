#include "shell/gallery_menu.h"

#include "lab/gallery.h"

namespace chaplygin::ui {

namespace {
// the titles of resources/scenes/gallery/*.json, for lupdate; a title missing here stays English
[[maybe_unused]] const char* const kGalleryTitles[] = {
    QT_TRANSLATE_NOOP("chaplygin::ui::GalleryMenu", "A corner in constant-speed mode: cannot turn"),
    QT_TRANSLATE_NOOP("chaplygin::ui::GalleryMenu",
                      "A corner in constant-energy mode: pivot in place"),
    QT_TRANSLATE_NOOP("chaplygin::ui::GalleryMenu", "A cusp: the sleigh backs up"),
    QT_TRANSLATE_NOOP("chaplygin::ui::GalleryMenu", "Very high curvature, b\u03ba = 1000"),
    QT_TRANSLATE_NOOP("chaplygin::ui::GalleryMenu", "A long horizon: t = 5000 s"),
    QT_TRANSLATE_NOOP("chaplygin::ui::GalleryMenu",
                      "Open-loop integration of (36)-(37) drifts off the path"),
    QT_TRANSLATE_NOOP("chaplygin::ui::GalleryMenu",
                      "The paper's printed branch reverses at inflections"),
    QT_TRANSLATE_NOOP("chaplygin::ui::GalleryMenu",
                      "The genuine vakonomic system leaves the circle"),
    QT_TRANSLATE_NOOP("chaplygin::ui::GalleryMenu", "Park sideways by b: two mirror optima"),
    QT_TRANSLATE_NOOP("chaplygin::ui::GalleryMenu", "Pivot by \u03c0: the Maxwell point"),
    QT_TRANSLATE_NOOP("chaplygin::ui::GalleryMenu", "A geodesic past its cut time"),
};
} // namespace

GalleryMenu::GalleryMenu(QWidget* parent) : QMenu(tr("&Gallery"), parent) {
    setToolTipsVisible(true);
    for (const GalleryEntry& e : galleryEntries()) {
        const QString name = QString::fromStdString(e.name);
        QString title = tr(e.title.c_str());
        if (e.rejected)
            title += tr(" (refused)");
        QAction* action = addAction(title, this, [this, name] { emit entryChosen(name); });
        action->setObjectName(QStringLiteral("gallery-") + name);
        action->setStatusTip(QString::fromStdString(e.scene.note));
        action->setToolTip(QString::fromStdString(e.scene.note));
    }
}

} // namespace chaplygin::ui
