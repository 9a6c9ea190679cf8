#include "util/output_file.h"

#include "util/error.h"
#include "util/interrupt.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace tp {

namespace {

// Writes all of `bytes` to `target` (created or truncated where it is a regular file), then
// closes it; on failure returns the errno of the step that failed, else 0.
int write_all(const std::string& target, std::string_view bytes, bool create) {
    const int fd = create ? ::open(target.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666)
                          : ::open(target.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) return errno;
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int e = n < 0 ? errno : EIO;
            ::close(fd);
            return e;
        }
        done += size_t(n);
    }
    // close() reports what the file system deferred (NFS, quota); a regular file is also
    // flushed first, so that a full disk shows up here and not after the rename.
    if (create && ::fsync(fd) != 0 && errno != EINVAL) {
        const int e = errno;
        ::close(fd);
        return e;
    }
    return ::close(fd) != 0 ? errno : 0;
}

} // namespace

void write_output_file(const std::string& path, std::string_view bytes) {
    const OutputWriteScope writing; // a second SIGINT/SIGTERM waits for the end (interrupt.h)
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
        if (S_ISDIR(st.st_mode)) runtime_error("cannot write {}: it is a directory", path);
        if (const int e = write_all(path, bytes, false))
            runtime_error("cannot write {}: {}", path, std::strerror(e));
        return;
    }
    const std::string tmp = path + ".partial";
    if (const int e = write_all(tmp, bytes, true)) {
        std::remove(tmp.c_str());
        runtime_error("cannot write {}: {}", path, std::strerror(e));
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const int e = errno;
        std::remove(tmp.c_str());
        runtime_error("cannot write {}: {}", path, std::strerror(e));
    }
}

} // namespace tp
