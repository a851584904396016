#include "calib/session/Session.h"

#include "core/ConfigSchema.h"
#include "core/YamlText.h"

#include <opencv2/core.hpp>

#include <cstdio>
#include <ctime>
#include <functional>
#include <set>
#include <sstream>

namespace omnitune {

namespace {

std::string typeOf(const cv::FileNode& n) { return yamlTypeOf(n); }

std::string formatNumber(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// The config parser's helper (core/YamlText.h), in this file's words.
int lineOfKey(const std::string& text, const std::string& section, const std::string& key)
{
    return yamlLineOfKey(text, section.empty() ? key : section + "." + key);
}

// Reads a node into the info, or returns why not (the info is left unchanged).
using Reader = std::function<std::optional<SessionIssue>(const cv::FileNode&, SessionInfo&)>;

// One key of session.yml: where it lives, how to read it, and whether it must be there.
struct InfoKey {
    std::string section;  // "" or "camera"
    std::string name;
    bool required = true;
    Reader read;
};

SessionIssue keyIssue(SessionIssueKind kind, std::string message)
{
    return SessionIssue{kind, "", 0, "", std::move(message)};
}

Reader intKey(double min, double max, std::function<int&(SessionInfo&)> field)
{
    return [=](const cv::FileNode& n, SessionInfo& info) -> std::optional<SessionIssue> {
        if (!n.isInt()) return keyIssue(SessionIssueKind::WrongType, "expected an integer, found " + typeOf(n));
        const int v = int(n);
        if (v < min || v > max)
            return keyIssue(SessionIssueKind::OutOfRange,
                            std::to_string(v) + " is outside " + formatNumber(min) + ".." + formatNumber(max));
        field(info) = v;
        return std::nullopt;
    };
}

Reader infoIntKey(double min, double max, int SessionInfo::*member)
{
    return intKey(min, max, [member](SessionInfo& i) -> int& { return i.*member; });
}

// Camera settings take their ranges from the config schema, which owns them.
Reader cameraIntKey(const std::string& schemaPath, int CameraSettings::*member)
{
    const ConfigKey* k = findConfigKey(schemaPath);
    return intKey(k ? k->min : 0.0, k ? k->max : 1e9, [member](SessionInfo& i) -> int& { return i.camera.*member; });
}

// A rate in frames/s within [min, max]; min itself is refused when `minExcluded`.
Reader rateKey(double min, double max, bool minExcluded, std::function<double&(SessionInfo&)> field)
{
    return [=](const cv::FileNode& n, SessionInfo& info) -> std::optional<SessionIssue> {
        if (!n.isInt() && !n.isReal())
            return keyIssue(SessionIssueKind::WrongType, "expected a number, found " + typeOf(n));
        const double v = double(n);
        if (!(v >= min && v <= max) || (minExcluded && v == min))
            return keyIssue(SessionIssueKind::OutOfRange, formatNumber(v) + " frames/s is outside " +
                                                              (minExcluded ? "(" : "[") + formatNumber(min) + ".." +
                                                              formatNumber(max) + "]");
        field(info) = v;
        return std::nullopt;
    };
}

// The camera's rate takes its range from the config schema, like the other camera keys.
Reader cameraRateKey()
{
    const ConfigKey* k = findConfigKey("camera.frame_rate");
    return rateKey(k ? k->min : 0.0, k ? k->max : 10000.0, !k,
                   [](SessionInfo& i) -> double& { return i.camera.frameRate; });
}

Reader textKey(std::function<std::string&(SessionInfo&)> field)
{
    return [=](const cv::FileNode& n, SessionInfo& info) -> std::optional<SessionIssue> {
        if (n.isString()) {
            const std::string s(n);
            if (findUnsavableCharacter(s) != std::string::npos)
                return keyIssue(SessionIssueKind::WrongType,
                                "contains a control character, which could not be saved back");
            field(info) = s;
            return std::nullopt;
        }
        // An unquoted number in a hand-edited file is still meant as text.
        if (n.isInt()) {
            field(info) = std::to_string(int(n));
            return std::nullopt;
        }
        if (n.isReal()) {
            field(info) = formatNumber(double(n));
            return std::nullopt;
        }
        return keyIssue(SessionIssueKind::WrongType, "expected text, found " + typeOf(n));
    };
}

const std::vector<InfoKey>& infoKeys()
{
    static const std::vector<InfoKey> keys = [] {
        std::vector<InfoKey> k;
        k.push_back({"", "created", true, textKey([](SessionInfo& i) -> std::string& { return i.created; })});
        k.push_back({"camera", "model", true, textKey([](SessionInfo& i) -> std::string& { return i.camera.model; })});
        k.push_back({"camera", "frame_rate", true, cameraRateKey()});
        k.push_back({"camera", "exposure", true, cameraIntKey("camera.exposure", &CameraSettings::exposure)});
        k.push_back({"camera", "white_balance_blue", true,
                     cameraIntKey("camera.white_balance_blue", &CameraSettings::whiteBalanceBlue)});
        k.push_back({"camera", "white_balance_red", true,
                     cameraIntKey("camera.white_balance_red", &CameraSettings::whiteBalanceRed)});
        k.push_back({"camera", "gain", true, cameraIntKey("camera.gain", &CameraSettings::gain)});
        k.push_back({"camera", "brightness", true, cameraIntKey("camera.brightness", &CameraSettings::brightness)});
        k.push_back({"", "frame_width", true, infoIntKey(0, kSessionMaxFrameSide, &SessionInfo::width)});
        k.push_back({"", "frame_height", true, infoIntKey(0, kSessionMaxFrameSide, &SessionInfo::height)});
        k.push_back({"", "pixel_format", true,
                     [](const cv::FileNode& n, SessionInfo& info) -> std::optional<SessionIssue> {
                         if (!n.isString())
                             return keyIssue(SessionIssueKind::WrongType, "expected bgr8 or uyvy, found " + typeOf(n));
                         for (PixelFormat f : {PixelFormat::Bgr8, PixelFormat::Uyvy})
                             if (std::string(n) == pixelFormatName(f)) {
                                 info.pixelFormat = f;
                                 return std::nullopt;
                             }
                         return keyIssue(SessionIssueKind::WrongType,
                                         "\"" + std::string(n) + "\" is not one of bgr8, uyvy");
                     }});
        k.push_back({"", "frame_count", true, infoIntKey(0, kSessionMaxFrames, &SessionInfo::frameCount)});
        // The recording's own rate may be anything above 0 (a slow-motion export, a time lapse).
        k.push_back({"", "frame_rate", true, rateKey(0.0, 10000.0, true, [](SessionInfo& i) -> double& { return i.frameRate; })});
        k.push_back({"", "notes", false, textKey([](SessionInfo& i) -> std::string& { return i.notes; })});
        k.push_back({"", "config_file", false, textKey([](SessionInfo& i) -> std::string& { return i.configFile; })});
        k.push_back({"", "complete", false, [](const cv::FileNode& n, SessionInfo& info) -> std::optional<SessionIssue> {
                         const std::string v = n.isString() ? std::string(n) : std::string();
                         if (v != "true" && v != "false")
                             return keyIssue(SessionIssueKind::WrongType, "expected true or false, found " + typeOf(n));
                         info.complete = v == "true";
                         return std::nullopt;
                     }});
        return k;
    }();
    return keys;
}

}  // namespace

SessionInfoParse parseSessionInfo(const std::string& text, const std::string& fileName)
{
    SessionInfoParse out;
    auto fail = [&](SessionIssueKind kind, const std::string& key, const std::string& message) {
        out.error = SessionIssue{kind, fileName, 0, key, message};
        return out;
    };
    if (text.find_first_not_of(" \t\r\n") == std::string::npos)
        return fail(SessionIssueKind::ParseError, "", "the file is empty");

    cv::FileStorage fs;
    if (const auto err = openYamlText(text, fs)) {
        out.error = SessionIssue{SessionIssueKind::ParseError, fileName, err->line, "", "not valid YAML: " + err->message};
        return out;
    }
    const cv::FileNode root = fs.root();
    if (!root.isMap()) return fail(SessionIssueKind::NotASession, "", "the top level is not a map of keys");

    const cv::FileNode format = root["session_format"];
    if (format.empty() || format.isNone())
        return fail(SessionIssueKind::NotASession, "session_format",
                    "no 'session_format' key: this is not an OmniTune session.yml");
    if (!format.isInt())
        return fail(SessionIssueKind::NotASession, "session_format", "expected an integer, found " + typeOf(format));
    if (int(format) != kSessionFormatVersion)
        return fail(SessionIssueKind::UnknownFormat, "session_format",
                    "session_format " + std::to_string(int(format)) + " is not known to this build, which reads " +
                        std::to_string(kSessionFormatVersion));

    const cv::FileNode camera = root["camera"];
    const bool cameraMissing = camera.empty() || camera.isNone();
    if (cameraMissing)
        out.warnings.push_back({SessionIssueKind::MissingKey, fileName, 0, "camera",
                                "missing, the camera settings are unknown (defaults used)"});
    else if (!camera.isMap())
        out.warnings.push_back({SessionIssueKind::WrongType, fileName, lineOfKey(text, "", "camera"), "camera",
                                "expected a section, found " + typeOf(camera) + " (defaults used)"});

    for (const InfoKey& k : infoKeys()) {
        const std::string path = k.section.empty() ? k.name : k.section + "." + k.name;
        cv::FileNode n;
        if (k.section.empty()) {
            n = root[k.name];
        } else {
            if (cameraMissing || !camera.isMap()) continue;  // reported once above
            n = camera[k.name];
        }
        if (n.empty() || n.isNone()) {
            if (k.required)
                out.warnings.push_back({SessionIssueKind::MissingKey, fileName, 0, path, "missing, the default is used"});
            continue;
        }
        if (auto issue = k.read(n, out.info)) {
            issue->file = fileName;
            issue->line = lineOfKey(text, k.section, k.name);
            issue->key = path;
            issue->message += ", the default is used";
            out.warnings.push_back(*issue);
        }
    }

    std::set<std::string> known = {"session_format", "camera"};
    std::set<std::string> knownCamera;
    for (const InfoKey& k : infoKeys()) (k.section.empty() ? known : knownCamera).insert(k.name);
    for (const cv::FileNode& child : root)
        if (!known.count(child.name()))
            out.warnings.push_back({SessionIssueKind::UnknownKey, fileName, lineOfKey(text, "", child.name()),
                                    child.name(), "unknown key, ignored (a typo?)"});
    if (!cameraMissing && camera.isMap())
        for (const cv::FileNode& child : camera)
            if (!knownCamera.count(child.name()))
                out.warnings.push_back({SessionIssueKind::UnknownKey, fileName,
                                        lineOfKey(text, "camera", child.name()), "camera." + child.name(),
                                        "unknown key, ignored (a typo?)"});
    return out;
}

std::string serializeSessionInfo(const SessionInfo& info)
{
    cv::FileStorage fs(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
    fs.writeComment("OmniTune recorded session. Reference: docs/sessions.md");
    fs << "session_format" << kSessionFormatVersion;
    fs.write("created", info.created);  // write(), not <<: text may start with [ { ] }
    fs << "camera" << "{";
    fs.write("model", info.camera.model);
    fs << "frame_rate" << info.camera.frameRate;
    fs << "exposure" << info.camera.exposure;
    fs << "white_balance_blue" << info.camera.whiteBalanceBlue;
    fs << "white_balance_red" << info.camera.whiteBalanceRed;
    fs << "gain" << info.camera.gain;
    fs << "brightness" << info.camera.brightness;
    fs << "}";
    fs << "frame_width" << info.width;
    fs << "frame_height" << info.height;
    fs << "pixel_format" << std::string(pixelFormatName(info.pixelFormat));
    fs << "frame_count" << info.frameCount;
    fs << "frame_rate" << info.frameRate;
    fs.write("notes", info.notes);
    if (!info.configFile.empty()) fs.write("config_file", info.configFile);
    if (info.complete) fs << "complete" << std::string(*info.complete ? "true" : "false");
    return fs.releaseAndGetString();
}

std::string sessionFrameName(int index)
{
    char name[32];
    std::snprintf(name, sizeof name, "%06d.png", index);
    return name;
}

std::string isoUtcNow()
{
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return buf;
}

}  // namespace omnitune
