#include "core/LutFile.h"

#include "core/AtomicFile.h"
#include "core/RegularFile.h"

#include <algorithm>

namespace omnitune {

namespace {

constexpr char kMagic[8] = {'O', 'T', 'L', 'U', 'T', '\r', '\n', '\x1a'};
constexpr std::uint32_t kVersion = 1;
// A table of 8 bits (16 MiB) with 15 long names and the header stays below this.
constexpr std::size_t kMaxLutBytes = (std::size_t(1) << 24) + 4096;

std::uint32_t fnv1a(const std::string& bytes, std::size_t n)
{
    std::uint32_t h = 2166136261u;
    for (std::size_t i = 0; i < n; ++i) {
        h ^= std::uint8_t(bytes[i]);
        h *= 16777619u;
    }
    return h;
}

void putU32(std::string& out, std::uint32_t v)
{
    for (int i = 0; i < 4; ++i) out += char((v >> (8 * i)) & 0xFF);
}

// Reads the file front to back; every read says whether the bytes were there.
struct Cursor {
    const std::string& bytes;
    std::size_t at = 0;
    bool u32(std::uint32_t& v)
    {
        if (bytes.size() - at < 4) return false;
        v = 0;
        for (int i = 0; i < 4; ++i) v |= std::uint32_t(std::uint8_t(bytes[at + std::size_t(i)])) << (8 * i);
        at += 4;
        return true;
    }
    bool u8(std::uint8_t& v)
    {
        if (at >= bytes.size()) return false;
        v = std::uint8_t(bytes[at++]);
        return true;
    }
};

}  // namespace

LutFile lutFileOf(const ColorLutOptions& options)
{
    const ColorLut lut(options);
    LutFile f;
    f.bits = options.bits;
    f.blackRelative = options.blackRelative;
    f.classes = options.classes;
    for (ColourClassDef& c : f.classes) c.boxes.clear();
    f.table = lut.bgrTable();
    return f;
}

std::string encodeLutFile(const LutFile& lut)
{
    std::string out(kMagic, sizeof kMagic);
    putU32(out, kVersion);
    putU32(out, std::uint32_t(lut.bits));
    putU32(out, std::uint32_t(lut.table.size()));
    putU32(out, lut.blackRelative ? 1u : 0u);
    putU32(out, std::uint32_t(lut.classes.size()));
    for (const ColourClassDef& c : lut.classes) {
        out += char(c.role);
        for (std::uint8_t v : c.display) out += char(v);
        out += char(std::min<std::size_t>(c.name.size(), 255));
        out += c.name.substr(0, 255);
    }
    out.append(reinterpret_cast<const char*>(lut.table.data()), lut.table.size());
    putU32(out, fnv1a(out, out.size()));
    return out;
}

LutFileLoad decodeLutFile(const std::string& bytes, const std::string& fileName)
{
    LutFileLoad out;
    auto fail = [&](FileIssueKind kind, const std::string& message) {
        out.error = FileIssue{kind, fileName, 0, "", message};
        return out;
    };
    if (bytes.size() < sizeof kMagic || bytes.compare(0, sizeof kMagic, kMagic, sizeof kMagic) != 0)
        return fail(FileIssueKind::ParseError, "not an OmniTune LUT file (no OTLUT magic at the start)");
    if (bytes.size() < sizeof kMagic + 4)
        return fail(FileIssueKind::ParseError, "the file ends inside its header: it was cut short");
    // The checksum first: a flipped byte anywhere is reported as such, not as whatever field it hit.
    const std::size_t body = bytes.size() - 4;
    Cursor tail{bytes, body};
    std::uint32_t stored = 0;
    if (!tail.u32(stored) || stored != fnv1a(bytes, body))
        return fail(FileIssueKind::ParseError,
                    "the checksum does not match: the file is damaged or cut short (" + std::to_string(bytes.size()) +
                        " bytes)");
    Cursor in{bytes, sizeof kMagic};
    std::uint32_t version = 0, bits = 0, entries = 0, flags = 0, count = 0;
    if (!in.u32(version) || !in.u32(bits) || !in.u32(entries) || !in.u32(flags) || !in.u32(count))
        return fail(FileIssueKind::ParseError, "the file ends inside its header: it was cut short");
    if (version != kVersion)
        return fail(FileIssueKind::UnknownFormat,
                    "LUT file version " + std::to_string(version) + "; this build reads version " + std::to_string(kVersion));
    if (bits < 4 || bits > 8) return fail(FileIssueKind::OutOfRange, "bits " + std::to_string(bits) + " is outside 4..8");
    if (entries != (1u << (3 * bits)))
        return fail(FileIssueKind::ParseError, "entry count " + std::to_string(entries) + " does not match " +
                                                   std::to_string(bits) + " bits (" + std::to_string(1u << (3 * bits)) + ")");
    if (count > std::uint32_t(kMaxColourClasses))
        return fail(FileIssueKind::OutOfRange, std::to_string(count) + " classes; at most " + std::to_string(kMaxColourClasses));
    out.lut.bits = int(bits);
    out.lut.blackRelative = flags & 1u;
    for (std::uint32_t i = 0; i < count; ++i) {
        ColourClassDef c;
        std::uint8_t role = 0, length = 0;
        if (!in.u8(role) || !in.u8(c.display[0]) || !in.u8(c.display[1]) || !in.u8(c.display[2]) || !in.u8(length) ||
            body - in.at < length)
            return fail(FileIssueKind::ParseError, "the file ends inside its class names: it was cut short");
        if (role >= kColourRoles.size()) return fail(FileIssueKind::BadValue, "class " + std::to_string(i) + " has an unknown role");
        c.role = ColourRole(role);
        c.name = bytes.substr(in.at, length);
        in.at += length;
        out.lut.classes.push_back(std::move(c));
    }
    if (body - in.at != entries)
        return fail(FileIssueKind::ParseError, "the table holds " + std::to_string(body - in.at) + " bytes where " +
                                                   std::to_string(entries) + " belong");
    out.lut.table.assign(bytes.begin() + std::ptrdiff_t(in.at), bytes.begin() + std::ptrdiff_t(body));
    for (std::uint8_t id : out.lut.table)
        if (id > count) return fail(FileIssueKind::BadValue, "the table names class " + std::to_string(id) + " of " + std::to_string(count));
    return out;
}

std::optional<FileIssue> saveLutFile(const LutFile& lut, const std::string& path)
{
    if (auto err = writeFileAtomically(path, encodeLutFile(lut), false))
        return FileIssue{FileIssueKind::WriteError, path, 0, "", *err};
    return std::nullopt;
}

LutFileLoad loadLutFile(const std::string& path)
{
    std::string why;
    const auto bytes = readRegularFile(path, kMaxLutBytes, why);
    if (!bytes) {
        LutFileLoad out;
        out.error = FileIssue{FileIssueKind::FileUnreadable, path, 0, "", why};
        return out;
    }
    return decodeLutFile(*bytes, path);
}

}  // namespace omnitune
