#include "shell/window_layout.h"

#include <algorithm>

namespace chaplygin::ui {

FirstStart firstStartGeometry(const QRect& available) {
    FirstStart f;
    if (available.width() <= 1366 || available.height() <= 800) {
        f.geometry = available;
        f.maximised = true;
        return f;
    }
    QSize size(available.width() * 85 / 100, available.height() * 85 / 100);
    f.geometry = QRect(QPoint(0, 0), size);
    f.geometry.moveCenter(available.center());
    return f;
}

} // namespace chaplygin::ui
