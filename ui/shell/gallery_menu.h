#pragma once
#include <QMenu>
#include <QString>

namespace chaplygin::ui {

/// The Gallery menu ("where methods fail"): one action per galleryEntries() entry,
/// by title, in the core's order; the scene's note is the status tip.
class GalleryMenu : public QMenu {
    Q_OBJECT
  public:
    explicit GalleryMenu(QWidget* parent = nullptr);

  signals:
    /// The entry's short name, e.g. "cusp".
    void entryChosen(const QString& name);
};

} // namespace chaplygin::ui
