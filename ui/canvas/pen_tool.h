#pragma once
#include "canvas/canvas_tool.h"
#include "scene/annotations.h"

#include <QColor>
#include <QPointF>
#include <QRectF>
#include <QString>

#include <functional>
#include <optional>
#include <vector>

namespace chaplygin::ui {

class CanvasView;
struct CanvasStyle;

/// The pen: freehand marks and arrows drawn over the canvas while it plays (docs/user-guide.md,
/// Drawing over the lesson). The marks are held in metres, so that they follow zoom and pan, and
/// they belong to the pen, not to the scene: they change neither the path nor the computation,
/// and no step of the scene's undo stack (a step that replaces the whole scene carries the marks
/// it took away: SceneDocument::penMarksLoaded). A drag draws a mark in the pen's colour; with
/// arrows chosen, or Shift held, the drag is an arrow from its start to its end.
class PenTool : public CanvasTool {
    Q_OBJECT
  public:
    /// `area`: where the scene is drawn [px] (the drawing area and the time line's band above
    /// it), which the marks are drawn within.
    PenTool(const CanvasView& view, const CanvasStyle& style, std::function<QRectF()> area,
            QObject* parent);

    /// Whether the canvas's left button draws (Edit > Pen, P on the canvas). The marks stay shown
    /// when it is off.
    bool enabled() const { return m_enabled; }
    void setEnabled(bool on);
    /// The colour of the next mark, 0 ... kMarkColours - 1.
    int colour() const { return m_colour; }
    void setColour(int colour);
    /// The next colour, after the last the first (C on the canvas).
    void nextColour();
    /// What a drag draws: a freehand stroke or an arrow (A on the canvas).
    MarkKind kind() const { return m_kind; }
    void setKind(MarkKind kind);
    /// Whether File > Save writes the marks into the scene file (off unless asked, or unless
    /// the opened file had them).
    bool savesWithScene() const { return m_state.savedWithScene; }
    void setSavesWithScene(bool on);

    /// The marks drawn, oldest first [m].
    const std::vector<AnnotationMark>& marks() const { return m_state.shown; }
    /// The marks shown, those the scene's file holds and the option to save them.
    const PenMarks& penMarks() const { return m_state; }
    /// All of it at once: a scene loaded or restored, or its undo step undone or redone.
    void setPenMarks(PenMarks marks);
    /// The scene's file was just written: it holds the marks if they are saved with the scene,
    /// else none.
    void setMarksSaved();
    /// Whether File > Save would write marks other than the file's: the marks are to be saved
    /// with the scene and differ from those last loaded or saved (PenMarks::unsaved).
    bool hasUnsavedMarks() const { return m_state.unsaved(); }
    /// Removes the last mark (Ctrl+Z while the pen is on); false when there is none.
    bool undoLast();
    /// Removes every mark (E or Delete while the pen is on).
    void clear();

    /// The palette: colours a projector shows apart on white, and their names.
    static QColor colourOf(int colour);
    static QString colourName(int colour);

    bool press(const QMouseEvent& e) override;
    bool move(const QMouseEvent& e) override;
    void release(const QMouseEvent& e) override;
    bool active() const override { return m_drawing.has_value(); }
    void cancel() override;
    Qt::CursorShape cursor() const override { return Qt::CrossCursor; }
    void paint(QPainter& p) const override;

  signals:
    /// A mark was added or removed, or the marks the scene's file holds changed.
    void marksChanged();
    void colourChanged(int colour);
    void kindChanged(chaplygin::MarkKind kind);
    void savesWithSceneChanged(bool on);

  private:
    /// A freehand stroke's points closer than this [px] at the zoom it is drawn at are dropped.
    static constexpr double kMinStepPx = 1.5;
    void paintMark(QPainter& p, const AnnotationMark& mark, const QRectF& area) const;
    /// Ends the mark being drawn and keeps it (a long stroke as several marks).
    void finish();

    const CanvasView& m_view;
    const CanvasStyle& m_style;
    std::function<QRectF()> m_area;
    bool m_enabled = false;
    int m_colour = 0;
    MarkKind m_kind = MarkKind::Freehand;
    PenMarks m_state;
    std::optional<AnnotationMark> m_drawing; // the mark under way
};

} // namespace chaplygin::ui
