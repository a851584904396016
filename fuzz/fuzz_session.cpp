// session.yml and truth.csv, the two text files of a session folder, through their pure
// parsers. One input holds both: the bytes before the first NUL are session.yml, the rest
// truth.csv (an input without NUL goes to both). Every input parses or fails with a message
// naming the file, and what parses serializes to text that parses back to the same.
#include "FuzzCheck.h"

#include "calib/session/Session.h"
#include "calib/session/TruthCsv.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace {

void sessionInfo(const std::string& text)
{
    const omnitune::SessionInfoParse parse = omnitune::parseSessionInfo(text, "session.yml");
    if (!parse.ok()) {
        FUZZ_CHECK(parse.error->toString().find("session.yml") != std::string::npos, "an error names the file");
        FUZZ_CHECK(!parse.error->message.empty(), "an error says what is wrong");
        return;
    }
    const std::string saved = omnitune::serializeSessionInfo(parse.info);
    const omnitune::SessionInfoParse again = omnitune::parseSessionInfo(saved, "saved.yml");
    FUZZ_CHECK(again.ok(), "a parsed session.yml serializes to text that parses");
    FUZZ_CHECK(omnitune::serializeSessionInfo(again.info) == saved, "serialize -> parse -> serialize is stable");
}

void truthCsv(const std::string& text)
{
    const omnitune::TruthParse parse = omnitune::parseTruthCsv(text, "truth.csv");
    if (!parse.ok()) {
        FUZZ_CHECK(parse.error->toString().find("truth.csv") != std::string::npos, "an error names the file");
        FUZZ_CHECK(!parse.error->message.empty(), "an error says what is wrong");
        return;
    }
    const std::string saved = omnitune::serializeTruthCsv(parse.rows);
    const omnitune::TruthParse again = omnitune::parseTruthCsv(saved, "saved.csv");
    FUZZ_CHECK(again.ok(), "parsed truth rows serialize to text that parses");
    FUZZ_CHECK(again.rows.size() == parse.rows.size(), "every row survives serialize -> parse");
    FUZZ_CHECK(omnitune::serializeTruthCsv(again.rows) == saved, "serialize -> parse -> serialize is stable");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::size_t nul = input.find('\0');
    if (nul == std::string::npos) {
        sessionInfo(input);
        truthCsv(input);
        return 0;
    }
    sessionInfo(input.substr(0, nul));
    truthCsv(input.substr(nul + 1));
    return 0;
}
