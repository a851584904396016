#include "app/ToolConfig.h"

#include "core/ConfigParser.h"
#include "calib/session/Session.h"

#include <opencv2/core/utils/logger.hpp>

#include <filesystem>
#include <iostream>

namespace omnitune {

void quietOpenCvLogs() { cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_ERROR); }

std::optional<Config> loadToolConfig(const std::optional<std::string>& configPath, const std::string& inputPath,
                                     const std::optional<std::string>& algorithm, std::string& error)
{
    std::string path;
    if (configPath) {
        path = *configPath;
    } else {
        const auto candidate = std::filesystem::path(inputPath) / kSessionConfigFile;
        std::error_code ec;
        if (!std::filesystem::exists(candidate, ec)) {  // anything else there: loadConfig says what is wrong
            error = "no --config given and " + inputPath + " holds no " + std::string(kSessionConfigFile);
            return std::nullopt;
        }
        path = candidate.string();
    }
    ConfigLoad load = loadConfig(path);
    for (const auto& w : load.warnings) std::cerr << "warning: " << w.toString() << "\n";
    if (!load.ok()) {
        error = load.error->toString();
        return std::nullopt;
    }
    if (algorithm) {
        const auto a = parseAlgorithm(*algorithm);
        if (!a) {
            error = "--algorithm must be specific, opencv or combined, not '" + *algorithm + "'";
            return std::nullopt;
        }
        load.config.algorithm = *a;
    }
    return load.config;
}

}  // namespace omnitune
