#include "core/RegularFile.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace omnitune {

namespace {

std::optional<std::string> notRegular(mode_t mode)
{
    if (S_ISREG(mode)) return std::nullopt;
    const char* what = S_ISDIR(mode)    ? "a folder"
                       : S_ISFIFO(mode) ? "a FIFO (named pipe)"
                       : S_ISSOCK(mode) ? "a socket"
                       : S_ISCHR(mode) || S_ISBLK(mode) ? "a device"
                                                        : "a special file";
    return std::string("is ") + what + ", not a regular file";
}

std::string openError(int e) { return e == ENOENT ? "no such file" : std::string("cannot be opened: ") + std::strerror(e); }

}  // namespace

std::optional<std::string> checkRegularFile(const std::string& path)
{
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return openError(errno);
    return notRegular(st.st_mode);
}

std::optional<std::string> readRegularFile(const std::string& path, std::size_t maxBytes, std::string& why)
{
    // O_NONBLOCK: opening a FIFO must not wait for a writer; fstat then refuses it.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        why = openError(errno);
        return std::nullopt;
    }
    struct stat st {};
    std::optional<std::string> fault;
    if (::fstat(fd, &st) != 0) fault = std::string("cannot be read: ") + std::strerror(errno);
    else fault = notRegular(st.st_mode);
    if (!fault && std::size_t(st.st_size) > maxBytes)
        fault = "is " + std::to_string(st.st_size / 1024) + " KiB; files of this kind are at most " +
                std::to_string(maxBytes / 1024) + " KiB";
    std::string text;
    if (!fault) {
        text.resize(std::size_t(st.st_size));
        std::size_t done = 0;
        while (done < text.size()) {
            const ssize_t n = ::read(fd, text.data() + done, text.size() - done);
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) {
                fault = std::string("cannot be read: ") + std::strerror(errno);
                break;
            }
            if (n == 0) break;  // shrank while being read
            done += std::size_t(n);
        }
        text.resize(done);
    }
    ::close(fd);
    if (fault) {
        why = *fault;
        return std::nullopt;
    }
    return text;
}

}  // namespace omnitune
