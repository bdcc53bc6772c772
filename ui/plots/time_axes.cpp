#include "plots/time_axes.h"

#include "plots/plot_figures.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace chaplygin::ui {

namespace {

const char* const kRole = "chaplyginControlled";
const char* const kClipName = "chaplyginClipName";
const char* const kFitAll = "chaplyginFitAll";
const char* const kMark = "chaplyginClipMark";

struct Extent {
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
    void add(double v) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    bool empty() const { return !(lo <= hi); }
};

QList<QCPGraph*> graphsOf(QCPAxisRect& rect) {
    QList<QCPGraph*> graphs;
    for (QCPAbstractPlottable* p : rect.plottables())
        if (auto* g = qobject_cast<QCPGraph*>(p))
            graphs << g;
    return graphs;
}

// the controlled curves' padded range, widened by the others within the allowed factor
QCPRange valueRange(const Extent& controlled, const Extent& all) {
    const QCPRange everything = paddedRange(all.lo, all.hi);
    if (controlled.empty())
        return everything;
    const QCPRange base = paddedRange(controlled.lo, controlled.hi);
    const bool flat = controlled.hi - controlled.lo < 0.5 * base.size();
    double below, above;
    if (flat) {
        const double c = 0.5 * (controlled.lo + controlled.hi);
        const double reach = kFlatFactor * std::max(std::abs(c), 0.5 * base.size());
        below = c - reach;
        above = c + reach;
    } else {
        below = base.lower - kWidenFraction * base.size();
        above = base.upper + kWidenFraction * base.size();
    }
    return QCPRange(std::min(base.lower, std::max(everything.lower, below)),
                    std::max(base.upper, std::min(everything.upper, above)));
}

// "↑ free" from the exit to the right, or "free ↑" to the left of it
void alignMark(QCPItemText& mark, bool left) {
    const QString name = mark.property("chaplyginName").toString();
    const QString arrow = mark.property("chaplyginArrow").toString();
    const Qt::Alignment edge = mark.positionAlignment() & Qt::AlignVertical_Mask
                                   ? mark.positionAlignment() & Qt::AlignVertical_Mask
                                   : Qt::Alignment(Qt::AlignTop);
    mark.setPositionAlignment(edge | (left ? Qt::AlignRight : Qt::AlignLeft));
    mark.setText(left ? name + QLatin1Char(' ') + arrow : arrow + QLatin1Char(' ') + name);
}

void removeMarks(QCPAxisRect& rect) {
    QCustomPlot* plot = rect.parentPlot();
    for (int i = plot->itemCount() - 1; i >= 0; --i) {
        QCPAbstractItem* item = plot->item(i);
        if (item->property(kMark).toBool() && item->clipAxisRect() == &rect)
            plot->removeItem(item);
    }
}

// "↑ free" where the curve first leaves through the top, "↓ free" through the bottom
using Marks = QList<QPair<double, QCPItemText*>>;

void addMarks(QCPAxisRect& rect, QCPGraph& g, const QCPRange& range, const QCPRange& time,
              Marks* topMarks, Marks* bottomMarks) {
    const QString name = g.property(kClipName).toString();
    if (name.isEmpty())
        return;
    QCPAxis* key = rect.axis(QCPAxis::atBottom);
    QCPAxis* value = rect.axis(QCPAxis::atLeft);
    bool doneTop = false, doneBottom = false;
    double lastKey = NAN, lastValue = NAN;
    for (const QCPGraphData& d : *g.data()) {
        if (!std::isfinite(d.key) || !std::isfinite(d.value)) {
            lastKey = lastValue = NAN;
            continue;
        }
        if (d.key < time.lower) { // before the time shown
            lastKey = d.key;
            lastValue = d.value;
            continue;
        }
        const bool top = d.value > range.upper, bottom = d.value < range.lower;
        if ((top && !doneTop) || (bottom && !doneBottom)) {
            const double edge = top ? range.upper : range.lower;
            // where the line crosses the edge, or the first point when it starts outside (the
            // left edge of the time shown when it was outside before it)
            double at = d.key;
            if (std::isfinite(lastValue) && range.contains(lastValue))
                at = lastKey + (d.key - lastKey) * (edge - lastValue) / (d.value - lastValue);
            else if (std::isfinite(lastKey) && lastKey < time.lower)
                at = time.lower;
            at = std::max(at, time.lower);
            if (at > time.upper)
                break;
            Marks& marks = top ? *topMarks : *bottomMarks;
            // a mark near another on the same edge goes under (over) it
            QCPItemText* near = nullptr;
            for (const auto& [k, other] : marks)
                if (std::abs(k - at) < 0.3 * key->range().size())
                    near = other;
            const bool right = at > key->range().lower + 0.7 * key->range().size();
            const QString arrow = top ? QStringLiteral("\u2191") : QStringLiteral("\u2193");
            auto* mark = new QCPItemText(rect.parentPlot());
            marks << qMakePair(at, mark);
            mark->setProperty(kMark, true);
            mark->setProperty("chaplyginExit", at);
            mark->setProperty("chaplyginName", name);
            mark->setProperty("chaplyginArrow", arrow);
            mark->setClipAxisRect(&rect);
            mark->setClipToAxisRect(true);
            mark->position->setAxes(key, value);
            mark->position->setAxisRect(&rect);
            mark->position->setTypeX(QCPItemPosition::ptPlotCoords);
            if (near) {
                mark->position->setParentAnchorY(top ? near->bottom : near->top);
                mark->position->setTypeY(QCPItemPosition::ptAbsolute);
                mark->position->setCoords(at, 0);
            } else {
                mark->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
                mark->position->setCoords(at, top ? 0 : 1);
            }
            QFont font = rect.parentPlot()->font();
            font.setPointSizeF(std::max(7.0, 0.85 * font.pointSizeF()));
            mark->setPositionAlignment(top ? Qt::AlignTop : Qt::AlignBottom);
            alignMark(*mark, right);
            mark->setFont(font);
            mark->setColor(g.pen().color());
            mark->setBrush(QColor(255, 255, 255, 215));
            mark->setPadding(QMargins(2, 0, 2, 0));
            if (top)
                doneTop = true;
            else
                doneBottom = true;
        }
        lastKey = d.key;
        lastValue = d.value;
        if (d.key > time.upper)
            break;
    }
}

// the finite values of g at the times of `time`: its points inside and the line at its edges
void addVisible(const QCPGraph& g, const QCPRange& time, Extent& values) {
    const QCPGraphData* last = nullptr;
    const auto end = g.data()->findEnd(time.upper);
    for (auto it = g.data()->findBegin(time.lower); it != end; ++it) {
        if (!std::isfinite(it->key) || !std::isfinite(it->value)) {
            last = nullptr;
            continue;
        }
        if (time.contains(it->key))
            values.add(it->value);
        if (last)
            for (double edge : {time.lower, time.upper})
                if (last->key < edge && edge < it->key)
                    values.add(last->value + (it->value - last->value) * (edge - last->key) /
                                                 (it->key - last->key));
        last = &*it;
    }
}

// the value axis and the clip marks for the extents of the curves
void fitValues(QCPAxisRect& rect, const QList<QCPGraph*>& graphs, const Extent& controlled,
               const Extent& all, const QCPRange& time) {
    const bool everything = fitAllCurves(*rect.parentPlot());
    const QCPRange range = everything ? paddedRange(all.lo, all.hi) : valueRange(controlled, all);
    rect.axis(QCPAxis::atLeft)->setRange(range);
    if (everything)
        return;
    Marks top, bottom;
    for (QCPGraph* g : graphs)
        if (!g->property(kRole).toBool())
            addMarks(rect, *g, range, time, &top, &bottom);
}

} // namespace

