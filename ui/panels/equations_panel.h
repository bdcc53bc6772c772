#pragma once
#include <QWidget>

class QTextBrowser;

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
    SceneDocument* m_document;
    QTextBrowser* m_view;
    double m_time = 0;
    bool m_stale = true;
    double m_basePoints = 0;
    QString m_html;
};

} // namespace chaplygin::ui
