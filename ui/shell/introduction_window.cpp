#include "shell/introduction_window.h"

#include "document/math_text.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QTextDocument>
#include <QVBoxLayout>

#include <cmath>

namespace chaplygin::ui {

namespace {

const char* const kDismissedKey = "help/introductionDismissed";
constexpr double kPi = 3.14159265358979323846;

// the diagram's own units: it is drawn in a 460 x 250 box, scaled to the widget
constexpr double kWidth = 460, kHeight = 250;

void arrowHead(QPainter& p, QPointF tip, double angle) {
    const double size = 8;
    QPolygonF head;
    head << tip << tip - size * QPointF(std::cos(angle - 0.4), std::sin(angle - 0.4))
         << tip - size * QPointF(std::cos(angle + 0.4), std::sin(angle + 0.4));
    p.drawPolygon(head);
}

void arrow(QPainter& p, QPointF from, QPointF to) {
    p.drawLine(from, to);
    const QPointF d = to - from;
    QBrush brush = p.brush();
    p.setBrush(p.pen().color());
    arrowHead(p, to, std::atan2(d.y(), d.x()));
    p.setBrush(brush);
}

// a board along the heading, the knife at P, seen from above
QPolygonF board(QPointF knife, double heading, double back, double ahead, double half) {
    const QPointF s(std::cos(heading), std::sin(heading)), n(-s.y(), s.x());
    QPolygonF shape;
    shape << knife - back * s - half * n << knife + ahead * s - half * n
          << knife + ahead * s + half * n << knife - back * s + half * n;
    return shape;
}

} // namespace

BodyDiagram::BodyDiagram(QWidget* parent) : QWidget(parent) {
    setMinimumSize(320, 174);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
    setAccessibleName(tr("Drawing of the body on its path with the angles Ψ, φ and χ"));
}

void BodyDiagram::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().base());
    const double scale = std::min(width() / kWidth, height() / kHeight);
    p.translate((width() - scale * kWidth) / 2, (height() - scale * kHeight) / 2);
    p.scale(scale, scale);
    QFont font = p.font();
    font.setPixelSize(13);
    p.setFont(font);
    QFont symbols = dottedSymbolFont(font); // the labels with a dot above
    symbols.setPixelSize(15);
    const QColor ink = palette().text().color();

    // the path (screen y points down: the path rises to the right, turning left)
    QPainterPath path(QPointF(15, 215));
    path.cubicTo(QPointF(120, 215), QPointF(230, 180), QPointF(330, 95));
    path.cubicTo(QPointF(370, 60), QPointF(400, 40), QPointF(445, 25));
    p.setPen(QPen(QColor(120, 160, 220, 150), 12, Qt::SolidLine, Qt::RoundCap));
    p.drawPath(path);
    p.setPen(QPen(QColor(40, 80, 160), 1.5));
    p.drawPath(path);
    p.drawText(QPointF(20, 240), tr("path"));

    const double at = 0.36;
    const QPointF knife = path.pointAtPercent(at);
    const double heading = -path.angleAtPercent(at) * kPi / 180; // Qt's angle is counter-clockwise
    const QPointF s(std::cos(heading), std::sin(heading));

    // the ghost: the same body without control, carried straight on by its momentum
    const QPointF ghostAt = knife + 150 * s + QPointF(0, 18);
    p.setPen(QPen(QColor(200, 40, 40), 1.5, Qt::DashLine));
    p.drawLine(knife, ghostAt);
    p.setBrush(QColor(200, 40, 40, 50));
    p.drawPolygon(board(ghostAt, heading + 0.12, 18, 50, 12));
    p.setPen(QColor(170, 30, 30));
    p.drawText(ghostAt + QPointF(-20, 36), tr("ghost: no control"));
    // the vakonomic body: its multiplier obeys its own equation, and it turns away
    QPainterPath vak(knife);
    vak.cubicTo(knife + 60 * s, knife + 110 * s + QPointF(-30, -40), knife + QPointF(20, -140));
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(QColor(120, 60, 160), 1.5, Qt::DashDotLine));
    p.drawPath(vak);
    p.setPen(QColor(110, 50, 150));
    p.drawText(knife + QPointF(30, -136), tr("vakonomic body"));

    // the body: knife at P, centre of mass C ahead of it at distance a
    p.setPen(QPen(ink, 1.5));
    p.setBrush(QColor(230, 230, 230, 220));
    p.drawPolygon(board(knife, heading, 20, 60, 15));
    p.setPen(QPen(ink, 4, Qt::SolidLine, Qt::RoundCap));
    p.drawLine(knife - 9 * s, knife + 9 * s); // the knife edge
    const QPointF centre = knife + 34 * s;
    p.setPen(QPen(ink, 1));
    p.setBrush(ink);
    p.drawEllipse(centre, 3.5, 3.5);
    p.drawEllipse(knife, 2.5, 2.5);
    p.setBrush(Qt::NoBrush);
    p.drawText(knife + QPointF(-8, 28), QStringLiteral("P"));
    p.drawText(centre + QPointF(-4, -10), QStringLiteral("C"));

    // the heading φ from the x direction, and the speed ṡ along it
    p.setPen(QPen(ink, 1, Qt::DotLine));
    p.drawLine(knife, knife + QPointF(110, 0));
    p.setPen(QPen(ink, 1));
    const double phiDeg = -heading * 180 / kPi;
    p.drawArc(QRectF(knife - QPointF(95, 95), QSizeF(190, 190)), 0, int(phiDeg * 16));
    p.drawText(knife + QPointF(98, -10), QStringLiteral("\u03c6"));
    p.setPen(QPen(QColor(0, 110, 60), 2));
    arrow(p, knife + 62 * s, knife + 110 * s);
    p.drawText(knife + 112 * s + QPointF(4, 4), QStringLiteral("\u1e61"));
    // the control turns χ = Ψ − (a/b)φ at the rate λ/(m b): a push λφ̇ and a couple −λṡ
    p.setPen(QPen(QColor(200, 110, 0), 2));
    QRectF turn(centre - QPointF(26, 26), QSizeF(52, 52));
    p.drawArc(turn, int((phiDeg + 110) * 16), 150 * 16);
    const double end = (phiDeg + 260) * kPi / 180;
    arrowHead(p, centre + 26 * QPointF(std::cos(end), -std::sin(end)), -end - kPi / 2);
    p.drawText(centre + QPointF(-120, 50), tr("control: \u03c7 = \u03a8 \u2212 (a/b)\u03c6,"));
    p.setFont(symbols);
    p.drawText(centre + QPointF(-120, 68), QStringLiteral("\u03bb = m b \u03c7\u0307"));
    p.setFont(font);

    // the energy triangle: ṡ = v_T sin Ψ, bφ̇ = v_T cos Ψ
    const QPointF o(25, 160); // the upper left corner, clear of the path and the bodies
    const double w = 110, h = 70;
    p.setPen(QPen(ink, 1.5));
    p.drawLine(o, o + QPointF(w, 0));
    p.drawLine(o + QPointF(w, 0), o + QPointF(w, -h));
    p.setPen(QPen(QColor(0, 110, 60), 2));
    p.drawLine(o, o + QPointF(w, -h));
    p.setPen(QPen(ink, 1));
    const double psiDeg = std::atan2(h, w) * 180 / kPi;
    p.drawArc(QRectF(o - QPointF(40, 40), QSizeF(80, 80)), 0, int(psiDeg * 16));
    p.drawText(o + QPointF(44, -6), QStringLiteral("\u03a8"));
    p.setFont(symbols);
    p.drawText(o + QPointF(w / 2 - 12, 18), QStringLiteral("b\u03c6\u0307"));
    p.setFont(font);
    p.drawText(o + QPointF(w + 5, -h / 2 + 4), QStringLiteral("\u1e61"));
    p.drawText(o + QPointF(w / 2 - 34, -h / 2 - 6), QStringLiteral("v_T"));
}