void setControlled(QCPGraph& graph) {
    graph.setProperty(kRole, true);
}

void setClipped(QCPGraph& graph, const QString& clipName) {
    graph.setProperty(kRole, false);
    graph.setProperty(kClipName, clipName);
}

bool fitAllCurves(const QCustomPlot& plot) {
    return plot.property(kFitAll).toBool();
}

void setFitAllCurves(QCustomPlot& plot, bool on) {
    plot.setProperty(kFitAll, on);
    for (QCPAxisRect* rect : plot.axisRects())
        fitTimeAxes(*rect);
}

void fitTimeAxes(QCPAxisRect& rect) {
    removeMarks(rect);
    Extent keys, controlled, all;
    const QList<QCPGraph*> graphs = graphsOf(rect);
    for (QCPGraph* g : graphs) {
        const bool isControlled = g->property(kRole).toBool();
        for (const QCPGraphData& d : *g->data()) {
            if (!std::isfinite(d.key) || !std::isfinite(d.value))
                continue;
            keys.add(d.key);
            all.add(d.value);
            if (isControlled)
                controlled.add(d.value);
        }
    }
    rect.axis(QCPAxis::atBottom)->setRange(paddedRange(keys.lo, keys.hi));
    const double inf = std::numeric_limits<double>::infinity();
    fitValues(rect, graphs, controlled, all, QCPRange(-inf, inf));
}

