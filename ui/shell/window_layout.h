#pragma once
#include <QRect>

namespace chaplygin::ui {

/// The window's first start on a screen with the given available geometry: 85 % of it,
/// centred; a screen of at most 1366 x 800 (a laptop, a projector) is used whole (maximised).
struct FirstStart {
    QRect geometry;
    bool maximised = false;
};
FirstStart firstStartGeometry(const QRect& available);

} // namespace chaplygin::ui
