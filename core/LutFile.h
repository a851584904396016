#pragma once
// The compiled BGR colour table as a binary file (omnitune-config --export-lut), for a robot that
// wants the table without compiling it from config.yml. Little-endian layout:
//
//   "OTLUT\r\n\x1a"            8 bytes magic (the \r\n and ^Z catch text-mode mangling)
//   u32 version (1)            u32 bits (4..8)            u32 entries (2^(3*bits))
//   u32 flags (bit 0: black_relative; the table then holds black up to the black boxes' V max,
//       as ColorLut::classifyBgr does without a frame's carpet)
//   u32 class count (0..15), then per class: u8 role, u8 B, u8 G, u8 R, u8 name length, name
//   entries bytes: class id per entry, index (b >> s) << 2*bits | (g >> s) << bits | (r >> s),
//       s = 8 - bits (0 = unknown, 1..count = the classes in order)
//   u32 FNV-1a 32 of every byte before it
//
// The loader refuses a wrong magic, version, size or checksum, naming the file.
#include "core/ColorLut.h"
#include "core/FileIssue.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct LutFile {
    int bits = 6;
    bool blackRelative = false;
    ColourClasses classes;  // names, roles and display colours (boxes are not stored)
    std::vector<std::uint8_t> table;
};

// The compiled table of `options`.
LutFile lutFileOf(const ColorLutOptions& options);

std::string encodeLutFile(const LutFile& lut);

struct LutFileLoad {
    LutFile lut;
    std::optional<FileIssue> error;
    bool ok() const { return !error.has_value(); }
};
// `fileName` labels the messages.
LutFileLoad decodeLutFile(const std::string& bytes, const std::string& fileName);

// Atomic write (core/AtomicFile.h); the fault, or nothing.
std::optional<FileIssue> saveLutFile(const LutFile& lut, const std::string& path);
LutFileLoad loadLutFile(const std::string& path);

}  // namespace omnitune
