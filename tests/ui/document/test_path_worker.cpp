// The path worker (docs/robustness.md, In the desktop app): typed paths are tabulated off the UI
// thread, the event loop keeps running meanwhile, and the latest request wins.
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "panels/path_panel.h"
#include "shell/main_window.h"
#include "widgets/number_field.h"

#include <QLineEdit>
#include <QStatusBar>
#include <QTimer>
#include <QUndoStack>
#include <QtTest>

#include <algorithm>
#include <memory>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {
// a path whose tabulation takes far longer than a frame
const QString kHeavy = QStringLiteral("sin(30*x)");
constexpr double kHeavyTo = 60; // 39,000 panels, within the table's budget
} // namespace

class TestPathWorker : public QObject {
    Q_OBJECT

  private slots:
    void init();
    void cleanup();
    void heavyPathKeepsEventLoopResponsive();
    void latestTypedPathWins();

  private:
    std::unique_ptr<MainWindow> m_window;
};

void TestPathWorker::init() {
    m_window = test::showTestWindow();
    QVERIFY(m_window);
}

void TestPathWorker::cleanup() {
    m_window.reset();
}

void TestPathWorker::heavyPathKeepsEventLoopResponsive() {
    m_window->document()->flush();
    auto before = m_window->document()->solution();
    int undoCount = m_window->undoStack()->count();
    PathPanel* panel = m_window->pathPanel();
    panel->fromSpin()->setValue(0);
    panel->toSpin()->setValue(kHeavyTo);
    panel->graphEdit()->setText(kHeavy);
    SceneDocument* document = m_window->document();
    // responsiveness without a stopwatch: a timer keeps firing while the path is being built
    int ticksWhilePending = 0;
    QTimer timer;
    timer.setInterval(5);
    connect(&timer, &QTimer::timeout, this, [&] {
        if (document->pathPending())
            ++ticksWhilePending;
    });
    timer.start();
    QTest::keyClick(panel->graphEdit(), Qt::Key_Return);
    QVERIFY2(document->pathPending(), "the wiggly path is still being tabulated");
    QVERIFY(m_window->statusBar()->currentMessage().startsWith(QStringLiteral("Tabulating")));
    // meanwhile the last valid solution stays on screen and the event loop keeps running
    QCOMPARE(document->solution(), before);
    QTRY_VERIFY_WITH_TIMEOUT(!document->pathPending(), 30000);
    timer.stop();
    QVERIFY2(ticksWhilePending >= 3, qPrintable(QString::number(ticksWhilePending)));
    document->flush();
    QCOMPARE(QString::fromStdString(document->solution()->scene().path.y), kHeavy);
    QCOMPARE(m_window->undoStack()->count(), undoCount + 1);
    QVERIFY(panel->errorText().isEmpty());
    QVERIFY(!m_window->statusBar()->currentMessage().startsWith(QStringLiteral("Tabulating")));
}

void TestPathWorker::latestTypedPathWins() {
    m_window->document()->flush();
    auto before = m_window->document()->solution();
    int undoCount = m_window->undoStack()->count();
    PathPanel* panel = m_window->pathPanel();
    panel->fromSpin()->setValue(0);
    panel->toSpin()->setValue(kHeavyTo);
    panel->graphEdit()->setText(kHeavy);
    QTest::keyClick(panel->graphEdit(), Qt::Key_Return);
    QVERIFY(m_window->document()->pathPending());
    // corrected before the heavy one is done: only the last one is applied
    panel->graphEdit()->setText(QStringLiteral("0.5*x"));
    QTest::keyClick(panel->graphEdit(), Qt::Key_Return);
    m_window->document()->flush();
    QCOMPARE(QString::fromStdString(m_window->document()->scene().path.y), QStringLiteral("0.5*x"));
    QCOMPARE(m_window->undoStack()->count(), undoCount + 1);
    // and an error typed after a valid request wins as well
    panel->graphEdit()->setText(kHeavy);
    QTest::keyClick(panel->graphEdit(), Qt::Key_Return);
    panel->graphEdit()->setText(QStringLiteral("sin(x"));
    QTest::keyClick(panel->graphEdit(), Qt::Key_Return);
    m_window->document()->flush();
    QVERIFY(panel->errorText().contains(QStringLiteral("position")));
    QTest::qWait(50); // the superseded heavy path never lands
    QCOMPARE(QString::fromStdString(m_window->document()->scene().path.y), QStringLiteral("0.5*x"));
}

QTEST_MAIN(TestPathWorker)
#include "test_path_worker.moc"
