#pragma once
// Opening only regular files: a FIFO, a device or a folder where a config, mask, session.yml,
// truth.csv or frame belongs would block a reader for good (a FIFO waits for a writer) or read
// forever (/dev/zero). Every reader checks here first.
#include <cstddef>
#include <optional>
#include <string>

namespace omnitune {

// Why `path` is not a readable regular file ("no such file", "is a FIFO, not a regular file",
// ...), or nothing when it is one. Symbolic links are followed.
std::optional<std::string> checkRegularFile(const std::string& path);

// The whole content of the regular file `path` if it holds at most `maxBytes`; otherwise
// nothing, and `why` says what is wrong (as checkRegularFile, or too large, or a read error).
std::optional<std::string> readRegularFile(const std::string& path, std::size_t maxBytes, std::string& why);

}  // namespace omnitune
