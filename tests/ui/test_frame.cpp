// GUI tests of the animation frame's economies: what a frame repaints and lays out, and that
// the cached layers draw what direct drawing draws. Offscreen, through the real window.
#include "canvas/scene_canvas.h"
#include "gui_test_support.h"
#include "shell/main_window.h"
#include "shell/playback.h"
#include "shell/timeline_bar.h"

#include <QLabel>
#include <QtTest>

#include <memory>

using namespace chaplygin;
using namespace chaplygin::ui;

namespace {

// counts the events of one type a widget receives
class EventCounter : public QObject {
  public:
    explicit EventCounter(QEvent::Type type) : m_type(type) {}
    int count = 0;
    bool eventFilter(QObject*, QEvent* e) override {
        count += e->type() == m_type ? 1 : 0;
        return false;
    }

  private:
    QEvent::Type m_type;
};

} // namespace

class TestFrame : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase();
    void init();
    void cleanup();

    void timeReadoutFitsWithoutLayingOutTheWindow();

  private:
    std::unique_ptr<MainWindow> m_window;
};

void TestFrame::initTestCase() {
    test::useTestSettings(QStringLiteral("ui_frame_tests"));
}

void TestFrame::init() {
    m_window = test::showTestWindow();
    QVERIFY(m_window && m_window->document()->solution());
}

void TestFrame::cleanup() {
    m_window.reset();
}

void TestFrame::timeReadoutFitsWithoutLayingOutTheWindow() {
    QLabel* label = m_window->timeline()->timeLabel();
    Playback* playback = m_window->playback();
    QTest::qWait(200); // the window's first layout settles
    EventCounter layouts(QEvent::LayoutRequest);
    m_window->installEventFilter(&layouts);
    // every time up to the end fits the label, and a new time lays out no part of the window
    for (double t : {0.0, 1.0, 9.99, playback->tEnd()}) {
        playback->seek(t);
        QCoreApplication::processEvents();
        QVERIFY(label->text().contains(QString::number(t, 'f', 2)));
        QVERIFY2(label->fontMetrics().horizontalAdvance(label->text()) <=
                     label->contentsRect().width(),
                 qPrintable(label->text()));
    }
    QCOMPARE(layouts.count, 0);
    // a longer horizon makes room for its longer times
    Scene s = m_window->document()->scene();
    s.speed = 0.1; // ten times slower: the end is past 100 s
    try {
        m_window->loadScene(s);
    } catch (const std::exception& e) {
        QFAIL(e.what());
    }
    m_window->document()->flush();
    playback->seek(111.11);
    QCoreApplication::processEvents();
    QVERIFY(label->text().contains(QStringLiteral("111.11")));
    QVERIFY(label->fontMetrics().horizontalAdvance(label->text()) <= label->contentsRect().width());
}

QTEST_MAIN(TestFrame)
#include "test_frame.moc"
