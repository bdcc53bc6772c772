#pragma once
#include <QObject>
#include <QString>

#include <optional>
#include <vector>

class QCustomPlot;
class QLabel;
class QWidget;

namespace chaplygin::ui {

/// Hovering a time plot: a thin vertical line at the time under the mouse and a read-out of every
/// named curve's value there (the plotted curve, linear between its samples), in the curve's
/// colour; hidden when the mouse leaves the plot or its axes. Installed on a plot, owned by it.
class PlotCrosshair : public QObject {
    Q_OBJECT
  public:
    explicit PlotCrosshair(QCustomPlot* plot);

    /// One curve's value at the hovered time.
    struct Value {
        QString name;
        double value = 0;
    };
    /// The hovered time [s] and the curves' values there; nothing when not hovering.
    const std::optional<double>& time() const { return m_time; }
    const std::vector<Value>& values() const { return m_values; }
    QLabel* readout() const { return m_readout; }

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void hoverAt(QPointF pixel);
    void hide();

    QCustomPlot* m_plot;
    QWidget* m_line;
    QLabel* m_readout;
    std::optional<double> m_time;
    std::vector<Value> m_values;
};

} // namespace chaplygin::ui
