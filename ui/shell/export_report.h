#pragma once
// The status bar's word on a finished export: what was written where, and a button that opens
// the folder in the desktop's file manager.
#include <QString>
#include <QUrl>
#include <QWidget>

#include <functional>

class QStatusBar;
class QToolButton;

namespace chaplygin::ui {

class ElidedLabel;

/// A permanent status-bar widget, hidden until an export finishes: "CSV written to
/// /home/me/runs" and an "Open folder" button (QDesktopServices::openUrl). It stays until the
/// next export or until dismissed.
class ExportReport : public QWidget {
    Q_OBJECT
  public:
    explicit ExportReport(QStatusBar* bar);

    /// Shows message ("Plots written to /home/me/plots") and offers to open folder.
    void report(const QString& message, const QString& folder);
    const QString& folder() const { return m_folder; }
    QString text() const;
    QToolButton* openButton() const { return m_open; }

    /// Replaces QDesktopServices::openUrl (tests); an empty function restores it.
    using OpenUrl = std::function<void(const QUrl&)>;
    static void setOpenUrlHook(OpenUrl hook);

  private:
    ElidedLabel* m_text;
    QToolButton* m_open;
    QToolButton* m_close;
    QString m_folder;
};

} // namespace chaplygin::ui
