#include "document/autosave.h"

#include "common/atomic_file.h"
#include "common/input_error.h"
#include "scene/scene_json.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

#include <algorithm>
#include <atomic>
#include <exception>

namespace chaplygin::ui {

namespace {

std::atomic<int> windowsStarted{0};

QString readText(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()).trimmed() : QString();
}

} // namespace

Autosave::Autosave(QObject* parent, const QString& directory)
    : QObject(parent), m_directory(directory), m_id(QStringLiteral("window-%1-%2")
                                                        .arg(QCoreApplication::applicationPid())
                                                        .arg(windowsStarted.fetch_add(1))) {
    QDir().mkpath(m_directory);
    m_lock = std::make_unique<QLockFile>(path(QStringLiteral(".lock")));
    m_lock->tryLock(0);
    m_timer.setSingleShot(true);
    m_timer.setInterval(kDelayMs);
    connect(&m_timer, &QTimer::timeout, this, [this] { writeNow(); });
}

Autosave::~Autosave() {
    discard();
    m_lock->unlock();
}

QString Autosave::defaultDirectory() {
    QString base = qEnvironmentVariable("XDG_STATE_HOME");
    if (base.isEmpty())
        base = QDir::homePath() + (QStandardPaths::isTestModeEnabled()
                                       ? QStringLiteral("/.qttest/state")
                                       : QStringLiteral("/.local/state"));
    return base + QStringLiteral("/chaplygin-lab/autosave");
}

QString Autosave::path(const QString& suffix) const {
    return QDir(m_directory).filePath(m_id + suffix);
}

QString Autosave::file() const {
    return m_written ? path(QStringLiteral(".json")) : QString();
}

void Autosave::sceneChanged(const Scene& scene, const QString& fileName) {
    m_pending = scene;
    m_pendingFileName = fileName;
    m_timer.start();
}

void Autosave::discard() {
    m_timer.stop();
    m_pending.reset();
    QFile::remove(path(QStringLiteral(".json")));
    QFile::remove(path(QStringLiteral(".origin")));
    m_written = false;
}

bool Autosave::writeNow() {
    m_timer.stop();
    if (!m_pending)
        return true;
    try {
        QDir().mkpath(m_directory);
        writeFileAtomically(path(QStringLiteral(".json")).toStdString(), sceneToJson(*m_pending));
        if (m_pendingFileName.isEmpty())
            QFile::remove(path(QStringLiteral(".origin")));
        else
            writeFileAtomically(path(QStringLiteral(".origin")).toStdString(),
                                m_pendingFileName.toStdString() + "\n");
    } catch (const std::exception&) {
        return false; // a full disk keeps the last copy; the scene itself is still in memory
    }
    m_pending.reset();
    m_written = true;
    return true;
}

std::vector<Autosave::Orphan> Autosave::orphans() const {
    std::vector<Orphan> found;
    const QDir dir(m_directory);
    for (const QFileInfo& info :
         dir.entryInfoList({QStringLiteral("window-*.json")}, QDir::Files, QDir::Time)) {
        const QString base = info.completeBaseName();
        if (base == m_id)
            continue;
        QLockFile lock(dir.filePath(base + QStringLiteral(".lock")));
        if (!lock.tryLock(0))
            continue; // its window is still open
        lock.unlock();
        found.push_back({info.filePath(), info.lastModified(),
                         readText(dir.filePath(base + QStringLiteral(".origin")))});
    }
    return found;
}

SceneSparingMarks Autosave::readOrphan(const Orphan& orphan) {
    QFile f(orphan.file);
    if (!f.open(QIODevice::ReadOnly))
        throw InputError(tr("cannot open '%1'").arg(orphan.file).toStdString(),
                         f.errorString().toStdString());
    return sceneFromJsonSparingMarks(f.readAll().toStdString());
}

void Autosave::removeOrphan(const Orphan& orphan) {
    const QFileInfo info(orphan.file);
    const QDir dir = info.dir();
    const QString base = info.completeBaseName();
    QFile::remove(orphan.file);
    QFile::remove(dir.filePath(base + QStringLiteral(".origin")));
    QFile::remove(dir.filePath(base + QStringLiteral(".lock")));
}

} // namespace chaplygin::ui
