#include "calib/eval/OutputFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

namespace omnitune {

namespace {

constexpr std::size_t kBufferBytes = 64 * 1024;

// Unique per process and call, so two runs writing the same file never share a temporary.
std::string temporaryNameFor(const std::string& path)
{
    static std::atomic<unsigned> counter{0};
    return path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

}  // namespace

std::optional<OutputFile> OutputFile::open(const std::string& path, bool durable, std::string& error)
{
    OutputFile out;
    out.name_ = path;
    out.durable_ = durable;
    out.ownsFd_ = true;
    struct stat st {};
    const bool exists = ::stat(path.c_str(), &st) == 0;
    if (exists && S_ISDIR(st.st_mode)) {
        error = path + ": is a folder, not a file";
        return std::nullopt;
    }
    if (exists && !S_ISREG(st.st_mode)) {  // a device, FIFO or socket: no rename over it
        out.fd_ = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    } else {
        out.temp_ = temporaryNameFor(path);
        out.fd_ = ::open(out.temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    }
    if (out.fd_ < 0) {
        const int e = errno;
        out.temp_.clear();  // nothing was created
        error = "cannot write " + path + ": " + std::strerror(e);
        return std::nullopt;
    }
    return std::optional<OutputFile>(std::move(out));
}

OutputFile OutputFile::standardOutput()
{
    OutputFile out;
    out.name_ = "standard output";
    out.fd_ = STDOUT_FILENO;
    return out;
}

OutputFile::OutputFile(OutputFile&& other) noexcept
    : name_(std::move(other.name_)),
      temp_(std::exchange(other.temp_, std::string())),
      fd_(std::exchange(other.fd_, -1)),
      ownsFd_(std::exchange(other.ownsFd_, false)),
      durable_(other.durable_),
      buffer_(std::move(other.buffer_)),
      failed_(std::move(other.failed_))
{
}

OutputFile::~OutputFile()
{
    if (ownsFd_ && fd_ >= 0) ::close(fd_);
    if (!temp_.empty()) ::unlink(temp_.c_str());
}

std::optional<std::string> OutputFile::failure(const std::string& what, int osError)
{
    failed_ = name_ + ": " + what + ": " + std::strerror(osError) +
              (temp_.empty() ? "" : "; " + name_ + " is left as it was");
    return failed_;
}

std::optional<std::string> OutputFile::flush()
{
    std::size_t done = 0;
    while (done < buffer_.size()) {
        const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return failure("writing failed", n < 0 ? errno : ENOSPC);
        done += std::size_t(n);
    }
    buffer_.clear();
    return std::nullopt;
}

std::optional<std::string> OutputFile::write(std::string_view bytes)
{
    if (failed_) return failed_;
    if (fd_ < 0) return failed_ = name_ + ": already closed";
    buffer_.append(bytes);
    if (buffer_.size() >= kBufferBytes) return flush();
    return std::nullopt;
}

std::optional<std::string> OutputFile::commit()
{
    if (failed_) return failed_;
    if (fd_ < 0) return failed_ = name_ + ": already closed";
    if (auto err = flush()) return err;
    if (temp_.empty()) {
        // A device or standard output: the data went out with write(); nothing to rename.
        if (ownsFd_ && ::close(std::exchange(fd_, -1)) != 0) return failure("closing failed", errno);
        fd_ = -1;
        return std::nullopt;
    }
    if (durable_ && ::fsync(fd_) != 0) return failure("flushing to disk failed", errno);
    if (::close(std::exchange(fd_, -1)) != 0) return failure("closing failed", errno);
    if (::rename(temp_.c_str(), name_.c_str()) != 0) return failure("renaming the finished file into place failed", errno);
    temp_.clear();
    return std::nullopt;
}

}  // namespace omnitune
