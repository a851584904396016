#include "app/ColourProfileCommand.h"

#include "calib/colour/ColourProfile.h"
#include "core/ConfigParser.h"
#include "core/ConfigWriter.h"

#include <filesystem>
#include <iostream>

namespace omnitune {

namespace {

int fail(const std::string& why)
{
    std::cerr << "omnitune-calibrate: " << why << "\n";
    return 1;
}

}  // namespace

bool wantsColourProfile(const CommandLine& cl)
{
    return cl.has("profile-list") || cl.has("profile-save") || cl.has("profile-load");
}

int runColourProfile(const CommandLine& cl)
{
    if (int(cl.has("profile-list")) + int(cl.has("profile-save")) + int(cl.has("profile-load")) > 1)
        return fail("give one of --profile-list, --profile-save and --profile-load");
    const auto configPath = cl.value("config");
    if (!configPath) return fail("the profiles live beside a config: give --config CONFIG.yml");
    const std::string folder = colourProfileFolder(*configPath);

    if (cl.has("profile-list")) {
        const auto entries = listColourProfiles(folder);
        if (entries.empty()) std::cout << "no colour profiles in " << folder << "\n";
        for (const ColourProfileEntry& e : entries) {
            if (e.error)
                std::cout << std::filesystem::path(e.path).filename().string() << "  (does not load: "
                          << e.error->toString() << ")\n";
            else
                std::cout << e.name << "  " << e.path << "\n";
        }
        return 0;
    }

    const ConfigLoad load = loadConfig(*configPath);
    if (!load.ok()) return fail(load.error->toString());
    for (const auto& w : load.warnings) std::cerr << "warning: " << w.toString() << "\n";

    if (cl.has("profile-save")) {
        const std::string name = *cl.value("profile-save");
        const ColourProfileSave saved = saveColourProfile(folder, ColourProfile{name, load.config.colors});
        if (saved.error) return fail(saved.error->toString());
        std::cout << "saved the colours of " << *configPath << " as profile \"" << name << "\": " << saved.path << "\n";
        return 0;
    }

    const std::string name = *cl.value("profile-load");
    const auto file = colourProfileFileName(name);
    if (!file) return fail("the profile name \"" + name + "\" has no letter or digit");
    const std::string path = (std::filesystem::path(folder) / *file).string();
    const ColourProfileLoad profile = loadColourProfile(path);
    if (!profile.ok()) return fail(profile.error->toString());
    for (const auto& w : profile.warnings) std::cerr << "warning: " << w.toString() << "\n";
    const auto out = cl.value("out");
    if (!out) return fail("--profile-load writes the config with the profile's colours: give --out OUT.yml");
    Config next = load.config;
    next.colors = profile.profile.colors;
    next.colors.sampleOutlierPct = load.config.colors.sampleOutlierPct;  // the sampling setting, not the venue's
    const bool existed = std::filesystem::exists(*out);
    if (const auto err = saveConfig(next, *out, true)) return fail(err->toString());
    std::cout << "wrote " << *out << " with the colours of profile \"" << profile.profile.name << "\" (" << path << ")"
              << (existed ? "; " + *out + ".bak keeps the file from before OmniTune first saved over it" : std::string())
              << "\n";
    return 0;
}

}  // namespace omnitune
