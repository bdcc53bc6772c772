#pragma once
#include "planning/pose_planner.h"
#include "scene/scene.h"

#include <QWidget>

#include <memory>
#include <optional>

class QTextBrowser;

namespace chaplygin {
class Solution;
}

namespace chaplygin::ui {

class SceneDocument;

/// The Equations dock: the formulas in use at the current time with the live values
/// substituted (equationsHtml), following the time, the system and the mode.
class EquationsPanel : public QWidget {
    Q_OBJECT
  public:
    explicit EquationsPanel(SceneDocument* document, QWidget* parent = nullptr);

    double time() const { return m_time; }
    QTextBrowser* view() const { return m_view; }
    /// The page as shown (rebuilt now if it was skipped while hidden or in a background tab).
    QString html();
    /// Enlarges the text (presentation mode): 1 is the normal size.
    void setFontScale(double scale);

  public slots:
    void setTime(double t);
    void refresh();

  protected:
    void showEvent(QShowEvent* e) override;

  private:
    /// The chosen motion of the scene's plan (docs/physics.md §10), empty without one.
    QString planSection(const Solution& solution);
    SceneDocument* m_document;
    QTextBrowser* m_view;
    double m_time = 0;
    bool m_stale = true;
    double m_basePoints = 0;
    QString m_html;
    std::optional<ScenePlan> m_planOf; // the plan m_planned was made for
    std::shared_ptr<const Solution> m_plannedFor;
    PlanRequest m_request;
    Plan m_planned;
};

} // namespace chaplygin::ui
