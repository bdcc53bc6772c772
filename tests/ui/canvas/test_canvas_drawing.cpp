// GUI tests of the canvas's drawing economies that need no window: a trail stroked only where a
// frame repaints, and a layer kept within areas by a coverage mask, each against the Qt drawing
// it stands in for (docs/numerics.md §7). Offscreen, on images.
#include "canvas/halo_text.h"
#include "canvas/legend_text.h"
#include "canvas/masked_layer.h"
#include "canvas/trail_stroke.h"
#include "pixel_difference.h"

#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <QPainterPathStroker>
#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace chaplygin::ui;

namespace {

// a trail-like polyline in pixels: loops that cross themselves, a stop (one point repeated, as
// while the body pivots), a long straight run and steps far below a pixel
QPolygonF loopingLine() {
    QPolygonF line;
    for (int i = 0; i <= 1500; ++i) {
        double u = 0.01 * i;
        line << QPointF(150 + 18 * u + 60 * std::cos(3 * u), 120 + 70 * std::sin(2.2 * u));
        if (i == 700)
            for (int k = 0; k < 5; ++k)
                line << line.last();
    }
    line << QPointF(20, 230);
    for (int i = 1; i <= 50; ++i)
        line << QPointF(20 + 0.002 * i, 230 - 0.003 * i);
    return line;
}

} // namespace

class TestCanvasDrawing : public QObject {
    Q_OBJECT

  private slots:
    void trailStrokesWithinAnAreaDrawWhatDrawPolylineDraws();
    void maskedLayerDrawsWhatClipPathsDraw();
    void legendTextTakesTheLongestFormThatFits();
    void haloTextLaidOutOnceIsWhatNineDrawTextCallsDraw();
};

void TestCanvasDrawing::trailStrokesWithinAnAreaDrawWhatDrawPolylineDraws() {
    // Qt's own stroke of the whole polyline is the reference: inside the area the culled,
    // self-dashed stroke inks the same pixels (translucent ink shows a crossing inked twice).
    // The line stays on the image: where it leaves the device Qt's dasher skips ahead by whole
    // patterns only roughly, and its dashes after the return start elsewhere
    const QPolygonF line = loopingLine();
    struct Case {
        Qt::PenStyle style;
        double width;
        bool cosmetic;
        double offset;
    };
    const Case cases[] = {{Qt::SolidLine, 2, true, 0},     {Qt::DashLine, 1.5, true, 0},
                          {Qt::DashDotLine, 1.5, true, 0}, {Qt::DashLine, 3, true, 0},
                          {Qt::DashLine, 2.5, false, 1.7}, {Qt::SolidLine, 4, false, 0}};
    const QRegion areas[] = {
        QRegion(0, 0, 520, 260),                            // everything
        QRegion(300, 40, 40, 50),                           // near the loops' end
        QRegion(120, 60, 30, 120),                          // across the crossings
        QRegion(0, 0, 400, 22) + QRegion(180, 100, 60, 60), // two boxes, as a frame's
        QRegion(10, 200, 30, 40),                           // the stop and the tiny steps
    };
    int compared = 0;
    for (double zoom : {1.0, 2.0}) // 2: a display of device pixel ratio 2
        for (const Case& c : cases)
            for (const QRegion& area : areas) {
                QPen pen(QColor(30, 90, 200, 150), c.width, c.style);
                pen.setCosmetic(c.cosmetic);
                pen.setCapStyle(c.cosmetic ? Qt::RoundCap : Qt::SquareCap);
                pen.setJoinStyle(c.cosmetic ? Qt::RoundJoin : Qt::MiterJoin);
                pen.setDashOffset(c.offset);
                QImage reference(QSize(520, 260) * zoom, QImage::Format_ARGB32_Premultiplied);
                reference.fill(Qt::white);
                QImage culled = reference;
                for (QImage* image : {&reference, &culled}) {
                    QPainter p(image);
                    p.setRenderHint(QPainter::Antialiasing, true);
                    p.scale(zoom, zoom);
                    p.setClipRegion(area);
                    if (image == &reference) {
                        p.setPen(pen);
                        p.drawPolyline(line);
                    } else {
                        strokePolylineWithin(p, line, pen, area);
                    }
                }
                int inked = 0, differing = 0, most = 0;
                for (int y = 0; y < reference.height(); ++y)
                    for (int x = 0; x < reference.width(); ++x) {
                        QRgb a = reference.pixel(x, y), b = culled.pixel(x, y);
                        int d = test::channelDifference(a, b);
                        inked += a != qRgb(255, 255, 255) ? 1 : 0;
                        differing += d > 0 ? 1 : 0;
                        most = std::max(most, d);
                    }
                const QString what = QStringLiteral("zoom %1 style %2 width %3 area %4: %5 px "
                                                    "differ, by up to %6, of %7 inked")
                                         .arg(zoom)
                                         .arg(int(c.style))
                                         .arg(c.width)
                                         .arg(area.boundingRect().x())
                                         .arg(differing)
                                         .arg(most)
                                         .arg(inked);
                QVERIFY2(inked > 40, qPrintable(what));
                // the same pixels but for the rasteriser's rounding of a dash end computed
                // in another order (a level on a few pixels)
                QVERIFY2(most <= 2 && differing <= std::max(3, inked / 200), qPrintable(what));
                ++compared;
            }
    QCOMPARE(compared, 60);
}

