#include "core/YamlText.h"

#include <regex>

namespace omnitune {

std::optional<YamlParseError> openYamlText(const std::string& text, cv::FileStorage& fs)
{
    const bool hasDirective = text.rfind("%YAML", 0) == 0;
    try {
        fs.open(hasDirective ? text : "%YAML:1.0\n" + text,
                cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
    } catch (const cv::Exception& e) {
        // OpenCV's parse errors read "...(line): message" in several shapes.
        YamlParseError err{0, e.err};
        std::smatch m;
        const std::string msg = e.msg;
        if (std::regex_search(msg, m, std::regex(R"(\((\d+)\): ([^\n]*))"))) {
            err.line = std::max(0, std::stoi(m[1]) - (hasDirective ? 0 : 1));
            err.message = m[2];
        }
        return err;
    } catch (const std::exception& e) {
        // OpenCV's parser lets std::length_error out on some malformed keys (" n:1\n :",
        // found by fuzz/fuzz_config); any escape would end the program.
        return YamlParseError{0, std::string("the YAML parser gave up (") + e.what() + ")"};
    }
    if (!fs.isOpened()) return YamlParseError{0, "not YAML"};
    return std::nullopt;
}

std::size_t findUnsavableCharacter(const std::string& value)
{
    for (std::size_t i = 0; i < value.size(); ++i) {
        const auto c = static_cast<unsigned char>(value[i]);
        if (c < 0x20 && c != '\t' && c != '\n' && c != '\r') return i;
    }
    return std::string::npos;
}

}  // namespace omnitune
