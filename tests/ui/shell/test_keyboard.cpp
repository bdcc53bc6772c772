// Keyboard and accessibility: both redo shortcuts, Space plays outside text fields, Tab leaves
// tables and reaches the parameters, Enter applies a range field and hands the keyboard to the
// canvas, a preset key says what it loaded and is one undo step, accessible names. Offscreen, real
// widgets.
#include "canvas/scene_canvas.h"
#include "panels/methods_panel.h"
#include "panels/parameters_panel.h"
#include "panels/path_panel.h"
#include "shell/playback.h"
#include "shell/timeline_bar.h"
#include "widgets/number_field.h"
#include "window_fixture.h"

#include <QLabel>
#include <QLineEdit>
#include <QSlider>
#include <QStatusBar>
#include <QTableWidget>
#include <QUndoStack>
#include <QtTest>

using namespace chaplygin;
using namespace chaplygin::ui;

class TestKeyboard : public QObject, private test::WindowFixture {
    Q_OBJECT

  private slots:
    void initTestCase() { startSuite("ui_keyboard_tests"); }
    void init() { openWindow(); }
    void cleanup() { closeWindow(); }

    void redoShortcuts();
    void spaceTogglesPlayInSpinBox();
    void tabLeavesTable();
    void tabReachesParameterSpinBoxes();
    void enterInRangeFieldApplies();
    void enterHandsTheKeyboardToTheCanvas();
    void presetKeySaysSoAndIsOneUndoStep();
    void accessibleNames();
};

void TestKeyboard::redoShortcuts() {
    NumberField* m = m_window->parametersPanel()->spinBox(QStringLiteral("m"));
    const double before = m->value();
    for (QKeySequence redo :
         {QKeySequence(Qt::CTRL | Qt::Key_Y), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)}) {
        QVERIFY(m_window->redoAction()->shortcuts().contains(redo));
        m->setValue(before + 1);
        m_window->document()->flush();
        QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
        m_window->document()->flush();
        QCOMPARE(m_window->document()->scene().system.params.at("m"), before);
        QTest::keySequence(m_window.get(), redo);
        m_window->document()->flush();
        QCOMPARE(m_window->document()->scene().system.params.at("m"), before + 1);
        QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
        m_window->document()->flush();
    }
}

void TestKeyboard::spaceTogglesPlayInSpinBox() {
    m_window->showParametersDock();
    NumberField* m = m_window->parametersPanel()->spinBox(QStringLiteral("m"));
    m->setFocus();
    QApplication::processEvents();
    const QString text = m->text();
    QTest::keyClick(m, Qt::Key_Space);
    QVERIFY(m_window->playback()->isPlaying());
    QCOMPARE(m->text(), text);
    QTest::keyClick(m, Qt::Key_Space);
    QVERIFY(!m_window->playback()->isPlaying());
    // a slider and the speed box too; a text field types the space
    QTest::keyClick(m_window->timeline()->slider(), Qt::Key_Space);
    QVERIFY(m_window->playback()->isPlaying());
    m_window->playback()->pause();
    QLineEdit* edit = m_window->pathPanel()->graphEdit();
    m_window->findChild<QDockWidget*>(QStringLiteral("pathDock"))->raise();
    edit->setFocus();
    edit->setText(QStringLiteral("x"));
    QTest::keyClick(edit, Qt::Key_Space);
    QCOMPARE(edit->text(), QStringLiteral("x "));
    QVERIFY(!m_window->playback()->isPlaying());
}

void TestKeyboard::tabLeavesTable() {
    m_window->showMethodsDock();
    QTableWidget* table = m_window->methodsPanel()->chosenTable();
    table->setRowCount(3);
    table->setFocus();
    QApplication::processEvents();
    QVERIFY(table->hasFocus());
    QTest::keyClick(table, Qt::Key_Tab);
    QVERIFY(!table->hasFocus());
    table->setFocus();
    QTest::keyClick(table, Qt::Key_Backtab, Qt::ShiftModifier);
    QVERIFY(!table->hasFocus());
}

