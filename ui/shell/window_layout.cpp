#include "shell/window_layout.h"

#include <QMainWindow>
#include <QScreen>
#include <QSettings>

#include <algorithm>

namespace chaplygin::ui {

FirstStart firstStartGeometry(const QRect& available) {
    FirstStart f;
    if (available.width() <= 1366 || available.height() <= 800) {
        f.geometry = available;
        f.maximised = true;
        return f;
    }
    QSize size(available.width() * 85 / 100, available.height() * 85 / 100);
    f.geometry = QRect(QPoint(0, 0), size);
    f.geometry.moveCenter(available.center());
    return f;
}

bool restoreWindowLayout(QMainWindow* window) {
    QSettings settings;
    const bool restored =
        window->restoreGeometry(settings.value(QStringLiteral("geometry")).toByteArray());
    window->restoreState(settings.value(QStringLiteral("windowState")).toByteArray());
    if (restored)
        return true;
    if (!window->screen()) {
        window->resize(1280, 800);
        return false;
    }
    FirstStart first = firstStartGeometry(window->screen()->availableGeometry());
    window->setGeometry(first.geometry);
    if (first.maximised)
        window->setWindowState(Qt::WindowMaximized);
    return false;
}

void saveWindowLayout(const QMainWindow* window) {
    QSettings settings;
    settings.setValue(QStringLiteral("geometry"), window->saveGeometry());
    settings.setValue(QStringLiteral("windowState"), window->saveState());
}

} // namespace chaplygin::ui
