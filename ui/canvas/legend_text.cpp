#include "canvas/legend_text.h"

#include <QFontMetrics>
#include <QFontMetricsF>

namespace chaplygin::ui {

QString fittingLegendText(const QFont& font, const QPaintDevice* device, double room,
                          std::initializer_list<QString> forms) {
    const QFontMetricsF metrics(font, device);
    QString last;
    for (const QString& form : forms) {
        if (form.isEmpty())
            continue;
        if (metrics.horizontalAdvance(form) <= room)
            return form;
        last = form;
    }
    return QFontMetrics(font, device).elidedText(last, Qt::ElideRight, int(room));
}

} // namespace chaplygin::ui
