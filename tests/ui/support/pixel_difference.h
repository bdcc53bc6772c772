#pragma once
// Comparing pictures in the GUI tests.
#include <QImage>
#include <QRgb>

#include <algorithm>
#include <cstdlib>

namespace chaplygin::ui::test {

/// The largest difference of two pixels' red, green and blue levels (0-255).
inline int channelDifference(QRgb a, QRgb b) {
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                     std::abs(qBlue(a) - qBlue(b))});
}

/// How two pictures of one size differ: the pixels whose levels differ, and by how much at most.
struct PictureDifference {
    int differing = 0, largest = 0;
};
inline PictureDifference pictureDifference(const QImage& a, const QImage& b) {
    PictureDifference d;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const int level = channelDifference(a.pixel(x, y), b.pixel(x, y));
            d.largest = std::max(d.largest, level);
            d.differing += level > 0 ? 1 : 0;
        }
    return d;
}

} // namespace chaplygin::ui::test
