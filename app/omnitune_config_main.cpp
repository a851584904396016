// omnitune-config: check a config.yml, upgrade it to the current schema, print the defaults,
// or print the schema reference.
#include "core/ConfigParser.h"
#include "core/ConfigSchema.h"
#include "core/ConfigWriter.h"
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
    for (const auto& w : load.warnings) std::cerr << "added: " << w.toString() << "\n";
    if (const auto err = omnitune::saveConfig(load.config, path)) {
        std::cerr << "error: " << err->toString() << "\n";
        return 1;
    }
    std::cout << path << ": written with every key of schema " << omnitune::kConfigSchemaVersion << " (" << path << ".bak holds the file from before OmniTune first saved it)\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc == 3 && std::strcmp(argv[1], "--check") == 0) return check(argv[2]);
    if (argc == 3 && std::strcmp(argv[1], "--upgrade") == 0) return upgrade(argv[2]);
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
