// The window at the sizes of a classroom: the first start sized to the screen, no scrolling docks
// at 1280x800, a usable canvas at 1024x768, the canvas legend in its own strip, the status bar.
// Offscreen, real widgets.
#include "canvas/scene_canvas.h"
#include "shell/dock_layout.h"
#include "shell/elided_label.h"
#include "shell/window_layout.h"
#include "window_fixture.h"

#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QStatusBar>
#include <QTabBar>
#include <QtTest>

#include <cmath>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestWindowLayout : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_window_layout_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void firstStartSizedToScreen();
    void firstStartBalancedOnceShown();
    void narrowedWindowKeepsCanvasUsable();
    void noDockScrollsAt1280x800();
    void usableCanvasAt1024x768();
    void legendOutsideDrawingArea();
    void statusBarElidedWithTooltip();
    void dockTabsWholeAt1024x768();
    void firstStartShowsThePathTab();
    void openedSceneShowsThePlots();
    void methodsAndSweepTabsGrow();
};

void TestWindowLayout::firstStartSizedToScreen() {
    FirstStart big = firstStartGeometry(QRect(0, 0, 1920, 1080));
    QCOMPARE(big.geometry.size(), QSize(1632, 918));
    QCOMPARE(big.geometry.center(), QRect(0, 0, 1920, 1080).center());
    QVERIFY(!big.maximised);
    FirstStart small = firstStartGeometry(QRect(0, 0, 1280, 800));
    QVERIFY(small.maximised);
    QCOMPARE(small.geometry, QRect(0, 0, 1280, 800));
    // a window with (empty) settings starts sized to its screen, not at a fixed 1280 x 800
    QSettings().clear();
    MainWindow window(true);
    FirstStart expected = firstStartGeometry(window.screen()->availableGeometry());
    if (expected.maximised)
        QVERIFY(window.windowState() & Qt::WindowMaximized);
    else
        QCOMPARE(window.size(), expected.geometry.size());
}

void TestWindowLayout::firstStartBalancedOnceShown() {
    // the dock sizes of a first start are those balanceDocks gives the shown window (before it
    // is shown the docks have no geometry to resize)
    QSettings().clear();
    MainWindow window(true);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QApplication::processEvents();
    auto* plots = window.findChild<QDockWidget*>(QStringLiteral("plotsDock"));
    auto* path = window.findChild<QDockWidget*>(QStringLiteral("pathDock"));
    const int plotsHeight = plots->height(), pathWidth = path->width();
    window.balanceDocks();
    QApplication::processEvents();
    QVERIFY2(
        std::abs(plots->height() - plotsHeight) <= 2,
        qPrintable(
            QStringLiteral("plots %1 px, balanced %2 px").arg(plotsHeight).arg(plots->height())));
    QVERIFY2(
        std::abs(path->width() - pathWidth) <= 2,
        qPrintable(QStringLiteral("path %1 px, balanced %2 px").arg(pathWidth).arg(path->width())));
}

void TestWindowLayout::narrowedWindowKeepsCanvasUsable() {
    // a window narrowed below 1200 px while it runs (a projector plugged in) tabs the right-hand
    // docks on the left as a narrow first start does
    m_window->resize(1024, 768);
    QApplication::processEvents();
    QCOMPARE(m_window->dockWidgetArea(dock("accuracyDock")), Qt::LeftDockWidgetArea);
    QTRY_VERIFY2(m_window->canvas()->width() >= 480,
                 qPrintable(QString::number(m_window->canvas()->width())));
    // widened again, the docks the narrowing moved go back to their own side, in their order
    // and with the accuracy in front; the path keeps the front on the left
    dock("notesDock")->show();
    m_window->resize(1280, 800);
    QApplication::processEvents();
    for (const char* name : {"accuracyDock", "notesDock", "equationsDock"})
        QCOMPARE(m_window->dockWidgetArea(dock(name)), Qt::RightDockWidgetArea);
    QTRY_VERIFY(dock("accuracyDock")->isVisible() &&
                !dock("accuracyDock")->visibleRegion().isEmpty());
    // the Notes, Equations and (hidden) Values docks tabbed with it again
    QCOMPARE(m_window->tabifiedDockWidgets(dock("accuracyDock")).size(), 3);
    QVERIFY(!dock("pathDock")->visibleRegion().isEmpty());
    // a dock the user puts on the left of a wide window stays there
    m_window->addDockWidget(Qt::LeftDockWidgetArea, dock("equationsDock"));
    m_window->resize(1300, 800);
    QApplication::processEvents();
    QCOMPARE(m_window->dockWidgetArea(dock("equationsDock")), Qt::LeftDockWidgetArea);
}

