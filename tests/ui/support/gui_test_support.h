#pragma once
// Shared set-up of the GUI tests: settings in a test location, and the window as every test
// starts with it.
#include "document/scene_document.h"
#include "shell/main_window.h"

#include <QAction>
#include <QApplication>
#include <QCoreApplication>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QMouseEvent>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <initializer_list>
#include <memory>

namespace chaplygin::ui::test {

/// A straight drawn path along x from the origin, 4 m long.
inline Scene straightScene() {
    Scene s;
    s.path.kind = PathKind::Polyline;
    s.path.points = {{0, 0}, {4, 0}};
    return s;
}

/// QSettings go to a folder of this process, never the user's and never another test's: ctest
/// runs the functions of one suite as parallel processes, and a folder one of them remembered
/// and then deleted must not reach another through a shared settings file.
inline void useTestSettings(const QString& applicationName) {
    QStandardPaths::setTestModeEnabled(true);
    static QTemporaryDir settingsFolder;
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settingsFolder.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsFolder.path());
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

/// Text typed into a line edit as the user does: all selected, deleted, then the keys.
inline void typeInto(QLineEdit* edit, const QString& text) {
    edit->selectAll();
    QTest::keyClick(edit, Qt::Key_Delete);
    QTest::keyClicks(edit, text);
}

/// The menu bar's item with this text (its mnemonic's ampersand aside), or null.
inline QAction* menuAction(QMenuBar* bar, const QString& text) {
    for (QAction* menu : bar->actions())
        if (menu->menu())
            for (QAction* a : menu->menu()->actions())
                if (a->text().remove(QLatin1Char('&')) == text)
                    return a;
    return nullptr;
}

/// Whether one of the menu bar's menus holds the action.
inline bool inMenuBar(QMenuBar* bar, QAction* action) {
    for (QAction* menu : bar->actions())
        if (menu->menu() && menu->menu()->actions().contains(action))
            return true;
    return false;
}

} // namespace chaplygin::ui::test