void TestCanvasDrawing::maskedLayerDrawsWhatClipPathsDraw() {
    // the path over a body: a layer's pixels and a stroke on them, kept within a turned ellipse
    // and the ring of its outline's pen, against drawing both under a clip path of the areas'
    // union. Away from the areas' edges (1.5 px) the pixels are the same; on the edges the
    // mask's coverage and the clip's antialiasing may differ
    for (double zoom : {1.0, 2.0}) {
        QImage layer(QSize(320, 220) * zoom, QImage::Format_ARGB32_Premultiplied);
        layer.setDevicePixelRatio(zoom);
        layer.fill(Qt::transparent);
        QPolygonF band;
        for (int i = 0; i <= 200; ++i)
            band << QPointF(10 + 1.5 * i, 110 + 60 * std::sin(0.03 * i));
        {
            QPainter l(&layer);
            l.setRenderHint(QPainter::Antialiasing, true);
            QPen pen(QColor(200, 170, 160), 6);
            pen.setCosmetic(true);
            l.setPen(pen);
            l.drawPolyline(band);
            l.setBrush(QColor(40, 40, 40));
            l.drawEllipse(QPointF(160, 100), 4, 4);
        }
        QTransform pose;
        pose.translate(170, 105);
        pose.rotate(27);
        QPainterPath body;
        body.addEllipse(QPointF(0, 0), 60, 35);
        body.moveTo(0, 0);
        body.arcTo(QRectF(-30, -30, 60, 60), 10, 120);
        body = pose.map(body);
        const QPainterPath& shape = body;
        QPainterPathStroker stroker;
        stroker.setWidth(5);
        const QPainterPath ring = stroker.createStroke(body);
        QPolygonF trail;
        for (int i = 0; i <= 120; ++i)
            trail << QPointF(60 + 2 * i, 112 + 55 * std::sin(0.05 * i + 0.3));
        QPen trailPen(QColor(20, 60, 140), 2.5);
        trailPen.setCosmetic(true);
        auto over = [&](QPainter& c) {
            c.setPen(trailPen);
            c.drawPolyline(trail);
        };
        const QRect box = body.boundingRect().united(ring.boundingRect()).toAlignedRect();
        QImage reference(QSize(320, 220) * zoom, QImage::Format_RGB32);
        reference.setDevicePixelRatio(zoom);
        reference.fill(QColor(120, 200, 230)); // the body's fill under the path
        QImage masked = reference;
        {
            QPainter p(&reference);
            p.setRenderHint(QPainter::Antialiasing, true);
            // one clip, the areas' union: under a clip per area the edges of what is drawn
            // where the areas overlap would be inked twice
            p.setClipPath(shape.united(ring));
            p.drawImage(QPointF(0, 0), layer);
            over(p);
        }
        {
            QPainter p(&masked);
            p.setRenderHint(QPainter::Antialiasing, true);
            drawMaskedLayer(p, layer, QPoint(0, 0), box, {&body, &ring}, over);
        }
        // a pixel (in the painter's coordinates) away from every edge: the 8 points 1.5 px
        // around its middle lie on the same side of both areas as the middle
        auto awayFromEdges = [&](QPointF c) {
            for (const QPainterPath* area : {&shape, &ring}) {
                const bool in = area->contains(c);
                for (int k = 0; k < 8; ++k)
                    if (area->contains(c + 1.5 * QPointF(std::cos(k * M_PI / 4),
                                                         std::sin(k * M_PI / 4))) != in)
                        return false;
            }
            return true;
        };
        int inside = 0, edge = 0, edgeDiffering = 0, most = 0;
        for (int y = 0; y < reference.height(); ++y)
            for (int x = 0; x < reference.width(); ++x) {
                const QRgb a = reference.pixel(x, y), b = masked.pixel(x, y);
                const int d = test::channelDifference(a, b);
                const QPointF c = QPointF(x + 0.5, y + 0.5) / zoom;
                if (awayFromEdges(c)) {
                    QVERIFY2(d <= 2, qPrintable(QStringLiteral("zoom %1: pixel (%2, %3) away from "
                                                               "the edges differs by %4")
                                                    .arg(zoom)
                                                    .arg(x)
                                                    .arg(y)
                                                    .arg(d)));
                    inside += body.contains(c) || ring.contains(c) ? 1 : 0;
                } else {
                    ++edge;
                    edgeDiffering += d > 24 ? 1 : 0;
                    most = std::max(most, d);
                }
            }
        const QString what = QStringLiteral("zoom %1: %2 px inside, %3 on the edges, %4 of them "
                                            "differ by more than 24 levels, at most %5")
                                 .arg(zoom)
                                 .arg(inside)
                                 .arg(edge)
                                 .arg(edgeDiffering)
                                 .arg(most);
        qInfo().noquote() << what;
        QVERIFY2(inside > 2000 * zoom * zoom, qPrintable(what));
        QVERIFY2(edge > 1000 * zoom && edgeDiffering == 0, qPrintable(what));
    }
}

