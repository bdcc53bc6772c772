#include "scene_document.h"

#include "common/input_error.h"

#include <algorithm>
#include <exception>

namespace chaplygin::ui {

namespace {
constexpr std::size_t kPathCacheSize = 8;
constexpr qint64 kFrameMs = 16;
} // namespace

SceneDocument::SceneDocument(QObject* parent) : QObject(parent) {
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &SceneDocument::recompute);
}

void SceneDocument::setScene(const Scene& scene) {
    m_scene = scene;
    m_dirty = true;
    if (m_timer.isActive())
        return;
    // at most one recompute per display frame, however fast the slider events arrive
    qint64 since = m_lastRecompute.isValid() ? m_lastRecompute.elapsed() : kFrameMs;
    m_timer.start(int(std::max<qint64>(0, kFrameMs - since)));
}

void SceneDocument::setSceneNow(const Scene& scene) {
    m_scene = scene;
    m_dirty = true;
    flush();
}

void SceneDocument::flush() {
    m_timer.stop();
    if (m_dirty)
        recompute();
}

std::shared_ptr<const Path> SceneDocument::pathFor(const PathSource& source) {
    for (std::size_t i = 0; i < m_pathCache.size(); ++i) {
        if (m_pathCache[i].first == source) {
            auto hit = m_pathCache[i];
            m_pathCache.erase(m_pathCache.begin() + static_cast<std::ptrdiff_t>(i));
            m_pathCache.insert(m_pathCache.begin(), hit);
            return hit.second;
        }
    }
    std::shared_ptr<const Path> path = buildPath(source);
    m_pathCache.insert(m_pathCache.begin(), {source, path});
    if (m_pathCache.size() > kPathCacheSize)
        m_pathCache.pop_back();
    return path;
}

void SceneDocument::setFileName(const QString& name) {
    if (name == m_fileName)
        return;
    m_fileName = name;
    emit fileNameChanged(name);
}

void SceneDocument::recompute() {
    m_dirty = false;
    m_lastRecompute.start();
    QString error;
    try {
        // only the cheap stages rerun when the path is cached
        auto solution =
            std::make_shared<const Solution>(Solution::compute(m_scene, pathFor(m_scene.path)));
        m_series = collectSeries(*solution, kFreeSamples);
        m_solution = std::move(solution);
    } catch (const InputError& e) {
        error = QString::fromStdString(e.what());
    } catch (const std::exception& e) {
        error = QStringLiteral("internal error: %1").arg(QString::fromUtf8(e.what()));
    }
    if (error != m_error || !error.isEmpty()) {
        m_error = error;
        emit errorChanged(m_error);
    }
    if (error.isEmpty())
        emit solutionChanged();
}

} // namespace chaplygin::ui
