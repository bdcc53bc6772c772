// Checks that need a real X server (its fonts, its window system): run by real_window_test.sh
// under Xvfb with QT_QPA_PLATFORM=xcb; under the offscreen platform, which lays text out
// differently, they skip.
#include "panels/accuracy_readout.h"
#include "window_fixture.h"

#include <QGuiApplication>
#include <QLabel>
#include <QtTest>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestRealWindow : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() {
        if (QGuiApplication::platformName() == QLatin1String("offscreen"))
            QSKIP("needs a real X server (tests/ui/real_window_test.sh runs it under Xvfb)");
        startSuite("ui_real_window_tests");
    }

    void wrappedReadoutsShowTheirWholeText();
};

void TestRealWindow::wrappedReadoutsShowTheirWholeText() {
    // a value that wraps ("no closed form for this scene" on the sinusoid) gets the lines it
    // needs in the Accuracy dock of a first start (on the right from 1200 px up)
    for (QSize size : {QSize(1280, 800), QSize(1920, 1080)}) {
        QSettings().clear();
        MainWindow window(true);
        window.resize(size);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.document()->flush();
        QApplication::processEvents();
        window.accuracyReadout()->refresh();
        QApplication::processEvents();
        QVERIFY(window.accuracyReadout()->isVisible());
        int checked = 0;
        for (QLabel* label : window.accuracyReadout()->findChildren<QLabel*>()) {
            if (!label->wordWrap() || !label->isVisible() || label->text().isEmpty())
                continue;
            ++checked;
            const int needed = label->heightForWidth(label->width());
            QVERIFY2(label->height() >= needed,
                     qPrintable(QStringLiteral("%1x%2: '%3' is %4 px high, needs %5")
                                    .arg(size.width())
                                    .arg(size.height())
                                    .arg(label->text().left(40))
                                    .arg(label->height())
                                    .arg(needed)));
        }
        QVERIFY(checked >= 5);
    }
}

QTEST_MAIN(TestRealWindow)
#include "test_real_window.moc"