void TestCanvasDrawing::legendTextTakesTheLongestFormThatFits() {
    // a legend entry in a room measured here: the full text, its brief form or its shortest,
    // each whole when it fits, the shortest elided when none does (a narrow canvas presenting)
    QImage device(800, 40, QImage::Format_ARGB32_Premultiplied);
    QFont font;
    font.setPointSizeF(18);
    const QFontMetricsF metrics(font, &device);
    const QString full = QStringLiteral("corpo controlado e seu rastro (segue o caminho)");
    const QString brief = QStringLiteral("corpo controlado (segue o caminho)");
    const QString shortest = QStringLiteral("corpo controlado");
    const double wFull = metrics.horizontalAdvance(full), wBrief = metrics.horizontalAdvance(brief),
                 wShortest = metrics.horizontalAdvance(shortest);
    QVERIFY(wShortest < wBrief && wBrief < wFull);
    QCOMPARE(fittingLegendText(font, &device, wFull, {full, brief, shortest}), full);
    QCOMPARE(fittingLegendText(font, &device, wFull - 1, {full, brief, shortest}), brief);
    QCOMPARE(fittingLegendText(font, &device, wBrief - 1, {full, brief, shortest}), shortest);
    QCOMPARE(fittingLegendText(font, &device, wShortest, {full, brief, shortest}), shortest);
    // no room for the shortest: it is elided, never a longer form
    const QString elided =
        fittingLegendText(font, &device, wShortest - 10, {full, brief, shortest});
    QVERIFY2(elided.endsWith(QChar(0x2026)) && elided.size() < shortest.size(), qPrintable(elided));
    // an entry without a shortest form keeps its brief one
    QCOMPARE(fittingLegendText(font, &device, wBrief - 1, {full, brief, QString()}),
             QFontMetrics(font, &device).elidedText(brief, Qt::ElideRight, int(wBrief - 1)));
}