IntroductionWindow::IntroductionWindow(bool useSettings, QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("introductionWindow"));
    setWindowTitle(tr("What am I looking at?"));
    setAttribute(Qt::WA_DeleteOnClose);
    // the screen first, in plain words; then the physics
    m_html = tr("<p><b>On the screen.</b> The big picture in the middle is the "
                "<b>canvas</b>: the <b>path</b> is the broad band, red where it turns right, "
                "grey where it runs straight and blue where it turns left, from its dot (the "
                "start) to its square (the end). The solid dark blue body follows it and leaves "
                "a trail; the dashed red ghost and the dash-dotted purple body start with it "
                "and go their own ways. The legend under the canvas names each line.</p>"
                "<p>The <b>four plots</b> below show, against time, the control angle \u03a8, "
                "the angle \u03c7 the control turns, how hard it turns it (\u03bb) and the "
                "kinetic energy T. The <b>green line</b> in each plot is the moment the canvas "
                "shows; click a plot to go to that moment.</p>"
                "<p><b>To play</b>, press <b>Space</b> or the play button at the bottom; drag "
                "the slider beside it to move through time, <b>Home</b> goes back to the start. "
                "The keys <b>1</b> to <b>4</b> load the paper's four examples, <b>Page Down</b> "
                "the gallery's next scene; <b>Ctrl+Z</b> takes any of them back.</p>");
    m_html +=
        tr("<p><b>The physics.</b> A <b>body</b> (a sleigh, a rolling disk or a two-wheeled "
           "carriage) rests on a "
           "knife edge at <b>P</b>: P moves only along the body's heading \u03c6, never sideways. "
           "A control inside the body steers it so that P follows the <b>path</b>.</p>"
           "<p><b>\u03a8</b>, the control angle, splits the body's energy between driving and "
           "turning: \u1e61 = v<sub>T</sub> sin \u03a8 and b\u03c6\u0307 = v<sub>T</sub> cos "
           "\u03a8 (the triangle). On a straight path \u03a8 = \u03c0/2; the path's curvature "
           "\u03ba fixes it, tan \u03a8 = 1/(b\u03ba).</p>"
           "<p><b>\u03c7</b> = \u03a8 \u2212 (a/b)\u03c6 is the angle the control turns, and "
           "<b>\u03bb</b> = m b \u03c7\u0307 is how hard it turns it: a push \u03bb\u03c6\u0307 "
           "along the heading and a couple \u2212\u03bb\u1e61, which at constant energy do no "
           "work.</p>"
           "<p>The <b>ghost</b> is the same body from the same start with no control (\u03bb = "
           "0): its turning dies away, the knife lets it go only straight on, and it leaves the "
           "path. The "
           "<b>vakonomic body</b> obeys the other mechanics the paper discusses: its \u03bb "
           "follows an equation of its own, only its start can be chosen, and it cannot keep to "
           "the path either.</p>");
    m_html += tr("<p><b>Plan</b> (Edit menu) turns this round: drag a target pose and the "
                 "program finds every vakonomic motion from the start that reaches it, choosing "
                 "only \u03bb(0). The fastest is drawn in full and certified; the fainter ones "
                 "arrive later, each labelled with its time. Where two are equally fast, both are "
                 "drawn in full.</p>");
    auto* text = new QLabel(withDottedSymbolFont(m_html));
    text->setWordWrap(true);
    text->setTextFormat(Qt::RichText);
    text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_dismiss = new QCheckBox(tr("Don't show this at start"));
    m_dismiss->setEnabled(useSettings);
    if (useSettings)
        m_dismiss->setChecked(!dueAtStart(QSettings()));
    connect(m_dismiss, &QCheckBox::toggled, this, [useSettings](bool on) {
        if (useSettings)
            QSettings().setValue(QLatin1String(kDismissedKey), on);
    });
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new BodyDiagram, 2);
    // the text scrolls when the screen is too low for all of it
    auto* scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(text);
    layout->addWidget(scroll, 3);
    layout->addWidget(m_dismiss);
    layout->addWidget(buttons);
    resize(600, 900); // within the screen's free area (placeOnScreen)
}

bool IntroductionWindow::dueAtStart(const QSettings& settings) {
    return !settings.value(QLatin1String(kDismissedKey), false).toBool();
}

QString IntroductionWindow::text() const {
    QTextDocument document;
    document.setHtml(m_html);
    return document.toPlainText();
}

} // namespace chaplygin::ui
