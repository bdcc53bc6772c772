#pragma once
// The set-up the window tests share: their own settings, a temporary folder, a fresh window for
// every test function, a preset chosen as the user does, and file dialogs answered by a script.
#include "document/file_dialogs.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "scene/presets.h"
#include "shell/main_window.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <memory>
#include <string>

namespace chaplygin::ui::test {

/// Used as a base of a QtTest class, whose initTestCase, init and cleanup slots call
/// startSuite, openWindow and closeWindow.
class WindowFixture {
  protected:
    /// settingsName: the test's own QSettings application name.
    void startSuite(const char* settingsName) {
        useTestSettings(QString::fromLatin1(settingsName));
        QVERIFY(m_dir.isValid());
    }
    /// A window as on a first start without settings (1280x800, the first scene solved).
    void openWindow() {
        QSettings().clear();
        m_window = showTestWindow();
        QVERIFY(m_window && m_window->document()->solution());
    }
    /// openWindow with settings of this test function's own (settingsName_function): ctest
    /// runs a suite's functions in parallel processes, and tests that write and read the
    /// settings must not meet there.
    void openWindowWithOwnSettings(const char* settingsName) {
        QCoreApplication::setApplicationName(QString::fromLatin1(settingsName) + QLatin1Char('_') +
                                             QString::fromLatin1(QTest::currentTestFunction()));
        openWindow();
    }
    void closeWindow() {
        m_window.reset();
        setDialogHook({});
    }
    /// Loads the named preset through the window (keys 1 ... 4 and the Path dock do the same).
    void choosePreset(const char* name) {
        const auto names = presetNames();
        auto it = std::find(names.begin(), names.end(), std::string(name));
        QVERIFY(it != names.end());
        m_window->choosePresetNumber(int(it - names.begin()));
        m_window->document()->flush();
        QCOMPARE(m_window->document()->scene().preset, std::string(name));
    }
    QDockWidget* dock(const char* objectName) const {
        return m_window->findChild<QDockWidget*>(QString::fromLatin1(objectName));
    }

    std::unique_ptr<MainWindow> m_window;
    QTemporaryDir m_dir;
};

/// Answers every file dialog with a fixed choice and records what was proposed.
struct DialogScript {
    QString answer, filter, proposed, caption;
    int calls = 0;
    void install() {
        setDialogHook([this](const QString& c, const QString& p, const QString&) {
            ++calls;
            caption = c;
            proposed = p;
            return DialogChoice{answer, filter};
        });
    }
    ~DialogScript() { setDialogHook({}); }
};

} // namespace chaplygin::ui::test
