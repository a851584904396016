// omnitune-config: check a config.yml, upgrade it to the current schema, print the defaults,
// or print the schema reference.
#include "core/ConfigParser.h"
#include "core/ConfigSchema.h"
#include "core/ConfigWriter.h"
#include "core/LutFile.h"
#include "core/RingCoverage.h"

#include <cstdio>
#include <cstring>
#include <iostream>

namespace {

int usage()
{
    std::cerr << "usage: omnitune-config --check FILE   check a config, print its warnings and first error\n"
                 "       omnitune-config --upgrade FILE rewrite a config with every current key (missing ones\n"
                 "                                      get their defaults; FILE.bak keeps the file as it was\n"
                 "                                      before OmniTune first saved it, and is never overwritten)\n"
                 "                                      (old per-class colour keys become the list colors.classes)\n"
                 "       omnitune-config --export-lut CONFIG FILE\n"
                 "                                      write CONFIG's compiled BGR colour table to FILE (binary,\n"
                 "                                      with a header and a checksum; layout in core/LutFile.h)\n"
                 "       omnitune-config --check-lut FILE check a LUT file (size, version, checksum), print its classes\n"
                 "       omnitune-config --defaults     print a config.yml with every default\n"
                 "       omnitune-config --doc          print docs/config.md (the schema reference)\n";
    return 2;
}

int check(const char* path)
{
    const omnitune::ConfigLoad load = omnitune::loadConfig(path);
    for (const auto& w : load.warnings) std::cerr << "warning: " << w.toString() << "\n";
    if (!load.ok()) {
        std::cerr << "error: " << load.error->toString() << "\n";
        return 1;
    }
    std::size_t warnings = load.warnings.size();
    const double share = omnitune::ringShareInImage(load.config.geometry);
    if (share < omnitune::kRingMostlyOffImageShare) {
        char pct[16];
        std::snprintf(pct, sizeof pct, "%.0f", 100.0 * share);
        std::cerr << "warning: " << path << ": geometry: only " << pct
                  << " % of the processed ring (inner_radius to outer_radius around center_x, center_y) lies inside the "
                  << load.config.geometry.imageWidth << "x" << load.config.geometry.imageHeight
                  << " image: is the centre or a radius wrong?\n";
        ++warnings;
    }
    std::cout << path << ": OK (" << warnings << " warning(s))\n";
    return 0;
}

// A config from an older OmniTune lacks the newer keys: the loader warns on every load.
// Saving it through the writer adds them with their defaults and their comments.
int upgrade(const char* path)
{
    const omnitune::ConfigLoad load = omnitune::loadConfig(path);
    if (!load.ok()) {
        std::cerr << "error: " << load.error->toString() << "\n";
        return 1;
    }
    for (const auto& w : load.warnings)
        std::cerr << (w.kind == omnitune::ConfigIssueKind::OldForm ? "upgraded: " : "added: ") << w.toString() << "\n";
    if (const auto err = omnitune::saveConfig(load.config, path)) {
        std::cerr << "error: " << err->toString() << "\n";
        return 1;
    }
    std::cout << path << ": written with every key of schema " << omnitune::kConfigSchemaVersion << " (" << path << ".bak holds the file from before OmniTune first saved it)\n";
    return 0;
}

int exportLut(const char* configPath, const char* out)
{
    const omnitune::ConfigLoad load = omnitune::loadConfig(configPath);
    if (!load.ok()) {
        std::cerr << "error: " << load.error->toString() << "\n";
        return 1;
    }
    const omnitune::LutFile lut = omnitune::lutFileOf(load.config.colors);
    if (const auto err = omnitune::saveLutFile(lut, out)) {
        std::cerr << "error: " << err->toString() << "\n";
        return 1;
    }
    std::cout << out << ": " << lut.table.size() << " entries (" << lut.bits << " bits per channel), "
              << lut.classes.size() << " classes"
              << (lut.blackRelative ? "; black_relative: black is fixed at the black boxes' V max in the file "
                                      "(the frame's carpet is not known to a table)"
                                    : "")
              << "\n";
    return 0;
}

int checkLut(const char* path)
{
    const omnitune::LutFileLoad load = omnitune::loadLutFile(path);
    if (!load.ok()) {
        std::cerr << "error: " << load.error->toString() << "\n";
        return 1;
    }
    std::cout << path << ": OK, " << load.lut.bits << " bits, " << load.lut.table.size() << " entries, classes:";
    for (const auto& c : load.lut.classes) std::cout << " " << c.name << " (" << omnitune::colourRoleName(c.role) << ")";
    std::cout << "\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc == 3 && std::strcmp(argv[1], "--check") == 0) return check(argv[2]);
    if (argc == 3 && std::strcmp(argv[1], "--upgrade") == 0) return upgrade(argv[2]);
    if (argc == 4 && std::strcmp(argv[1], "--export-lut") == 0) return exportLut(argv[2], argv[3]);
    if (argc == 3 && std::strcmp(argv[1], "--check-lut") == 0) return checkLut(argv[2]);
    if (argc == 2 && std::strcmp(argv[1], "--defaults") == 0) {
        std::cout << omnitune::serializeConfig(omnitune::Config{});
        return 0;
    }
    if (argc == 2 && std::strcmp(argv[1], "--doc") == 0) {
        std::cout << omnitune::configSchemaMarkdown();
        return 0;
    }
    return usage();
}
