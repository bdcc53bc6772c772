#pragma once
// Help ▸ What am I looking at?: a drawing of the body with Ψ, χ and λ, and a few sentences on
// why the ghost and the vakonomic body leave the path. Shown once at the first start.
#include <QDialog>

class QCheckBox;
class QSettings;

namespace chaplygin::ui {

/// The short explanation window (not modal). Its "Don't show this at start" box is the setting
/// "help/introductionDismissed"; only a window with user settings offers it at start.
class IntroductionWindow : public QDialog {
    Q_OBJECT
  public:
    explicit IntroductionWindow(bool useSettings, QWidget* parent = nullptr);

    /// Whether a start with these settings shows the window (not dismissed yet).
    static bool dueAtStart(const QSettings& settings);
    QCheckBox* dismissBox() const { return m_dismiss; }
    /// The explanation's text (plain), for tests.
    QString text() const;

  private:
    QCheckBox* m_dismiss;
    QString m_html;
};

/// The drawing of the body: knife point P on the path, heading φ, centre of mass C, the
/// energy triangle with Ψ, the control's push λφ̇ and couple −λṡ, the ghost and the vakonomic
/// body leaving the path.
class BodyDiagram : public QWidget {
    Q_OBJECT
  public:
    explicit BodyDiagram(QWidget* parent = nullptr);
    QSize sizeHint() const override { return {460, 250}; }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override { return width * 250 / 460; }

  protected:
    void paintEvent(QPaintEvent* event) override;
};

} // namespace chaplygin::ui
