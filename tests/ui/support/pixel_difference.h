#pragma once
// Comparing pictures in the GUI tests.
#include <QRgb>

#include <algorithm>
#include <cstdlib>

namespace chaplygin::ui::test {

/// The largest difference of two pixels' red, green and blue levels (0-255).
inline int channelDifference(QRgb a, QRgb b) {
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                     std::abs(qBlue(a) - qBlue(b))});
}

} // namespace chaplygin::ui::test
