#pragma once
#include <QObject>

class QWidget;

namespace chaplygin::ui {

/// Enter in a field of the window's docks (a line edit or a number field) hands the keyboard
/// back to the canvas once the field has taken the value, so that Space then plays instead of
/// typing a space. A field that refused its value keeps the keyboard.
class EnterToCanvas : public QObject {
    Q_OBJECT
  public:
    /// Watches the application's events for window; canvas gets the focus.
    EnterToCanvas(QWidget* window, QWidget* canvas);
    ~EnterToCanvas() override;

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    QWidget* m_window;
    QWidget* m_canvas;
};

} // namespace chaplygin::ui
