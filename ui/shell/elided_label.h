#pragma once
#include <QLabel>

namespace chaplygin::ui {

/// A one-line label that elides its text to its width ("…") and shows the whole text as its
/// tooltip; for the status bar, which must never cut text silently.
class ElidedLabel : public QLabel {
    Q_OBJECT
  public:
    explicit ElidedLabel(QWidget* parent = nullptr);

    void setFullText(const QString& text);
    const QString& fullText() const { return m_full; }
    QSize minimumSizeHint() const override;

  protected:
    void resizeEvent(QResizeEvent* e) override;

  private:
    void elide();
    QString m_full;
};

} // namespace chaplygin::ui
