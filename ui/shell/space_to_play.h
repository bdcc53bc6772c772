#pragma once
#include <QObject>

class QAction;
class QWidget;

namespace chaplygin::ui {

/// Space toggles play wherever the focus is in the window, except in text fields (line edits,
/// text edits, editable combo boxes), where it types a space. Spin boxes, buttons, sliders and
/// tables would otherwise take Space for themselves.
class SpaceToPlay : public QObject {
    Q_OBJECT
  public:
    /// Watches the application's events for window; play is triggered.
    SpaceToPlay(QWidget* window, QAction* play);
    ~SpaceToPlay() override;

    /// Whether a Space typed into widget is text (and so does not toggle play).
    static bool isTextField(const QWidget* widget);

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    QWidget* m_window;
    QAction* m_play;
};

} // namespace chaplygin::ui