void TestKeyboard::tabReachesParameterSpinBoxes() {
    m_window->showParametersDock();
    QApplication::processEvents();
    m_window->canvas()->setFocus();
    QSet<QWidget*> reached;
    for (int i = 0; i < 200; ++i) {
        QWidget* f = QApplication::focusWidget();
        QVERIFY(f);
        reached.insert(f);
        QTest::keyClick(f, Qt::Key_Tab);
    }
    for (const QString& name :
         {QStringLiteral("m"), QStringLiteral("a"), QStringLiteral("speed")}) {
        NumberField* spin = m_window->parametersPanel()->spinBox(name);
        QVERIFY(spin);
        QVERIFY2(reached.contains(spin), qPrintable(name));
    }
    QVERIFY(reached.contains(m_window->canvas()));
    QVERIFY(reached.contains(m_window->timeline()->slider()));
}

void TestKeyboard::enterInRangeFieldApplies() {
    PathPanel* panel = m_window->pathPanel();
    m_window->findChild<QDockWidget*>(QStringLiteral("pathDock"))->raise();
    panel->graphEdit()->setText(QStringLiteral("0.5*x"));
    NumberField* to = panel->toSpin();
    to->setFocus();
    to->selectAll();
    QTest::keyClicks(to, QStringLiteral("2.5"));
    QTest::keyClick(to, Qt::Key_Return);
    m_window->document()->flush();
    QTRY_COMPARE(m_window->document()->scene().path.to, 2.5);
    QCOMPARE(QString::fromStdString(m_window->document()->scene().path.y), QStringLiteral("0.5*x"));
    NumberField* from = panel->fromSpin();
    from->setFocus();
    from->selectAll();
    QTest::keyClicks(from, QStringLiteral("0.5"));
    QTest::keyClick(from, Qt::Key_Enter);
    m_window->document()->flush();
    QTRY_COMPARE(m_window->document()->scene().path.from, 0.5);
}

void TestKeyboard::enterHandsTheKeyboardToTheCanvas() {
    PathPanel* panel = m_window->pathPanel();
    m_window->findChild<QDockWidget*>(QStringLiteral("pathDock"))->raise();
    QLineEdit* edit = panel->graphEdit();
    edit->setFocus();
    edit->selectAll();
    QTest::keyClicks(edit, QStringLiteral("0.5*x"));
    QTest::keyClick(edit, Qt::Key_Return);
    QTRY_COMPARE(QApplication::focusWidget(), static_cast<QWidget*>(m_window->canvas()));
    m_window->document()->flush();
    QCOMPARE(QString::fromStdString(m_window->document()->scene().path.y), QStringLiteral("0.5*x"));
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);
    QVERIFY(m_window->playback()->isPlaying());
    QCOMPARE(edit->text(), QStringLiteral("0.5*x"));
}

void TestKeyboard::presetKeySaysSoAndIsOneUndoStep() {
    const Scene before = m_window->document()->scene();
    const int steps = m_window->undoStack()->count();
    m_window->canvas()->setFocus();
    QTest::keyClick(m_window->canvas(), Qt::Key_2);
    m_window->document()->flush();
    const QString name = QString::fromStdString(presetNames().at(1));
    QCOMPARE(QString::fromStdString(m_window->document()->scene().preset), name);
    QVERIFY2(m_window->statusBar()->currentMessage().contains(name),
             qPrintable(m_window->statusBar()->currentMessage()));
    QCOMPARE(m_window->undoStack()->count(), steps + 1);
    m_window->undoStack()->undo();
    m_window->document()->flush();
    QCOMPARE(m_window->document()->scene(), before);
}

void TestKeyboard::accessibleNames() {
    QVERIFY(!m_window->canvas()->accessibleName().isEmpty());
    QVERIFY(!m_window->canvas()->accessibleDescription().isEmpty());
    QVERIFY(!m_window->timeline()->accessibleName().isEmpty());
    QVERIFY(!m_window->timeline()->slider()->accessibleName().isEmpty());
    QVERIFY(!m_window->timeline()->timeLabel()->accessibleName().isEmpty());
    // the canvas and the slider are reachable by keyboard
    QVERIFY(m_window->canvas()->focusPolicy() & Qt::TabFocus);
    QVERIFY(m_window->timeline()->slider()->focusPolicy() & Qt::TabFocus);
}

QTEST_MAIN(TestKeyboard)
#include "test_keyboard.moc"
