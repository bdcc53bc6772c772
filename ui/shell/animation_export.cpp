#include "shell/animation_export.h"

#include "canvas/scene_canvas.h"
#include "common/atomic_file.h"
#include "common/input_error.h"
#include "document/scene_document.h"
#include "plots/plots_panel.h"

#include <QBuffer>
#include <QDir>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QPainter>
#include <QStandardPaths>
#include <QSysInfo>
#include <QTemporaryFile>
#include <QWidget>

#include <cmath>
#include <cstdio>

namespace chaplygin::ui {
namespace {

std::string text(const QString& s) {
    return s.toStdString();
}

// QImage::Format_RGB32 is 0xffRRGGBB per pixel: in memory B, G, R, 0xff on little-endian machines
QString rawPixelFormat() {
    return QSysInfo::ByteOrder == QSysInfo::LittleEndian ? QStringLiteral("bgra")
                                                         : QStringLiteral("argb");
}

QString framePattern() {
    return QStringLiteral("frame_%1.png");
}

} // namespace

AnimationFormat animationFormatOf(const QString& file) {
    if (file.isEmpty())
        throw InputError("--animation", "needs a file name (name.gif, name.mp4 or a folder/)");
    if (file.endsWith(QLatin1Char('/')))
        return AnimationFormat::PngFrames;
    QString suffix = QFileInfo(file).suffix().toLower();
    if (suffix.isEmpty())
        return AnimationFormat::PngFrames;
    if (suffix == QLatin1String("gif"))
        return AnimationFormat::Gif;
    if (suffix == QLatin1String("mp4"))
        return AnimationFormat::Mp4;
    throw InputError("--animation", "unknown format '." + text(suffix) + "' of '" + text(file) +
                                        "' (use name.gif, name.mp4, or a folder for PNG frames)");
}

QString findFfmpeg() {
    return QStandardPaths::findExecutable(QStringLiteral("ffmpeg"));
}

std::vector<double> animationFrameTimes(double tEnd, int fps, double speedFactor) {
    std::vector<double> times;
    double step = speedFactor / fps;
    for (long k = 0;; ++k) {
        double t = k * step;
        if (t >= tEnd - 1e-9 * step)
            break;
        times.push_back(t);
    }
    times.push_back(tEnd);
    return times;
}

AnimationExporter::AnimationExporter(SceneDocument* document, const AnimationSettings& settings)
    : m_document(document), m_settings(settings), m_format(animationFormatOf(settings.file)) {
    if (settings.fps < 1 || settings.fps > 120)
        throw InputError("--fps", "must be a whole number from 1 to 120");
    if (settings.size.width() < 64 || settings.size.height() < 64 || settings.size.width() > 7680 ||
        settings.size.height() > 4320)
        throw InputError("--size", "width and height must be in 64x64 ... 7680x4320");
    if (!(settings.speedFactor > 0) || !std::isfinite(settings.speedFactor))
        throw InputError("speed", "the playback speed must be > 0");
    const auto& solution = document->solution();
    if (!solution)
        throw InputError("scene", "there is no valid motion to export");
    m_times = animationFrameTimes(solution->tEnd(), settings.fps, settings.speedFactor);

    // the widgets that are painted into each frame; never shown on a screen
    m_frame = std::make_unique<QWidget>();
    m_frame->setAttribute(Qt::WA_DontShowOnScreen);
    auto* layout = new QHBoxLayout(m_frame.get());
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    m_canvas = new SceneCanvas(document);
    m_canvas->setLook(settings.look);
    layout->addWidget(m_canvas, 3);
    if (settings.withPlots) {
        m_plots = new PlotsPanel(document);
        layout->addWidget(m_plots, 2);
    }
    m_frame->resize(settings.size);
    m_frame->show();
    layout->activate();
    m_canvas->fitScene();
    if (m_plots) {
        m_plots->refresh();
        m_plots->replotNow(); // the plots are drawn once; each frame moves the time cursor
    }

    if (m_format == AnimationFormat::PngFrames) {
        QString dir = settings.file;
        if (!QDir().mkpath(dir))
            throw IoError("cannot create the frames folder '" + text(dir) + "'");
        return;
    }
    QString ffmpeg = findFfmpeg();
    if (ffmpeg.isEmpty())
        throw InputError("--animation",
                         "writing '" + text(settings.file) +
                             "' needs the ffmpeg program, which is not on PATH; install ffmpeg "
                             "(Debian: apt install ffmpeg), or give a folder (name/) for PNG "
                             "frames");
    QFileInfo target(settings.file);
    if (!target.absoluteDir().exists())
        throw IoError("cannot write '" + text(settings.file) + "': the folder '" +
                      text(target.absolutePath()) + "' does not exist");
    if (target.isDir())
        throw IoError("cannot write '" + text(settings.file) + "': it is a folder");
    {
        QTemporaryFile reserve(target.absoluteDir().filePath(
            QStringLiteral(".") + target.fileName() + QStringLiteral(".XXXXXX")));
        reserve.setAutoRemove(false);
        if (!reserve.open())
            throw IoError("cannot write into the folder '" + text(target.absolutePath()) +
                          "': " + text(reserve.errorString()));
        m_temporary = reserve.fileName();
        // QTemporaryFile makes it private; the animation is an ordinary document
        reserve.setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner |
                               QFileDevice::ReadGroup | QFileDevice::ReadOther);
    }
    QStringList args{QStringLiteral("-hide_banner"),
                     QStringLiteral("-loglevel"),
                     QStringLiteral("error"),
                     QStringLiteral("-nostdin"),
                     QStringLiteral("-y"),
                     QStringLiteral("-f"),
                     QStringLiteral("rawvideo"),
                     QStringLiteral("-pix_fmt"),
                     rawPixelFormat(),
                     QStringLiteral("-s"),
                     QStringLiteral("%1x%2").arg(settings.size.width()).arg(settings.size.height()),
                     QStringLiteral("-framerate"),
                     QString::number(settings.fps),
                     QStringLiteral("-i"),
                     QStringLiteral("-")};
    if (m_format == AnimationFormat::Gif) {
        args << QStringLiteral("-vf")
             << QStringLiteral("split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse="
                               "dither=bayer:bayer_scale=3")
             << QStringLiteral("-f") << QStringLiteral("gif");
    } else {
        // yuv420p (what players accept) needs even sides
        args << QStringLiteral("-vf") << QStringLiteral("pad=ceil(iw/2)*2:ceil(ih/2)*2")
             << QStringLiteral("-c:v") << QStringLiteral("libx264") << QStringLiteral("-preset")
             << QStringLiteral("veryfast") << QStringLiteral("-crf") << QStringLiteral("20")
             << QStringLiteral("-pix_fmt") << QStringLiteral("yuv420p")
             << QStringLiteral("-movflags") << QStringLiteral("+faststart") << QStringLiteral("-f")
             << QStringLiteral("mp4");
    }
    args << m_temporary;
    m_ffmpeg.setProcessChannelMode(QProcess::SeparateChannels);
    m_ffmpeg.start(ffmpeg, args);
    if (!m_ffmpeg.waitForStarted(10000)) {
        cleanUp();
        throw IoError("cannot start '" + text(ffmpeg) + "': " + text(m_ffmpeg.errorString()));
    }
}

