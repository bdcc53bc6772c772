#pragma once
#include <QRect>

class QMainWindow;
class QWidget;

namespace chaplygin::ui {

/// The window's first start on a screen with the given available geometry: 85 % of it,
/// centred; a screen of at most 1366 x 800 (a laptop, a projector) is used whole (maximised).
struct FirstStart {
    QRect geometry;
    bool maximised = false;
};
FirstStart firstStartGeometry(const QRect& available);

/// Restores the window's geometry and dock state saved in QSettings and returns true; without a
/// saved geometry (a first start) sizes the window to its screen and returns false.
bool restoreWindowLayout(QMainWindow* window);
/// Saves the window's geometry and dock state in QSettings.
void saveWindowLayout(const QMainWindow* window);

/// A tool window (help, introduction) of the wanted size, at most 90 % of the free area of the
/// screen of over, centred over over and moved inside that area.
void placeOnScreen(QWidget* window, const QSize& wanted, const QWidget* over);

} // namespace chaplygin::ui
