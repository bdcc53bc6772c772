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

void placeOnScreen(QWidget* window, const QSize& wanted, const QWidget* over) {
    const QScreen* screen = over && over->screen() ? over->screen() : window->screen();
    if (!screen) {
        window->resize(wanted);
        return;
    }
    const QRect available = screen->availableGeometry();
    // the frame the window manager adds, as far as it is known before the window is shown
    const QSize frame = window->frameGeometry().size() - window->geometry().size();
    const QSize size = wanted.boundedTo(available.size() * 0.9 - frame);
    window->resize(size); // not below the window's minimum size
    QRect placed(QPoint(0, 0), window->size() + frame);
    placed.moveCenter(over ? over->frameGeometry().center() : available.center());
    placed.moveLeft(std::clamp(placed.left(), available.left(),
                               std::max(available.left(), available.right() + 1 - placed.width())));
    placed.moveTop(std::clamp(placed.top(), available.top(),
                              std::max(available.top(), available.bottom() + 1 - placed.height())));
    window->move(placed.topLeft());
}

void saveWindowLayout(const QMainWindow* window) {
    QSettings settings;
    settings.setValue(QStringLiteral("geometry"), window->saveGeometry());
    settings.setValue(QStringLiteral("windowState"), window->saveState());
}

} // namespace chaplygin::ui
