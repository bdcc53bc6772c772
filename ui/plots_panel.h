#pragma once
#include "plot_figures.h"

#include <QWidget>

#include <array>

class QCustomPlot;
class QCPItemStraightLine;

namespace chaplygin::ui {

class SceneDocument;

/// The plots dock: Psi, chi, lambda and the kinetic energy against t, each drawn by drawPlot
/// (so they look like the exported plots) with the free motion alongside, and a time cursor
/// on its own buffered layer so that moving it repaints only that layer. Clicking seeks.
class PlotsPanel : public QWidget {
    Q_OBJECT
public:
    static constexpr std::array<PlotKind, 4> kKinds{PlotKind::Psi, PlotKind::Chi, PlotKind::Lambda,
                                                    PlotKind::Energy};

    explicit PlotsPanel(SceneDocument* document, QWidget* parent = nullptr);

    QCustomPlot* plot(int index) const { return m_plots[index]; }
    double cursorTime() const { return m_time; }

public slots:
    /// Hands the document's series to the plots (after each recompute).
    void refresh();
    void setTime(double t);
    /// Repaints every plot now (for screenshots and the benchmark).
    void replotNow();

signals:
    void seekRequested(double t);

private:
    void placeCursor(int index);

    SceneDocument* m_document;
    std::array<QCustomPlot*, 4> m_plots{};
    std::array<QCPItemStraightLine*, 4> m_cursors{};
    double m_time = 0;
};

} // namespace chaplygin::ui