void TestCanvasDrawing::haloTextLaidOutOnceIsWhatNineDrawTextCallsDraw() {
    // the reference: the halo as QPainter::drawText draws it, nine times at the offsets
    auto reference = [](QPainter& p, const QRectF& box, int flags, const QString& text,
                        double width) {
        p.setPen(QColor(255, 255, 255, 220));
        for (QPointF d : {QPointF(-1, 0), QPointF(1, 0), QPointF(0, -1), QPointF(0, 1),
                          QPointF(-1, -1), QPointF(1, 1), QPointF(-1, 1), QPointF(1, -1)})
            p.drawText(box.translated(d * width), flags, text);
        p.setPen(Qt::black);
        p.drawText(box, flags, text);
    };
    const QString texts[] = {
        QStringLiteral("t = 12.34 s of 20.00 s    scale 57.3 px/m"),
        QStringLiteral("t = 0.00 s de 20.00 s    escala 1.2e+03 px/m    curvas desenhadas em "
                       "parte neste zoom"),
        QStringLiteral("t = 3.50 s   "), // trailing spaces
    };
    int compared = 0;
    for (double dpr : {1.0, 2.0})
        for (int flags : {int(Qt::AlignLeft), int(Qt::AlignLeft | Qt::AlignVCenter)})
            for (double points : {9.0, 13.5, 36.0})
                for (const QString& text : texts)
                    for (const QRectF& box : {QRectF(8, 6, 700, 28), QRectF(10.5, 0, 300, 61.25)}) {
                        QImage image[2];
                        for (int k = 0; k < 2; ++k) {
                            image[k] =
                                QImage(QSize(760, 80) * dpr, QImage::Format_ARGB32_Premultiplied);
                            image[k].setDevicePixelRatio(dpr);
                            image[k].fill(QColor(90, 160, 230));
                            QPainter p(&image[k]);
                            p.setRenderHint(QPainter::Antialiasing, true);
                            QFont f = p.font();
                            f.setPointSizeF(points);
                            f.setBold(points > 30);
                            p.setFont(f);
                            const double halo = points > 30 ? 2 : 1;
                            if (k == 0)
                                reference(p, box, flags, text, halo);
                            else
                                drawHaloText(p, box, flags, text, halo);
                        }
                        int differing = 0;
                        QRect where;
                        for (int y = 0; y < image[0].height(); ++y)
                            for (int x = 0; x < image[0].width(); ++x)
                                if (image[0].pixel(x, y) != image[1].pixel(x, y)) {
                                    ++differing;
                                    where |= QRect(x, y, 1, 1);
                                }
                        QVERIFY2(differing == 0,
                                 qPrintable(QStringLiteral("ratio %1, flags %2, %3 pt, box at "
                                                           "%4, \"%5\": %6 pixels differ in "
                                                           "(%7, %8) %9 x %10")
                                                .arg(dpr)
                                                .arg(flags)
                                                .arg(points)
                                                .arg(box.x())
                                                .arg(text)
                                                .arg(differing)
                                                .arg(where.x())
                                                .arg(where.y())
                                                .arg(where.width())
                                                .arg(where.height())));
                        ++compared;
                    }
    QCOMPARE(compared, 72);
}

QTEST_MAIN(TestCanvasDrawing)
#include "test_canvas_drawing.moc"
