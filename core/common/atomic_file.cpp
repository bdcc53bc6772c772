#include "common/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace chaplygin {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what, int err) {
    throw IoError("cannot write '" + path + "': " + what +
                  (err ? std::string(": ") + std::strerror(err) : ""));
}

bool writeAll(int fd, const std::string& content) {
    const char* p = content.data();
    std::size_t left = content.size();
    while (left > 0) {
        ssize_t n = ::write(fd, p, left);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    return true;
}

} // namespace

void writeFileAtomically(const std::string& path, const std::string& content) {
    if (path == "-") {
        if (std::fwrite(content.data(), 1, content.size(), stdout) != content.size() ||
            std::fflush(stdout) != 0)
            fail("standard output", "short write", errno);
        return;
    }
    if (path.empty())
        throw IoError("cannot write: the file name is empty");
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
        if (S_ISDIR(st.st_mode))
            fail(path, "it is a directory", 0);
        // a device or a pipe (/dev/stdout, a FIFO): it cannot be replaced, so write in place
        int fd = ::open(path.c_str(), O_WRONLY);
        if (fd < 0)
            fail(path, "cannot open", errno);
        errno = 0;
        bool ok = writeAll(fd, content);
        int err = errno;
        if (::close(fd) != 0 && ok) {
            ok = false;
            err = errno;
        }
        if (!ok)
            fail(path, "short write", err == 0 ? ENOSPC : err);
        return;
    }
    std::string tmp = path + ".tmp-XXXXXX";
    int fd = ::mkstemp(tmp.data());
    if (fd < 0)
        fail(path, "cannot create a temporary file beside it", errno);
    auto abandon = [&](const std::string& what) {
        int err = errno;
        ::close(fd);
        ::unlink(tmp.c_str());
        fail(path, what, err == 0 ? ENOSPC : err);
    };
    errno = 0;
    if (!writeAll(fd, content))
        abandon("short write (disk full?)");
    if (::fsync(fd) != 0)
        abandon("fsync failed");
    ::fchmod(fd, 0644);
    if (::close(fd) != 0) {
        int err = errno;
        ::unlink(tmp.c_str());
        fail(path, "close failed", err);
    }
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        int err = errno;
        ::unlink(tmp.c_str());
        fail(path, "rename failed", err);
    }
}

} // namespace chaplygin
