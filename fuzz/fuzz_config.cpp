// config.yml text -> parseConfig (the loader's pure part; loadConfig only adds reading the file
// and the mask image). Every input either loads or fails with a message naming the file, and
// a config that loads saves to text that loads back to the same text.
#include "FuzzCheck.h"

#include "core/ConfigParser.h"
#include "core/ConfigWriter.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    const omnitune::ConfigLoad load = omnitune::parseConfig(text, "fuzz.yml");
    if (!load.ok()) {
        const std::string message = load.error->toString();
        FUZZ_CHECK(message.find("fuzz.yml") != std::string::npos, "an error names the file");
        FUZZ_CHECK(!load.error->message.empty(), "an error says what is wrong");
        return 0;
    }
    const std::string saved = omnitune::serializeConfig(load.config);
    const omnitune::ConfigLoad again = omnitune::parseConfig(saved, "saved.yml");
    FUZZ_CHECK(again.ok(), "a loaded config saves to text that loads");
    FUZZ_CHECK(omnitune::serializeConfig(again.config) == saved, "save -> load -> save gives the same text");
    return 0;
}
