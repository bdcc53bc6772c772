#include "plots/pixel_ticker.h"

#include <QFontMetricsF>

#include <algorithm>
#include <cmath>
#include <span>

namespace chaplygin::ui {

double PixelTicker::readableStep(double minimum, bool fine) {
    if (!(minimum > 0) || !std::isfinite(minimum))
        return 1;
    const double magnitude = std::pow(10.0, std::floor(std::log10(minimum)));
    static constexpr double kCoarse[] = {1, 2, 2.5, 5, 10};
    static constexpr double kFine[] = {1, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10};
    for (double mantissa : fine ? std::span<const double>(kFine) : std::span<const double>(kCoarse))
        if (mantissa * magnitude >= minimum * (1 - 1e-12))
            return mantissa * magnitude;
    return 10 * magnitude;
}

int PixelTicker::ticksIn(const QCPRange& range, double step) {
    const double first = std::ceil(range.lower / step - 1e-9);
    const double last = std::floor(range.upper / step + 1e-9);
    return last >= first ? static_cast<int>(std::min(last - first + 1, 1e6)) : 0;
}

double PixelTicker::axisLength() const {
    const QCPAxisRect* rect = m_axis->axisRect();
    const bool vertical = m_axis->orientation() == Qt::Vertical;
    const int laidOut = vertical ? rect->height() : rect->width();
    if (laidOut > 1)
        return laidOut;
    // not laid out yet: a guess from the plot's size (the second layout corrects it)
    const QCustomPlot* plot = m_axis->parentPlot();
    return 0.6 * (vertical ? plot->height() : plot->width());
}

double PixelTicker::neededApart(double step, const QCPRange& range, double gap) {
    const QFontMetricsF metrics(m_axis->tickLabelFont());
    if (m_axis->orientation() == Qt::Vertical)
        return gap * metrics.height();
    // a key axis: the widest of the labels drawn at this step, and a gap of 1.6 digits (1.15,
    // 1 when tighter)
    const QLocale locale = m_axis->parentPlot()->locale();
    const QChar format =
        m_axis->numberFormat().isEmpty() ? QLatin1Char('g') : m_axis->numberFormat().at(0);
    double widest = 0;
    if (!(step > 0)) // no step yet: a lower bound, a one-digit label
        return 3 * metrics.horizontalAdvance(QLatin1Char('0'));
    const double first = std::ceil(range.lower / step - 1e-9);
    const int count = std::min(ticksIn(range, step), 200);
    for (int i = 0; i < count; ++i) {
        const QString label =
            getTickLabel((first + i) * step, locale, format, m_axis->numberPrecision());
        widest = std::max(widest, metrics.horizontalAdvance(label));
    }
    return widest + gap * metrics.horizontalAdvance(QLatin1Char('0'));
}

double PixelTicker::getTickStep(const QCPRange& range) {
    const double length = axisLength();
    const double size = range.size();
    if (!(length > 1) || !(size > 0) || !std::isfinite(size))
        return QCPAxisTicker::getTickStep(range);
    auto stepFor = [&](double gap, bool fine) {
        // the step grows until its ticks are as far apart as their labels need (on a key axis
        // the labels' width depends on the step)
        double step = readableStep(size * neededApart(0, range, gap) / length, fine);
        for (int i = 0; i < 12 && step * length / size < neededApart(step, range, gap); ++i)
            step = readableStep(step * 1.0001, fine);
        return step;
    };
    // comfortable, else tight, else the finer steps, until two ticks are shown
    double step = 0;
    for (auto [gap, fine] : {std::pair{1.6, false}, {1.15, false}, {1.0, true}})
        if (step = stepFor(gap, fine); ticksIn(range, step) >= 2)
            break;
    return step;
}

} // namespace chaplygin::ui