AnimationExporter::~AnimationExporter() {
    if (!m_finished)
        cleanUp();
}

QImage AnimationExporter::renderFrame(double t) {
    m_canvas->setTime(t);
    if (m_plots)
        m_plots->setTime(t);
    // the raster engine's fastest format; ffmpeg reads it as is
    QImage image(m_settings.size, QImage::Format_RGB32);
    image.fill(Qt::white);
    m_frame->render(&image);
    return image;
}

void AnimationExporter::writeToFfmpeg(const QImage& frame) {
    // 32-bit pixels: rows have no padding
    const qint64 size = frame.sizeInBytes();
    if (m_ffmpeg.write(reinterpret_cast<const char*>(frame.constBits()), size) != size)
        throw IoError("ffmpeg stopped taking frames: " + text(m_ffmpeg.errorString()));
    while (m_ffmpeg.bytesToWrite() > 0) {
        if (!m_ffmpeg.waitForBytesWritten(30000) || m_ffmpeg.state() != QProcess::Running)
            throw IoError("ffmpeg stopped taking frames: " +
                          text(QString::fromLocal8Bit(m_ffmpeg.readAllStandardError()).trimmed()));
    }
}

void AnimationExporter::writeNextFrame() {
    if (m_done >= frameCount())
        return;
    QImage image = renderFrame(m_times[m_done]);
    if (m_format == AnimationFormat::PngFrames) {
        QByteArray png;
        QBuffer buffer(&png);
        buffer.open(QIODevice::WriteOnly);
        if (!image.save(&buffer, "PNG", 80)) // light compression: frames are many and large
            throw IoError("cannot encode frame " + std::to_string(m_done));
        QString name =
            QDir(m_settings.file).filePath(framePattern().arg(m_done, 5, 10, QLatin1Char('0')));
        writeFileAtomically(text(name), png.toStdString());
        m_written << name;
    } else {
        writeToFfmpeg(image);
    }
    ++m_done;
}

void AnimationExporter::finish() {
    while (m_done < frameCount())
        writeNextFrame();
    if (m_format == AnimationFormat::PngFrames) {
        // frames of an earlier, longer export would play on after this one
        QDir dir(m_settings.file);
        for (const QString& old : dir.entryList({QStringLiteral("frame_*.png")}, QDir::Files))
            if (!m_written.contains(dir.filePath(old)))
                dir.remove(old);
        m_finished = true;
        return;
    }
    m_ffmpeg.closeWriteChannel();
    bool ended = m_ffmpeg.waitForFinished(600000);
    if (!ended || m_ffmpeg.exitStatus() != QProcess::NormalExit || m_ffmpeg.exitCode() != 0) {
        QString why = QString::fromLocal8Bit(m_ffmpeg.readAllStandardError()).trimmed();
        cleanUp();
        throw IoError("ffmpeg could not write '" + text(m_settings.file) + "'" +
                      (why.isEmpty() ? std::string() : ": " + text(why)));
    }
    if (std::rename(QFile::encodeName(m_temporary).constData(),
                    QFile::encodeName(m_settings.file).constData()) != 0) {
        cleanUp();
        throw IoError("cannot move the animation into place as '" + text(m_settings.file) + "'");
    }
    m_temporary.clear();
    m_finished = true;
}

void AnimationExporter::cancel() {
    cleanUp();
}

void AnimationExporter::cleanUp() {
    if (m_ffmpeg.state() != QProcess::NotRunning) {
        m_ffmpeg.kill();
        m_ffmpeg.waitForFinished(10000);
    }
    if (!m_temporary.isEmpty())
        QFile::remove(m_temporary);
    m_temporary.clear();
    for (const QString& f : m_written)
        QFile::remove(f);
    m_written.clear();
}

bool AnimationExporter::run(const std::function<bool(int, int)>& progress) {
    while (m_done < frameCount()) {
        writeNextFrame();
        if (progress && !progress(m_done, frameCount())) {
            cancel();
            return false;
        }
    }
    finish();
    return true;
}

} // namespace chaplygin::ui
