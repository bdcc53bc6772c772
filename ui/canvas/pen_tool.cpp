#include "canvas/pen_tool.h"

#include "canvas/canvas_style.h"
#include "canvas/canvas_view.h"
#include "canvas/trail_stroke.h"

#include <QLineF>
#include <QMouseEvent>
#include <QPaintEngine>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace chaplygin::ui {

namespace {

// a mark's pixels farther than this from the drawing area are stroked segment by segment, only
// where they reach it (strokePolylineWithin), rather than handed to Qt as a curve
constexpr double kSmoothReachPx = 1e5;

QPointF pointOf(const std::pair<double, double>& p) {
    return {p.first, p.second};
}

std::pair<double, double> pairOf(QPointF p) {
    return {p.x(), p.y()};
}

} // namespace

PenTool::PenTool(const CanvasView& view, const CanvasStyle& style, std::function<QRectF()> area,
                 QObject* parent)
    : CanvasTool(parent), m_view(view), m_style(style), m_area(std::move(area)) {}

void PenTool::setEnabled(bool on) {
    if (!on)
        cancel();
    m_enabled = on;
}

void PenTool::setColour(int colour) {
    colour = std::clamp(colour, 0, kMarkColours - 1);
    if (colour == m_colour)
        return;
    m_colour = colour;
    emit colourChanged(colour);
}

void PenTool::nextColour() {
    setColour((m_colour + 1) % kMarkColours);
}

void PenTool::setKind(MarkKind kind) {
    if (kind == m_kind)
        return;
    m_kind = kind;
    emit kindChanged(kind);
}

void PenTool::setSavesWithScene(bool on) {
    if (on == m_state.savedWithScene)
        return;
    m_state.savedWithScene = on;
    emit savesWithSceneChanged(on);
}

void PenTool::setPenMarks(PenMarks marks) {
    m_drawing.reset();
    const bool option = marks.savedWithScene;
    marks.savedWithScene = m_state.savedWithScene;
    m_state = std::move(marks);
    emit marksChanged();
    setSavesWithScene(option);
    emit changed();
}

void PenTool::setMarksSaved() {
    m_state.inFile = m_state.savedWithScene ? m_state.shown : std::vector<AnnotationMark>{};
    emit marksChanged();
}

bool PenTool::undoLast() {
    if (m_drawing) {
        cancel();
        return true;
    }
    if (m_state.shown.empty())
        return false;
    m_state.shown.pop_back();
    emit marksChanged();
    emit changed();
    return true;
}

void PenTool::clear() {
    m_drawing.reset();
    if (!m_state.shown.empty()) {
        m_state.shown.clear();
        emit marksChanged();
    }
    emit changed();
}

QColor PenTool::colourOf(int colour) {
    switch (colour) {
    case 1:
        return {20, 90, 220}; // blue
    case 2:
        return {0, 140, 50}; // green
    case 3:
        return {20, 20, 20}; // black
    default:
        return {220, 20, 30}; // red
    }
}

QString PenTool::colourName(int colour) {
    switch (colour) {
    case 1:
        return tr("Blue");
    case 2:
        return tr("Green");
    case 3:
        return tr("Black");
    default:
        return tr("Red");
    }
}

bool PenTool::press(const QMouseEvent& e) {
    if (!m_enabled || e.button() != Qt::LeftButton)
        return false;
    const bool arrow = m_kind == MarkKind::Arrow || (e.modifiers() & Qt::ShiftModifier);
    const auto at = pairOf(m_view.toWorld(e.position()));
    m_drawing = AnnotationMark{m_colour, arrow ? MarkKind::Arrow : MarkKind::Freehand, {at}};
    if (arrow)
        m_drawing->points.push_back(at);
    emit changed();
    return true;
}

bool PenTool::move(const QMouseEvent& e) {
    if (!m_drawing)
        return false;
    const auto at = pairOf(m_view.toWorld(e.position()));
    if (m_drawing->kind == MarkKind::Arrow)
        m_drawing->points.back() = at;
    else
        m_drawing->points.push_back(at);
    emit changed();
    return true;
}

void PenTool::release(const QMouseEvent& e) {
    if (!m_drawing || e.button() != Qt::LeftButton)
        return;
    move(e);
    finish();
}

void PenTool::cancel() {
    if (!m_drawing)
        return;
    m_drawing.reset();
    emit changed();
}

