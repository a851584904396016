// omnitune-config: check a config.yml, upgrade it to the current schema, print the defaults,
// or print the schema reference.
#include "core/ConfigParser.h"
#include "core/ConfigSchema.h"
#include "core/ConfigWriter.h"

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
    std::cout << path << ": OK (" << load.warnings.size() << " warning(s))\n";
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
