#pragma once
// The marks a lecturer draws over the canvas with the pen (docs/user-guide.md, Drawing over the
// lesson): freehand strokes and arrows, in world coordinates, view only.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace chaplygin {

/// What a mark is: a freehand stroke through its points, or an arrow from its first point to its
/// second.
enum class MarkKind { Freehand, Arrow };

/// The pen's colours, in the order of its menu; a mark holds the index.
constexpr int kMarkColours = 4;

/// One mark: its colour (0 ... kMarkColours - 1), its kind and its points [m]; an arrow has two.
struct AnnotationMark {
    int colour = 0;
    MarkKind kind = MarkKind::Freehand;
    std::vector<std::pair<double, double>> points;

    bool operator==(const AnnotationMark&) const = default;
};

/// The pen's marks beside the scene's file (docs/user-guide.md, Drawing over the lesson): those
/// shown over the canvas, those the file holds, and whether File > Save writes them into it.
struct PenMarks {
    std::vector<AnnotationMark> shown;
    std::vector<AnnotationMark> inFile;
    bool savedWithScene = false;

    /// File > Save would write marks other than the file's: unsaved changes, as the scene's own.
    bool unsaved() const { return savedWithScene && shown != inFile; }
    /// Marks shown that the file does not hold, to be saved with it or not: what the
    /// crash-recovery copy keeps (docs/robustness.md, Crash recovery).
    bool outsideFile() const { return shown != inFile; }
    /// The marks that come with a scene's file: shown as they are, File > Save annotations ticked
    /// when there are any and otherwise as it was (`savedWithScene`).
    static PenMarks ofFile(std::vector<AnnotationMark> marks, bool savedWithScene);

    bool operator==(const PenMarks&) const = default;
};

/// At most this many marks on a scene, this many points in one mark.
constexpr std::size_t kMaxMarks = 500;
constexpr std::size_t kMaxMarkPoints = 5000;

/// The colour's name in the scene file ("red", "blue", "green", "black"); empty past the palette.
std::string markColourName(int colour);
/// The index of a colour's name, or -1 when it is none of them.
int markColourFromName(const std::string& name);

/// A freehand stroke with fewer points and the same shape: the first point, then each point at
/// least minDistance from the last one kept, and the last point. Every dropped point is within
/// minDistance of the point kept before it, so every point of the drawn polyline is within
/// minDistance of the kept one.
std::vector<std::pair<double, double>>
simplifyStroke(const std::vector<std::pair<double, double>>& points, double minDistance);

} // namespace chaplygin
