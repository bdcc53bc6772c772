// The parts of a box that a stroke's ink can reach (canvas/ink_rows): every pixel within reach
// of a segment or a mark lies in one part, the parts do not overlap and stay in the box.
#include "canvas/ink_rows.h"

#include <QRandomGenerator>
#include <QRegion>
#include <QtTest>

#include <cmath>
#include <limits>

using namespace chaplygin::ui;

namespace {

double distanceToSegment(QPointF p, QPointF a, QPointF b) {
    const QPointF d = b - a;
    const double length2 = QPointF::dotProduct(d, d);
    const double t =
        length2 > 0 ? std::clamp(QPointF::dotProduct(p - a, d) / length2, 0.0, 1.0) : 0.0;
    const QPointF q = a + t * d - p;
    return std::hypot(q.x(), q.y());
}

// whether some point of pixel (x, y) (its corners, edges' middles and centre) lies within reach
// of the segment a -> b
bool pixelWithin(int x, int y, QPointF a, QPointF b, double reach) {
    for (double u : {0.0, 0.5, 1.0})
        for (double v : {0.0, 0.5, 1.0})
            if (distanceToSegment(QPointF(x + u, y + v), a, b) <= reach)
                return true;
    return false;
}

} // namespace

class TestInkRows : public QObject {
    Q_OBJECT

  private slots:
    void everyPixelWithinReachLiesInOnePart();
    void partsStayInTheBoxAndLeaveOutRowsWithoutInk();
    void pointsThatCannotBeDrawnAreSkipped();
};

void TestInkRows::everyPixelWithinReachLiesInOnePart() {
    QRandomGenerator random(2718);
    int checked = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const QRect box(random.bounded(-50, 50), random.bounded(-50, 50), random.bounded(20, 300),
                        random.bounded(20, 300));
        // a wandering line through and around the box, and a mark
        QPolygonF line;
        QPointF at(box.left() + random.bounded(double(box.width())),
                   box.top() + random.bounded(double(box.height())));
        const int points = random.bounded(2, 60);
        for (int i = 0; i < points; ++i) {
            line << at;
            at += QPointF(random.bounded(80.0) - 40, random.bounded(80.0) - 40);
        }
        const double reach = 0.5 + random.bounded(8.0);
        const InkMark mark{QPointF(box.left() + random.bounded(double(box.width())),
                                   box.top() + random.bounded(double(box.height()))),
                           3 + random.bounded(6.0)};
        const int rows = random.bounded(4, 70);
        const std::vector<QRect> parts = inkRows(box, rows, {{&line, reach}}, {mark});
        QRegion covered;
        for (const QRect& r : parts) {
            QVERIFY2(!covered.intersects(r), "two parts overlap");
            covered += r;
        }
        for (int y = box.top(); y <= box.bottom(); ++y)
            for (int x = box.left(); x <= box.right(); ++x) {
                bool inked = pixelWithin(x, y, mark.at, mark.at, mark.reach);
                for (qsizetype i = 1; i < line.size() && !inked; ++i)
                    inked = pixelWithin(x, y, line[i - 1], line[i], reach);
                if (!inked)
                    continue;
                ++checked;
                QVERIFY2(covered.contains(QPoint(x, y)),
                         qPrintable(QStringLiteral("trial %1: pixel (%2, %3) within reach is in "
                                                   "no part")
                                        .arg(trial)
                                        .arg(x)
                                        .arg(y)));
            }
    }
    QVERIFY(checked > 10000);
}

void TestInkRows::partsStayInTheBoxAndLeaveOutRowsWithoutInk() {
    const QRect box(100, 200, 300, 256);
    // a horizontal line 2 px wide across rows 300-304: one band of 32 rows (296-327), narrowed
    // to the line's columns
    const QPolygonF line{QPointF(150, 302), QPointF(250, 302)};
    const std::vector<QRect> parts = inkRows(box, 32, {{&line, 2}}, {});
    QCOMPARE(parts.size(), std::size_t(1));
    QCOMPARE(parts[0].top(), 296);
    QCOMPARE(parts[0].height(), 32);
    QVERIFY(parts[0].left() >= 147 && parts[0].left() <= 148);
    QVERIFY(parts[0].right() >= 252 && parts[0].right() <= 253);
    // a line far outside: nothing; a line through it all: every band, each within the box
    const QPolygonF far{QPointF(-900, -900), QPointF(-800, -950)};
    QVERIFY(inkRows(box, 32, {{&far, 5}}, {}).empty());
    const QPolygonF across{QPointF(-1e6, -1e6), QPointF(1e6, 1e6)};
    const std::vector<QRect> all = inkRows(box, 32, {{&across, 5}}, {});
    QCOMPARE(all.size(), std::size_t(8));
    for (const QRect& r : all)
        QVERIFY(box.contains(r));
    QCOMPARE(all.back().bottom(), box.bottom());
}

void TestInkRows::pointsThatCannotBeDrawnAreSkipped() {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const QRect box(0, 0, 200, 200);
    // the NaN and the infinity end the segments next to them; the points between still ink
    const QPolygonF line{QPointF(nan, 5), QPointF(50, 50), QPointF(inf, 0), QPointF(150, 150),
                         QPointF(160, 150)};
    const std::vector<QRect> parts = inkRows(box, 16, {{&line, 3}}, {{QPointF(nan, nan), 5}});
    QRegion covered;
    for (const QRect& r : parts)
        covered += r;
    QVERIFY(covered.contains(QPoint(50, 50)));
    QVERIFY(covered.contains(QPoint(155, 150)));
    QVERIFY(!covered.contains(QPoint(100, 100))); // no segment through the infinity
    QVERIFY(!covered.contains(QPoint(5, 5)));
}

QTEST_MAIN(TestInkRows)
#include "test_ink_rows.moc"
