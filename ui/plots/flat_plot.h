#pragma once
#include <QImage>

#include <qcustomplot.h>

namespace chaplygin::ui {

/// A QCustomPlot that repaints from one opaque image: its background and its layers' buffers
/// composited once per replot, as QCustomPlot's own paint composites them on every repaint.
/// A repaint (a moved time cursor uncovers two strips; a plot shown again) then copies rows
/// rectangle by rectangle, where the plain widget blends each translucent buffer under the
/// repainted region and Qt hands those spans to its thread pool. Only for an opaque
/// background brush and no background pixmap; otherwise it paints as QCustomPlot does.
class FlatPlot : public QCustomPlot {
  public:
    explicit FlatPlot(QWidget* parent = nullptr);

    /// Off: paints as QCustomPlot does (the reference of the tests).
    void setFlattened(bool on) {
        m_flattened = on;
        update();
    }

  protected:
    void paintEvent(QPaintEvent* event) override;

  private:
    QImage m_flat;
    bool m_stale = true;
    bool m_flattened = true;
};

} // namespace chaplygin::ui
