#include "core/AtomicFile.h"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#ifdef OMNITUNE_FAULT_INJECTION
#include <cstdlib>
#include <map>
#endif

namespace omnitune {

namespace {

namespace fs = std::filesystem;

std::string errnoText(int e) { return std::strerror(e); }

// A save through a symbolic link replaces the file the link points at, never the link itself
// (a session's config.yml may link to the one the robot loads).
std::string followLinks(const std::string& path)
{
    std::error_code ec;
    if (!fs::is_symlink(path, ec)) return path;
    const fs::path target = fs::weakly_canonical(path, ec);
    return ec ? path : target.string();
}

std::string folderOf(const std::string& path)
{
    const fs::path parent = fs::path(path).parent_path();
    return parent.empty() ? std::string(".") : parent.string();
}

#ifdef OMNITUNE_FAULT_INJECTION
// Test builds only (tests/CMakeLists.txt compiles this file a second time with the define):
// OMNITUNE_FAULT_STOP=point:n ends the process at the n-th pass through `point`, as a kill
// would; OMNITUNE_FAULT_FAIL=point[:n][,point[:n]...] makes the system call there fail (ENOSPC).
bool faultHit(const char* variable, const std::string& point)
{
    static std::map<std::string, int> passes;
    const char* want = std::getenv(variable);
    if (!want) return false;
    std::stringstream specs(want);
    bool counted = false;
    for (std::string spec; std::getline(specs, spec, ',');) {
        const auto colon = spec.find(':');
        if (spec.substr(0, colon) != point) continue;
        if (colon == std::string::npos) return true;
        if (!counted) ++passes[std::string(variable) + point];
        counted = true;
        if (passes[std::string(variable) + point] == std::atoi(spec.c_str() + colon + 1)) return true;
    }
    return false;
}
void stopPoint(const char* point)
{
    if (faultHit("OMNITUNE_FAULT_STOP", point)) ::_exit(86);
}
bool failPoint(const char* point) { return faultHit("OMNITUNE_FAULT_FAIL", point); }
#else
void stopPoint(const char*) {}
bool failPoint(const char*) { return false; }
#endif

// Writes all of `bytes` to `fd`; 0 or the errno of the failure.
int writeAll(int fd, const std::string& bytes)
{
    if (failPoint("write")) return ENOSPC;
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        done += std::size_t(n);
    }
    return 0;
}

// Creates a temporary of a name no other save uses: FILE.<pid>-<n>.tmp (".tmp" last, so the
// session reader and users recognise a leftover).
int createTemp(const std::string& path, std::string& temp)
{
    static std::atomic<unsigned> counter{0};
    for (int attempt = 0; attempt < 100; ++attempt) {
        temp = path + "." + std::to_string(::getpid()) + "-" + std::to_string(++counter) + ".tmp";
        const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
        if (fd >= 0 || errno != EEXIST) return fd;
    }
    errno = EEXIST;
    return -1;
}

// The backup rule of AtomicFile.h: FILE.bak made once, from the file about to be replaced.
std::optional<std::string> keepFirstBackup(const std::string& path)
{
    const std::string backup = path + ".bak";
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;  // nothing to keep
    if (::lstat(backup.c_str(), &st) == 0) return std::nullopt;                          // the first backup stays
    if (failPoint("link")) errno = EPERM;  // what a file system without hard links says
    else if (::link(path.c_str(), backup.c_str()) == 0) return std::nullopt;
    if (errno == EEXIST) return std::nullopt;  // another save made it a moment ago
    // No hard links here (a FAT-formatted stick): copy through a temporary of its own.
    std::ifstream in(path, std::ios::binary);
    std::stringstream old;
    old << in.rdbuf();
    if (!in) return "cannot read " + path + " to keep it as " + backup;
    StagedFile copy(backup, old.str());
    if (copy.error()) return "cannot keep the backup: " + *copy.error();
    return copy.commit(false);
}

}  // namespace

StagedFile::StagedFile(std::string path, const std::string& bytes) : path_(followLinks(path))
{
    const int fd = createTemp(path_, temp_);
    if (fd < 0) {
        error_ = "cannot create " + temp_ + ": " + errnoText(errno);
        temp_.clear();
        return;
    }
    int fault = writeAll(fd, bytes);
    if (fault == 0 && ::fsync(fd) != 0) fault = errno;
    if (::close(fd) != 0 && fault == 0) fault = errno;
    if (fault != 0) {
        error_ = "cannot write " + temp_ + ": " + errnoText(fault);
        ::unlink(temp_.c_str());
        temp_.clear();
        return;
    }
    stopPoint("staged");
}

StagedFile::~StagedFile()
{
    if (!temp_.empty()) ::unlink(temp_.c_str());
}

std::optional<std::string> StagedFile::commit(bool keepBackup)
{
    if (error_) return error_;
    if (temp_.empty()) return "nothing staged for " + path_;
    stopPoint("commit");
    if (keepBackup) {
        if (auto err = keepFirstBackup(path_)) return err;
        stopPoint("backup");
    }
    if (::rename(temp_.c_str(), path_.c_str()) != 0) return "cannot replace " + path_ + ": " + errnoText(errno);
    temp_.clear();  // the old file or the new one, whole, even after a power cut: never a mix
    return std::nullopt;
}

FolderSaveLock::FolderSaveLock(const std::string& file)
{
    const std::string folder = folderOf(followLinks(file));
    fd_ = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd_ < 0) return;  // no lock to take: the write itself will report why the folder is unusable
    // Saves take milliseconds; a holder that keeps the lock this long is stuck or saving a lot.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        if (errno != EWOULDBLOCK && errno != EINTR) return;  // no locking on this file system
        if (std::chrono::steady_clock::now() > deadline) {
            error_ = "another program has been saving into " + folder +
                     " for 5 s and still is; nothing was written, try again";
            ::close(fd_);
            fd_ = -1;
            return;
        }
        const timespec pause{0, 10'000'000};
        ::nanosleep(&pause, nullptr);
    }
}

FolderSaveLock::~FolderSaveLock()
{
    if (fd_ >= 0) ::close(fd_);  // closing releases the flock
}

std::optional<std::string> writeFileAtomically(const std::string& path, const std::string& bytes, bool keepBackup)
{
    const FolderSaveLock lock(path);
    if (lock.error()) return "cannot save " + path + ": " + *lock.error();
    StagedFile staged(path, bytes);
    return staged.commit(keepBackup);
}

}  // namespace omnitune