// the first start shows the Path dock in front of its tabs, at every size (the parameters and
// the perturbation share them)
void TestWindowLayout::firstStartShowsThePathTab() {
    for (const QSize size : {QSize(1024, 768), QSize(1280, 800), QSize(1920, 1080)}) {
        MainWindow window(false); // a first start, sized here (the offscreen screen is small)
        window.resize(size);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QApplication::processEvents();
        QCOMPARE(window.size(), size);
        auto* path = window.findChild<QDockWidget*>(QStringLiteral("pathDock"));
        auto* parameters = window.findChild<QDockWidget*>(QStringLiteral("parametersDock"));
        auto* plots = window.findChild<QDockWidget*>(QStringLiteral("plotsDock"));
        QVERIFY2(path->isVisible() && !path->visibleRegion().isEmpty(),
                 qPrintable(QStringLiteral("%1x%2").arg(size.width()).arg(size.height())));
        QVERIFY(parameters->visibleRegion().isEmpty());
        QVERIFY(!plots->visibleRegion().isEmpty());
    }
}

// a scene opened while the Sweep tab (empty for a new scene) or the Methods tab is in front, and a
// start that restores such a layout, show the plots
void TestWindowLayout::openedSceneShowsThePlots() {
    const QString file = m_dir.filePath(QStringLiteral("circle.json"));
    choosePreset("circle");
    QVERIFY(m_window->saveFile(file));
    for (const char* front : {"sweepDock", "methodsDock"}) {
        dock(front)->raise();
        QApplication::processEvents();
        QVERIFY(dock("plotsDock")->visibleRegion().isEmpty());
        QVERIFY(m_window->openFile(file));
        QApplication::processEvents();
        QVERIFY2(!dock("plotsDock")->visibleRegion().isEmpty(), front);
    }
    dock("sweepDock")->raise();
    QApplication::processEvents();
    saveWindowLayout(m_window.get());
    MainWindow restarted(true);
    restarted.show();
    QVERIFY(QTest::qWaitForWindowExposed(&restarted));
    QApplication::processEvents();
    QVERIFY(
        !restarted.findChild<QDockWidget*>(QStringLiteral("plotsDock"))->visibleRegion().isEmpty());
}

// the Methods and Sweep tabs, clicked, grow the bottom docks as their menu entries do; the
// Plots tab gives the plots their height back
void TestWindowLayout::methodsAndSweepTabsGrow() {
    m_window->resize(1280, 800);
    m_window->balanceDocks();
    QApplication::processEvents();
    const int plotsHeight = dock("plotsDock")->height();
    QVERIFY(plotsHeight < 300);
    auto clickTab = [this](const QString& title) {
        for (QTabBar* bar : m_window->findChildren<QTabBar*>(Qt::FindDirectChildrenOnly))
            for (int i = 0; i < bar->count(); ++i)
                if (bar->isVisible() && bar->tabText(i) == title) {
                    QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(i).center());
                    QApplication::processEvents();
                    QApplication::processEvents();
                    return true;
                }
        return false;
    };
    // as tall as asked, or as the canvas's minimum height leaves
    QVERIFY(clickTab(QStringLiteral("Methods")));
    QTRY_VERIFY2(dock("methodsDock")->height() >= std::min(methodsDockHeight(800), 330),
                 qPrintable(QString::number(dock("methodsDock")->height())));
    const int methodsHeight = dock("methodsDock")->height();
    QVERIFY(clickTab(QStringLiteral("Sweep")));
    QTRY_VERIFY2(dock("sweepDock")->height() >= std::min(sweepDockHeight(800), methodsHeight),
                 qPrintable(QString::number(dock("sweepDock")->height())));
    QVERIFY(clickTab(QStringLiteral("Plots")));
    QTRY_VERIFY2(std::abs(dock("plotsDock")->height() - plotsHeight) <= 4,
                 qPrintable(QString::number(dock("plotsDock")->height())));
    // the menu entry's height is the tab's
    m_window->showMethodsDock();
    QTRY_VERIFY2(std::abs(dock("methodsDock")->height() - methodsHeight) <= 4,
                 qPrintable(QString::number(dock("methodsDock")->height())));
}

