#pragma once
// Shared set-up of the GUI tests: settings in a test location, and the window as every test
// starts with it.
#include "document/scene_document.h"
#include "shell/main_window.h"

#include <QCoreApplication>
#include <QStandardPaths>
#include <QtTest>

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

} // namespace chaplygin::ui::test
