#include "app/ToolConfig.h"

#include "core/ConfigParser.h"
#include "calib/session/Session.h"
#include "calib/session/SessionReader.h"

#include <opencv2/core/utils/logger.hpp>

#include <filesystem>
#include <iostream>

namespace omnitune {

void quietOpenCvLogs() { cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_ERROR); }

std::optional<Config> loadToolConfig(const std::optional<std::string>& configPath, const std::string& inputPath,
                                     const std::optional<std::string>& algorithm, std::string& error,
                                     std::string* usedPath)
{
    std::string path;
    if (configPath) {
        path = *configPath;
    } else {
        // A session runs with the config SessionReader names (calib/session/SessionConfig.h),
        // the same one the window opens.
        namespace fs = std::filesystem;
        const fs::path input(inputPath);
        std::error_code ec;
        fs::path folder = input.filename() == kSessionInfoFile ? input.parent_path() : input;
        if (folder.empty()) folder = ".";  // --input session.yml from inside the session
        const bool isSession = fs::is_directory(folder, ec) && (fs::exists(folder / kSessionInfoFile, ec) ||
                                                                fs::is_directory(folder / kSessionFramesDir, ec));
        if (isSession) {
            const SessionOpen session = SessionReader::open(folder.string());
            if (!session.ok()) {
                error = session.error ? session.error->toString() : "cannot open the session " + inputPath;
                return std::nullopt;
            }
            path = session.reader->configPath();
            if (path.empty()) {
                error = "no --config given and the session " + inputPath + " has no config: " +
                        (session.reader->configIssue() ? session.reader->configIssue()->toString()
                                                                       : "no " + std::string(kSessionConfigFile) + " in it");
                return std::nullopt;
            }
        } else {
            error = "no --config given and " + inputPath + " is not a session folder with a " +
                    std::string(kSessionConfigFile);
            return std::nullopt;
        }
    }
    if (usedPath) *usedPath = path;
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
