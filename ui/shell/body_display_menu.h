#pragma once
#include "canvas/canvas_style.h"

#include <QMenu>

class QActionGroup;

namespace chaplygin::ui {

/// View > Bodies: to scale, outline or marker; the trail width; the body's opacity; the side view
/// of the wheels. Each choice emits the whole new style.
class BodyDisplayMenu : public QMenu {
    Q_OBJECT
  public:
    explicit BodyDisplayMenu(QWidget* parent = nullptr);

    /// Checks the entries of style without emitting.
    void setCanvasStyle(const CanvasStyle& style);
    const CanvasStyle& chosenStyle() const { return m_style; }
    /// The action of a display mode (tests and shortcuts).
    QAction* displayAction(BodyDisplay display) const;
    /// View > Bodies > Side view of the wheels (Ctrl+Shift+4).
    QAction* wheelInsetAction() const { return m_wheelInset; }

  signals:
    void styleChosen(const CanvasStyle& style);

  private:
    CanvasStyle m_style;
    QActionGroup* m_display;
    QActionGroup* m_trail;
    QActionGroup* m_opacity;
    QAction* m_wheelInset;
};

} // namespace chaplygin::ui
