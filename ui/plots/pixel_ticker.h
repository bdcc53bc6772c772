#pragma once
// PixelTicker: an axis's tick step chosen from the axis's length in pixels and its tick labels'
// size, so that the labels never run into each other, whatever the plot's size and font.
#include <qcustomplot.h>

namespace chaplygin::ui {

/// Ticks at a readable step (1, 2, 2.5 or 5 times a power of ten) no closer than their labels
/// need: on a value axis 1.6 label heights apart, on a key axis the widest label and 1.6 digits;
/// when that leaves fewer than two ticks, 1.15 heights (digits), and on a very short axis one
/// height (digit) at a step of 1, 1.5, 2, 2.5, 3, 4, 5, 6 or 8 times a power of ten. The axis's
/// length is the one of the last layout; fitAxesAfterLayout (axis_fitting.h) lays a plot out
/// again after each layout, so the ticks are made for the final length.
class PixelTicker : public QCPAxisTicker {
  public:
    explicit PixelTicker(const QCPAxis* axis) : m_axis(axis) {}

    /// The smallest readable step at least `minimum`; fine: from the longer list of mantissas.
    static double readableStep(double minimum, bool fine = false);
    /// How many multiples of step lie in range.
    static int ticksIn(const QCPRange& range, double step);

  protected:
    double getTickStep(const QCPRange& range) override;

  private:
    double axisLength() const;
    // the pixels two neighbouring ticks need at this step
    double neededApart(double step, const QCPRange& range, double gap);
    const QCPAxis* m_axis;
};

} // namespace chaplygin::ui
