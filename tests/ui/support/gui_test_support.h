#pragma once
// Shared set-up of the GUI tests: settings in a test location, and the window as every test
// starts with it.
#include "document/scene_document.h"
#include "shell/main_window.h"

#include <QApplication>
#include <QCoreApplication>
#include <QMouseEvent>
#include <QStandardPaths>
#include <QtTest>

#include <initializer_list>
#include <memory>

namespace chaplygin::ui::test {

/// QSettings go to a test location, never the user's.
inline void useTestSettings(const QString& applicationName) {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("ChaplyginLabTests"));
    QCoreApplication::setApplicationName(applicationName);
}

/// A main window without user settings, 1280x800, shown and with its first scene solved;
/// null when the window could not be exposed.
inline std::unique_ptr<MainWindow> showTestWindow() {
    auto window = std::make_unique<MainWindow>(false);
    window->resize(1280, 800);
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get()))
        return nullptr;
    window->document()->flush();
    return window;
}

/// A stroke drawn with the left button held: pressed at `from`, moved through `through`,
/// released at `to` (the canvas in draw mode makes a path of it).
inline void dragStroke(QWidget* canvas, QPoint from, std::initializer_list<QPoint> through,
                       QPoint to) {
    QTest::mousePress(canvas, Qt::LeftButton, {}, from);
    for (QPoint p : through) {
        QMouseEvent move(QEvent::MouseMove, p, canvas->mapToGlobal(p), Qt::NoButton, Qt::LeftButton,
                         {});
        QApplication::sendEvent(canvas, &move);
    }
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, to);
}

} // namespace chaplygin::ui::test
