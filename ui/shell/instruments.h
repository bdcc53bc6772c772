#pragma once
#include <QMenu>

class QDockWidget;

namespace chaplygin::ui {

class MainWindow;
class NotesPanel;
class EquationsPanel;

/// View > Vectors: a toggle per arrow (saved in the scene, so each is an undo step), and
/// longer, shorter or automatic lengths for the shown ones.
class VectorsMenu : public QMenu {
    Q_OBJECT
  public:
    explicit VectorsMenu(MainWindow* window);
    /// The toggle of an arrow, by VectorKind.
    QAction* toggle(int kind) const { return m_toggles[kind]; }

  private:
    void sync();
    void rescale(double factor); // 0: automatic
    MainWindow* m_window;
    QAction* m_toggles[5] = {};
};

/// The Compare menu: "Pin this run" and "Clear pins" (scene changes, so undo steps).
class CompareMenu : public QMenu {
    Q_OBJECT
  public:
    explicit CompareMenu(MainWindow* window);
    QAction* pinAction() const { return m_pin; }
    QAction* clearAction() const { return m_clear; }

  private:
    void sync();
    MainWindow* m_window;
    QAction* m_pin;
    QAction* m_clear;
};

/// Adds the teaching instruments to a window: the Notes and Equations docks (right, tabbed
/// with the Accuracy dock), View > Vectors and the Compare menu. Called once, by the window, with
/// the View menu it extends and the Accuracy dock it tabs with.
void installInstruments(MainWindow* window, QMenu& viewMenu, QDockWidget& accuracyDock);

} // namespace chaplygin::ui