void TestWindowLayout::noDockScrollsAt1280x800() {
    m_window->resize(1280, 800);
    m_window->balanceDocks();
    QApplication::processEvents();
    for (const char* name : {"pathDock", "parametersDock"}) {
        QDockWidget* d = dock(name);
        d->raise();
        QApplication::processEvents();
        auto* scroll = qobject_cast<QScrollArea*>(d->widget());
        QVERIFY(scroll);
        QVERIFY2(scroll->verticalScrollBar()->maximum() == 0,
                 qPrintable(QStringLiteral("%1 scrolls by %2 px")
                                .arg(QLatin1String(name))
                                .arg(scroll->verticalScrollBar()->maximum())));
    }
}

void TestWindowLayout::usableCanvasAt1024x768() {
    m_window->resize(1024, 768);
    m_window->balanceDocks();
    QApplication::processEvents();
    SceneCanvas* canvas = m_window->canvas();
    QVERIFY2(canvas->width() >= 480, qPrintable(QString::number(canvas->width())));
    QVERIFY2(canvas->drawingArea().height() >= 220,
             qPrintable(QString::number(canvas->drawingArea().height())));
}

void TestWindowLayout::dockTabsWholeAt1024x768() {
    // six docks tabbed on the left (path, parameters, accuracy, notes, equations with the
    // instruments open): each tab shows its whole title
    m_window->resize(1024, 768);
    m_window->balanceDocks();
    QApplication::processEvents();
    for (const char* name : {"accuracyDock", "notesDock", "equationsDock"}) {
        dock(name)->show();
        QCOMPARE(m_window->dockWidgetArea(dock(name)), Qt::LeftDockWidgetArea);
    }
    m_window->balanceDocks();
    QApplication::processEvents();
    int tabs = 0, left = 0;
    for (QTabBar* bar : m_window->findChildren<QTabBar*>(Qt::FindDirectChildrenOnly)) {
        if (!bar->isVisible())
            continue;
        left = std::max(left, bar->count());
        for (int i = 0; i < bar->count(); ++i, ++tabs) {
            const QString text = bar->tabText(i);
            const int need = bar->fontMetrics().horizontalAdvance(text);
            QVERIFY2(bar->elideMode() == Qt::ElideNone && bar->tabRect(i).width() >= need + 4,
                     qPrintable(QStringLiteral("\"%1\" needs %2 px, its tab is %3 px")
                                    .arg(text)
                                    .arg(need)
                                    .arg(bar->tabRect(i).width())));
        }
    }
    QVERIFY2(left >= 5, qPrintable(QString::number(left)));
    QVERIFY(tabs >= 8);
}

void TestWindowLayout::legendOutsideDrawingArea() {
    SceneCanvas* canvas = m_window->canvas();
    canvas->fitScene();
    QRectF area = canvas->drawingArea();
    QVERIFY(area.bottom() < canvas->height() - 40); // the legend has its own strip
    // what either fit frames lies inside the drawing area, none of it under the legend
    auto inside = [&](const QRectF& bounds) {
        const QRectF pixels =
            QRectF(canvas->toPixel(bounds.topLeft()), canvas->toPixel(bounds.bottomRight()))
                .normalized();
        return area.adjusted(-1, -1, 1, 1).contains(pixels);
    };
    QVERIFY(inside(canvas->pathBounds()));
    canvas->fitEverything();
    QVERIFY(inside(canvas->sceneBounds()));
    // L collapses the legend: the drawing area grows to the bottom edge
    canvas->setFocus();
    QTest::keyClick(canvas, Qt::Key_L);
    QVERIFY(!canvas->legendVisible());
    QCOMPARE(canvas->drawingArea().bottom(), double(canvas->height()));
    QTest::keyClick(canvas, Qt::Key_L);
    QVERIFY(canvas->legendVisible());
}

void TestWindowLayout::statusBarElidedWithTooltip() {
    ElidedLabel* label = m_window->statusLabel();
    QVERIFY(!label->fullText().isEmpty());
    QCOMPARE(label->toolTip(), label->fullText());
    const QString longText = QString(QStringLiteral("model ")).repeated(200);
    label->setFullText(longText);
    QApplication::processEvents();
    QVERIFY(label->text().endsWith(QChar(0x2026)));
    QVERIFY(label->fontMetrics().horizontalAdvance(label->text()) <= label->width());
    QCOMPARE(label->toolTip(), longText);
    // the status bar does not grow with the text
    QVERIFY(m_window->statusBar()->width() <= m_window->width());
}

QTEST_MAIN(TestWindowLayout)
#include "test_window_layout.moc"
