#pragma once
// Fault injection for the GUI tests: a full disk that root cannot bypass and a private /dev/full.
// Everything happens inside the test's own temporary directory.
#include <QByteArray>
#include <QFile>
#include <QString>

#include <cerrno>
#include <csignal>
#include <cstring>

#include <fcntl.h>
#include <unistd.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

inline QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

inline bool writeBytes(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

/// Makes a private copy of /dev/full (char device 1,7) at path and checks that writing to it
/// fails with ENOSPC. False, with the reason in *why, where mknod is forbidden or the copy is
/// unusable (a file system mounted nodev, a container's device filter).
inline bool makeFullDevice(const QString& path, QString* why = nullptr) {
    const QByteArray name = QFile::encodeName(path);
    auto refuse = [&](const char* what) {
        if (why)
            *why = QStringLiteral("%1: %2").arg(QLatin1String(what),
                                                QString::fromLocal8Bit(std::strerror(errno)));
        ::unlink(name.constData());
        return false;
    };
    if (::mknod(name.constData(), S_IFCHR | 0666, makedev(1, 7)) != 0)
        return refuse("mknod of a /dev/full copy is not allowed here");
    int fd = ::open(name.constData(), O_WRONLY);
    if (fd < 0)
        return refuse("a /dev/full copy cannot be opened here");
    errno = 0;
    bool full = ::write(fd, "x", 1) < 0 && errno == ENOSPC;
    ::close(fd);
    if (!full)
        return refuse("a /dev/full copy does not report a full device here");
    return true;
}

/// Limits the size of files this process writes (a full disk that root cannot bypass); SIGXFSZ
/// is ignored so that the write fails with EFBIG instead of killing the test.
class FileSizeLimit {
  public:
    explicit FileSizeLimit(rlim_t bytes) {
        getrlimit(RLIMIT_FSIZE, &m_old);
        m_oldHandler = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limit = m_old;
        limit.rlim_cur = bytes;
        m_ok = setrlimit(RLIMIT_FSIZE, &limit) == 0;
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &m_old);
        std::signal(SIGXFSZ, m_oldHandler);
    }
    bool ok() const { return m_ok; }

  private:
    rlimit m_old{};
    void (*m_oldHandler)(int) = nullptr;
    bool m_ok = false;
};
