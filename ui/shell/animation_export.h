#pragma once
#include "canvas/canvas_style.h"

#include <QImage>
#include <QProcess>
#include <QSize>
#include <QString>
#include <QStringList>

#include <functional>
#include <memory>
#include <vector>

class QWidget;

namespace chaplygin::ui {

class SceneDocument;
class SceneCanvas;
class PlotsPanel;

enum class AnimationFormat { Gif, Mp4, PngFrames };

/// What an animation export writes: the canvas (and optionally the plots beside it) from t = 0
/// to t_end, at fps frames per real second, the motion running at speedFactor times real time.
struct AnimationSettings {
    QString file;          ///< name.gif, name.mp4, or a folder (ends in / or has no extension)
    int fps = 30;          ///< frames per second, 1 ... 120
    QSize size{1280, 720}; ///< frame size [px]
    double speedFactor = 1;
    bool withPlots = false; ///< the plots to the right of the canvas
    CanvasLook look;        ///< the canvas's style and the bodies shown (the screen's, in the app)
};

/// The format a file name asks for. Throws InputError("--animation") for another extension.
AnimationFormat animationFormatOf(const QString& file);

/// The ffmpeg program on PATH, or an empty string.
QString findFfmpeg();

/// The times of the frames: 0, speed/fps, 2 speed/fps, ... and t_end itself.
std::vector<double> animationFrameTimes(double tEnd, int fps, double speedFactor);

/// Renders frames offscreen (the canvas widget painted into a QImage, never a grab of a visible
/// window) and hands them to ffmpeg through a pipe, or writes PNG frames into a folder. The
/// output appears only when finished: a GIF or MP4 is written to a temporary file beside it and
/// renamed into place; a cancelled or failed export removes what it wrote.
class AnimationExporter {
  public:
    /// Checks the settings and starts ffmpeg. Throws InputError (bad file name, size or fps,
    /// ffmpeg missing, no valid scene) or IoError (the output cannot be created).
    AnimationExporter(SceneDocument* document, const AnimationSettings& settings);
    ~AnimationExporter();
    AnimationExporter(const AnimationExporter&) = delete;
    AnimationExporter& operator=(const AnimationExporter&) = delete;

    int frameCount() const { return static_cast<int>(m_times.size()); }
    int framesDone() const { return m_done; }
    /// The frame at time t, as written (for tests and previews).
    QImage renderFrame(double t);
    /// Renders and writes the next frame. Throws IoError when it cannot be written.
    void writeNextFrame();
    /// After the last frame: waits for ffmpeg and moves the file into place. Throws IoError.
    void finish();
    /// Stops and removes what was written.
    void cancel();
    /// Every frame and finish(); progress(done, total) is called after each frame and returns
    /// false to cancel. Returns false when cancelled.
    bool run(const std::function<bool(int, int)>& progress = {});

  private:
    void writeToFfmpeg(const QImage& frame);
    void cleanUp();

    SceneDocument* m_document;
    AnimationSettings m_settings;
    AnimationFormat m_format;
    std::vector<double> m_times;
    int m_done = 0;
    bool m_finished = false;
    std::unique_ptr<QWidget> m_frame; // the offscreen widget that is painted
    SceneCanvas* m_canvas = nullptr;
    PlotsPanel* m_plots = nullptr;
    QProcess m_ffmpeg;
    QString m_temporary;   // ffmpeg's output until finish()
    QStringList m_written; // PNG frames written so far
};

} // namespace chaplygin::ui
