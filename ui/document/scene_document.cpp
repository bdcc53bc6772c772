#include "document/scene_document.h"

#include "document/pin_set.h"

#include "common/input_error.h"
#include "numerics/chebyshev.h"
#include "paths/path_table.h"
#include "planning/scene_path.h"

#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <exception>

namespace chaplygin::ui {

namespace {
constexpr std::size_t kPathCacheSize = 8;
// the paths kept besides the newest: at most this much memory (docs/robustness.md, Bounded work
// and memory); one path of the table's whole halving budget is about 170 MB
constexpr std::size_t kPathCacheBytes = std::size_t(256) << 20;

// a path's table in memory, from above: per panel its node, its Gauss panel and the
// interpolant's rows and samples at the highest degree
std::size_t pathBytes(const Path& path) {
    constexpr std::size_t perPanel = sizeof(PathNode) + sizeof(PathTable::GaussPanel) +
                                     sizeof(PathTable::ChebPanel) +
                                     (cheb::kDegree + 2) * sizeof(PathTable::Row) +
                                     (cheb::kDegree + 1) * sizeof(PathTable::Sample);
    std::size_t panels = 0;
    for (const PathPiece& p : path.pieces())
        if (p.kind == PathPiece::Kind::Curve)
            panels += p.table->panels().size() + 1;
    return sizeof(Path) + panels * perPanel;
}
constexpr qint64 kFrameMs = 16;
constexpr int kPathWaitMs = 8; // how long a path request may hold the UI thread
} // namespace

SceneDocument::SceneDocument(QObject* parent, bool persistent)
    : QObject(parent), m_persistent(persistent), m_undo(new QUndoStack(this)),
      m_pins(new PinSet(this)) {
    connect(m_undo, &QUndoStack::cleanChanged, this,
            [this](bool clean) { emit modifiedChanged(!clean); });
    if (m_persistent) {
        // every change is kept on disk until it is saved (or undone back to the saved state)
        m_autosave = new Autosave(this);
        connect(m_undo, &QUndoStack::indexChanged, this, &SceneDocument::keepCopy);
        connect(m_undo, &QUndoStack::cleanChanged, this, &SceneDocument::keepCopy);
    }
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &SceneDocument::recompute);
    // one worker: every asynchronous path build (and so every GiNaC compile it makes) is serial
    m_pathPool.setMaxThreadCount(1);
    m_pathPool.setExpiryTimeout(-1);
    connect(&m_pathWatcher, &QFutureWatcherBase::finished, this, &SceneDocument::takePath);
}

SceneDocument::~SceneDocument() {
    // the undo stack signals cleanChanged while it is destroyed
    m_undo->disconnect(this);
    m_pathWatcher.disconnect(this);
    m_pathPool.waitForDone();
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
    if (pathPending()) {
        m_pathFuture.waitForFinished();
        takePath();
    }
    m_timer.stop();
    if (m_dirty)
        recompute();
}

std::shared_ptr<const Path> SceneDocument::cachedPath(const PathSource& source) {
    for (std::size_t i = 0; i < m_pathCache.size(); ++i) {
        if (m_pathCache[i].first == source) {
            auto hit = m_pathCache[i];
            m_pathCache.erase(m_pathCache.begin() + static_cast<std::ptrdiff_t>(i));
            m_pathCache.insert(m_pathCache.begin(), hit);
            return hit.second;
        }
    }
    return nullptr;
}

void SceneDocument::cachePath(const PathSource& source, std::shared_ptr<const Path> path) {
    m_pathCache.insert(m_pathCache.begin(), {source, std::move(path)});
    // a count and a size: eight paths of the largest table would take 1.4 GB
    std::size_t bytes = 0, keep = 0;
    for (const auto& entry : m_pathCache) {
        bytes += pathBytes(*entry.second);
        if (keep > 0 && (keep == kPathCacheSize || bytes > kPathCacheBytes))
            break;
        ++keep;
    }
    m_pathCache.resize(keep);
}

std::shared_ptr<const Path> SceneDocument::pathFor(const PathSource& source) {
    if (auto hit = cachedPath(source))
        return hit;
    std::shared_ptr<const Path> path = buildScenePath(source);
    cachePath(source, path);
    return path;
}

void SceneDocument::requestPath(const PathSource& source, PathDone done) {
    ++*m_pathLatest; // a queued older request now skips its work
    if (cachedPath(source)) {
        m_pathFuture = {};
        m_pathDone = {};
        done({});
        return;
    }
    m_pathDone = std::move(done);
    m_pathTaken = false;
    m_pathFuture = QtConcurrent::run(
        &m_pathPool, [source, id = m_pathLatest->load(), latest = m_pathLatest]() {
            PathJob job;
            if (id != latest->load())
                return job; // superseded before it started
            try {
                job.path = buildScenePath(source);
            } catch (const InputError& e) {
                job.error = QString::fromStdString(e.what());
            } catch (const std::exception& e) {
                job.error = tr("internal error: %1").arg(QString::fromUtf8(e.what()));
            }
            return job;
        });
    m_pathSource = source;
    // setFuture drops the finished signal of a superseded job: the latest request wins
    m_pathWatcher.setFuture(m_pathFuture);
    // a quick path is in place within half a frame, as if it had been built here
    if (m_pathPool.waitForDone(kPathWaitMs))
        takePath();
}

bool SceneDocument::pathPending() const {
    return m_pathFuture.isValid() && !m_pathTaken;
}

void SceneDocument::takePath() {
    if (!pathPending() || !m_pathFuture.isFinished())
        return;
    m_pathTaken = true;
    PathJob job = m_pathFuture.result();
    if (job.path)
        cachePath(m_pathSource, job.path);
    PathDone done = std::move(m_pathDone);
    m_pathDone = {};
    m_pathFuture = {};
    if (done)
        done(job.path ? QString() : job.error);
}

void SceneDocument::check(const Scene& scene) {
    m_checked = std::make_shared<const Solution>(Solution::compute(scene, pathFor(scene.path)));
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
    SceneError error;
    std::shared_ptr<const Solution> checked = std::move(m_checked);
    try {
        // only the cheap stages rerun when the path is cached; a checked scene is not solved twice
        std::shared_ptr<const Solution> solution;
        if (checked && checked->scene() == m_scene)
            solution = checked;
        else if (m_vetted && m_vetted->first == m_scene.system)
            solution = std::make_shared<const Solution>(
                Solution::compute(m_scene, pathFor(m_scene.path), m_vetted->second));
        else
            solution =
                std::make_shared<const Solution>(Solution::compute(m_scene, pathFor(m_scene.path)));
        // nothing non-finite reaches a view: the solution is checked as it is made, the plots'
        // series here
        PlotSeries series = collectSeries(*solution, kFreeSamples);
        requireFiniteSeries(series);
        m_series = std::move(series);
        m_solution = std::move(solution);
    } catch (const InputError& e) {
        error = SceneError::of(e);
    } catch (const std::exception& e) {
        error = SceneError::other(tr("internal error: %1").arg(QString::fromUtf8(e.what())));
    }
    if (!(error == m_error) || !error.isEmpty()) {
        m_error = error;
        emit errorChanged(m_error);
    }
    if (error.isEmpty())
        emit solutionChanged();
}

} // namespace chaplygin::ui