void fitTimeAxes(QCPAxisRect& rect, const QCPRange& time) {
    removeMarks(rect);
    Extent controlled, all;
    const QList<QCPGraph*> graphs = graphsOf(rect);
    for (QCPGraph* g : graphs) {
        Extent values;
        addVisible(*g, time, values);
        if (values.empty())
            continue;
        all.add(values.lo);
        all.add(values.hi);
        if (g->property(kRole).toBool()) {
            controlled.add(values.lo);
            controlled.add(values.hi);
        }
    }
    rect.axis(QCPAxis::atBottom)->setRange(time);
    fitValues(rect, graphs, controlled, all, time);
}

void placeClipMarks(QCPAxisRect& rect) {
    QCustomPlot* plot = rect.parentPlot();
    QCPAxis* key = rect.axis(QCPAxis::atBottom);
    for (int i = 0; i < plot->itemCount(); ++i) {
        auto* mark = qobject_cast<QCPItemText*>(plot->item(i));
        if (!mark || !mark->property(kMark).toBool() || mark->clipAxisRect() != &rect)
            continue;
        const double exit = mark->property("chaplyginExit").toDouble();
        const double x = key->coordToPixel(exit);
        alignMark(*mark, false);
        const double width = QFontMetricsF(mark->font()).horizontalAdvance(mark->text()) +
                             mark->padding().left() + mark->padding().right();
        // to the right of the exit if it fits, else to its left, else against the frame
        double at = x;
        if (x + width > rect.right()) {
            if (x - width >= rect.left()) {
                alignMark(*mark, true);
            } else if (width <= rect.width()) {
                at = rect.left();
            } else {
                // a frame narrower than the name: the arrow alone, in the curve's colour
                mark->setText(mark->property("chaplyginArrow").toString());
                mark->setPositionAlignment((mark->positionAlignment() & Qt::AlignVertical_Mask) |
                                           Qt::AlignHCenter);
                at = std::clamp(x, rect.left() + 8.0, rect.right() - 8.0);
            }
        }
        mark->position->setCoords(key->pixelToCoord(at), mark->position->coords().y());
    }
}

QStringList clipMarks(QCPAxisRect& rect) {
    QStringList texts;
    QCustomPlot* plot = rect.parentPlot();
    for (int i = 0; i < plot->itemCount(); ++i)
        if (auto* text = qobject_cast<QCPItemText*>(plot->item(i)))
            if (text->property(kMark).toBool() && text->clipAxisRect() == &rect)
                texts << text->text();
    return texts;
}

} // namespace chaplygin::ui
