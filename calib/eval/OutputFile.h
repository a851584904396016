#pragma once
// A file a tool writes as it goes (the detection CSV, stage images), where a full disk or a
// read-only folder must never pass for success: every write is checked, and a failure names
// the file and the OS reason ("out.csv: No space left on device").
//
// A regular file (or a new one) is written to a temporary file beside it and renamed over it
// by commit(), so a failed or interrupted run leaves the previous file as it was; the
// temporary is removed when the writer goes away uncommitted. A device or pipe (/dev/stdout,
// a FIFO) is written straight through, and standardOutput() writes file descriptor 1.
#include <optional>
#include <string>
#include <string_view>

namespace omnitune {

class OutputFile {
public:
    // Opens `path` for writing; on failure returns nothing and sets `error`. `durable`: commit()
    // flushes the data to the disk (fsync) before the rename, for results worth a little time.
    static std::optional<OutputFile> open(const std::string& path, bool durable, std::string& error);
    static OutputFile standardOutput();

    OutputFile(OutputFile&& other) noexcept;
    OutputFile& operator=(OutputFile&&) = delete;
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;
    ~OutputFile();  // removes the temporary file unless committed

    // Buffers `bytes`; a failure (now or of an earlier buffered write) is the message.
    std::optional<std::string> write(std::string_view bytes);
    // Writes what is buffered, then (for a temporary) flushes, closes and renames it over the
    // target. After a failure the target is as it was before open().
    std::optional<std::string> commit();

    const std::string& name() const { return name_; }

private:
    OutputFile() = default;
    std::optional<std::string> flush();
    std::optional<std::string> failure(const std::string& what, int osError);

    std::string name_;  // the target, or "standard output"
    std::string temp_;  // empty when writing straight to the target
    int fd_ = -1;
    bool ownsFd_ = false;
    bool durable_ = false;
    std::string buffer_;
    std::optional<std::string> failed_;  // the first failure; every later call repeats it
};

}  // namespace omnitune