void PenTool::finish() {
    AnnotationMark mark = std::move(*m_drawing);
    m_drawing.reset();
    if (mark.kind == MarkKind::Arrow) {
        // a click is no arrow
        if (QLineF(m_view.toPixel(pointOf(mark.points[0])), m_view.toPixel(pointOf(mark.points[1])))
                .length() < 3) {
            emit changed();
            return;
        }
        m_state.shown.push_back(std::move(mark));
    } else {
        // the points closer than kMinStepPx at this zoom are dropped; a long stroke is kept as
        // marks of at most kMaxMarkPoints, each starting where the one before ended
        const auto points = simplifyStroke(mark.points, kMinStepPx / m_view.scale());
        for (std::size_t from = 0;;) {
            const std::size_t to = std::min(points.size(), from + kMaxMarkPoints);
            m_state.shown.push_back(
                {mark.colour,
                 MarkKind::Freehand,
                 {points.begin() + std::ptrdiff_t(from), points.begin() + std::ptrdiff_t(to)}});
            if (to == points.size())
                break;
            from = to - 1;
        }
    }
    // the oldest marks go past the most a scene holds
    if (m_state.shown.size() > kMaxMarks)
        m_state.shown.erase(m_state.shown.begin(), m_state.shown.end() - std::ptrdiff_t(kMaxMarks));
    emit marksChanged();
    emit changed();
}

void PenTool::paintMark(QPainter& p, const AnnotationMark& mark, const QRectF& area) const {
    const double ls = m_style.lineScale, width = 4 * ls, halo = width + 3 * ls;
    QPolygonF line;
    line.reserve(qsizetype(mark.points.size()));
    for (const auto& point : mark.points)
        line << m_view.toPixel(pointOf(point));
    const QRectF box = line.boundingRect();
    const double reach = 24 * ls; // an arrow's head and its pen beyond its end
    if (!box.adjusted(-reach, -reach, reach, reach).intersects(area))
        return;
    const QColor colour = colourOf(mark.colour);
    const QColor white(255, 255, 255, 190);
    const bool near =
        area.adjusted(-kSmoothReachPx, -kSmoothReachPx, kSmoothReachPx, kSmoothReachPx)
            .contains(box);
    // a white edge under each mark: it reads on the path's colours and on the bodies
    auto stroke = [&](const QPainterPath& path, const QPolygonF& fallback) {
        for (const auto& [c, w] : {std::pair{white, halo}, std::pair{colour, width}}) {
            QPen pen(c, w, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
            if (near) {
                p.strokePath(path, pen);
            } else {
                strokePolylineWithin(p, fallback, pen, QRegion(area.toAlignedRect()));
            }
        }
    };
    if (mark.kind == MarkKind::Arrow && line.size() == 2) {
        const QPointF a = line[0], b = line[1];
        const QLineF shaft(a, b);
        const double head = std::min(18 * ls, 0.6 * shaft.length());
        const QPointF u = (b - a) / std::max(shaft.length(), 1e-9);
        const QPointF n(-u.y(), u.x());
        const double spread = head * std::tan(24 * std::numbers::pi / 180);
        const QPointF base = b - head * u;
        QPainterPath path(a);
        path.lineTo(base);
        stroke(path, QPolygonF{a, base});
        if (!area.adjusted(-reach, -reach, reach, reach).contains(b))
            return;
        const QPolygonF tip{b, base + spread * n, base - spread * n};
        p.setPen(QPen(white, halo - width, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.setBrush(colour);
        p.drawPolygon(tip);
        p.setPen(QPen(colour, 1.5 * ls, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPolygon(tip);
        return;
    }
    if (line.size() == 1) {
        // a dot
        p.setPen(Qt::NoPen);
        p.setBrush(white);
        p.drawEllipse(line[0], halo / 2, halo / 2);
        p.setBrush(colour);
        p.drawEllipse(line[0], width / 2, width / 2);
        return;
    }
    // smooth: quadratic pieces through the midpoints, with the points as their controls
    QPainterPath path(line[0]);
    for (qsizetype i = 1; i + 1 < line.size(); ++i)
        path.quadTo(line[i], (line[i] + line[i + 1]) / 2);
    path.lineTo(line.back());
    stroke(path, line);
}

void PenTool::paint(QPainter& p) const {
    if (m_state.shown.empty() && !m_drawing)
        return;
    QRectF area = m_area();
    // an animation frame repaints a small region: the marks that cannot reach it are left out
    if (const QPaintEngine* engine = p.paintEngine(); engine && !engine->systemClip().isEmpty())
        area &= p.deviceTransform().inverted().mapRect(QRectF(engine->systemClip().boundingRect()));
    if (area.isEmpty())
        return;
    p.save();
    p.setClipRect(area, Qt::IntersectClip);
    p.setRenderHint(QPainter::Antialiasing);
    for (const AnnotationMark& mark : m_state.shown)
        paintMark(p, mark, area);
    if (m_drawing)
        paintMark(p, *m_drawing, area);
    p.restore();
}

} // namespace chaplygin::ui
