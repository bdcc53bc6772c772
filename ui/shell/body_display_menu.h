#pragma once
#include "canvas/canvas_style.h"

#include <QMenu>

class QActionGroup;

namespace chaplygin::ui {

/// View > Bodies: to scale, outline or marker; the trail width; the body's opacity. Each choice
/// emits the whole new style.
class BodyDisplayMenu : public QMenu {
    Q_OBJECT
  public:
    explicit BodyDisplayMenu(QWidget* parent = nullptr);

    /// Checks the entries of style without emitting.
    void setStyle(const CanvasStyle& style);
    const CanvasStyle& chosenStyle() const { return m_style; }
    /// The action of a display mode (tests and shortcuts).
    QAction* displayAction(BodyDisplay display) const;

  signals:
    void styleChosen(const CanvasStyle& style);

  private:
    CanvasStyle m_style;
    QActionGroup* m_display;
    QActionGroup* m_trail;
    QActionGroup* m_opacity;
};

} // namespace chaplygin::ui
