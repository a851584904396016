#include "calib/camera/Dc1394Camera.h"

#include "calib/camera/CameraSettingsIo.h"
#include "core/ColorLut.h"

#include <dc1394/dc1394.h>
#include <opencv2/imgproc.hpp>

#include <poll.h>

#include <cmath>
#include <cstdio>
#include <mutex>

namespace omnitune {

namespace {

// libdc1394 prints its errors to stderr by default; the tools need one-line messages. The last
// error is kept here (process-wide, as libdc1394's log is) and put into our messages.
std::mutex logMutex;
std::string lastLog;

void keepLog(dc1394log_t, const char* message, void*)
{
    std::lock_guard<std::mutex> lock(logMutex);
    lastLog = message ? message : "";
}

void quietLog()
{
    static std::once_flag once;
    std::call_once(once, [] {
        dc1394_log_register_handler(DC1394_LOG_ERROR, keepLog, nullptr);
        dc1394_log_register_handler(DC1394_LOG_WARNING, keepLog, nullptr);
    });
}

std::string takeLog()
{
    std::lock_guard<std::mutex> lock(logMutex);
    std::string s;
    s.swap(lastLog);
    return s.empty() ? s : " (libdc1394: " + s + ")";
}

dc1394_t* newContext() { quietLog(); return dc1394_new(); }

constexpr std::string_view kNoBus =
    "no FireWire bus: libdc1394 found no /dev/fw* device it may open (no FireWire card, the "
    "firewire-ohci module not loaded, or no permission on /dev/fw*)";

std::optional<dc1394feature_t> dcFeature(CameraFeatureId id)
{
    switch (id) {
    case CameraFeatureId::Exposure: return DC1394_FEATURE_EXPOSURE;
    case CameraFeatureId::Shutter: return DC1394_FEATURE_SHUTTER;
    case CameraFeatureId::Gain: return DC1394_FEATURE_GAIN;
    case CameraFeatureId::Brightness: return DC1394_FEATURE_BRIGHTNESS;
    case CameraFeatureId::WhiteBalanceBlue:
    case CameraFeatureId::WhiteBalanceRed: return DC1394_FEATURE_WHITE_BALANCE;
    case CameraFeatureId::Gamma: return DC1394_FEATURE_GAMMA;
    case CameraFeatureId::Saturation: return DC1394_FEATURE_SATURATION;
    }
    return std::nullopt;
}

bool hasMode(const dc1394feature_info_t& f, dc1394feature_mode_t mode)
{
    for (uint32_t i = 0; i < f.modes.num; ++i)
        if (f.modes.modes[i] == mode) return true;
    return false;
}

dc1394framerate_t nearestRate(dc1394camera_t* cam, dc1394video_mode_t mode, double fps)
{
    dc1394framerates_t rates;
    dc1394framerate_t best = DC1394_FRAMERATE_30;
    double bestDiff = 1e9;
    if (dc1394_video_get_supported_framerates(cam, mode, &rates) != DC1394_SUCCESS) return best;
    for (uint32_t i = 0; i < rates.num; ++i) {
        float f = 0;
        dc1394_framerate_as_float(rates.framerates[i], &f);
        if (std::abs(f - fps) < bestDiff) bestDiff = std::abs(f - fps), best = rates.framerates[i];
    }
    return best;
}

}  // namespace

std::string formatGuid(std::uint64_t guid)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "0x%016llx", static_cast<unsigned long long>(guid));
    return buf;
}

std::optional<std::uint64_t> parseGuid(const std::string& text)
{
    std::string hex = text;
    if (hex.rfind("0x", 0) == 0 || hex.rfind("0X", 0) == 0) hex = hex.substr(2);
    if (hex.empty() || hex.size() > 16 || hex.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
        return std::nullopt;
    return std::stoull(hex, nullptr, 16);
}

CameraScan listDc1394Cameras()
{
    CameraScan scan;
    dc1394_t* d = newContext();
    if (!d) {
        scan.notes.push_back("dc1394: " + std::string(kNoBus) + takeLog());
        return scan;
    }
    dc1394camera_list_t* list = nullptr;
    if (dc1394_camera_enumerate(d, &list) != DC1394_SUCCESS || !list) {
        scan.notes.push_back("dc1394: could not list the FireWire bus" + takeLog());
    } else {
        for (uint32_t i = 0; i < list->num; ++i) {
            CameraInfo info{"dc1394:" + formatGuid(list->ids[i].guid), "IIDC camera " + formatGuid(list->ids[i].guid)};
            if (dc1394camera_t* cam = dc1394_camera_new(d, list->ids[i].guid)) {
                info.name = std::string(cam->vendor ? cam->vendor : "") + " " + (cam->model ? cam->model : "");
                dc1394_camera_free(cam);
            }
            scan.cameras.push_back(info);
        }
        if (list->num == 0) scan.notes.push_back("dc1394: no camera on the FireWire bus");
        dc1394_camera_free_list(list);
    }
    dc1394_free(d);
    return scan;
}

Dc1394Camera::Dc1394Camera(std::optional<std::uint64_t> guid, const Dc1394Options& options)
    : guid_(guid), options_(options)
{
}

Dc1394Camera::~Dc1394Camera() { close(); }

std::string Dc1394Camera::description() const
{
    return "dc1394 camera " + (guid_ ? formatGuid(*guid_) : std::string("(first found)")) +
           (name_.empty() ? "" : " (" + name_ + ")");
}

std::optional<CameraError> Dc1394Camera::open()
{
    close();
    auto* d = newContext();
    if (!d) return error(CameraErrorKind::NoDevice, std::string(kNoBus) + takeLog());
    context_ = d;
    dc1394camera_list_t* list = nullptr;
    if (dc1394_camera_enumerate(d, &list) != DC1394_SUCCESS || !list) {
        close();
        return error(CameraErrorKind::NoDevice, "could not list the FireWire bus" + takeLog());
    }
    std::optional<std::uint64_t> found;
    for (uint32_t i = 0; i < list->num; ++i)
        if (!guid_ || list->ids[i].guid == *guid_) {
            found = list->ids[i].guid;
            break;
        }
    const uint32_t count = list->num;
    dc1394_camera_free_list(list);
    if (!found) {
        close();
        return error(CameraErrorKind::NoDevice, count == 0 ? "no camera on the FireWire bus"
                                                           : "no camera with this GUID on the FireWire bus (" +
                                                                 std::to_string(count) + " other(s): omnitune-camera --list)");
    }
    guid_ = found;
    auto* cam = dc1394_camera_new(d, *found);
    if (!cam) {
        close();
        return error(CameraErrorKind::Device, "the camera did not answer" + takeLog());
    }
    camera_ = cam;
    name_ = std::string(cam->vendor ? cam->vendor : "") + " " + (cam->model ? cam->model : "");

    // 640x480 YUV 4:2:2, else RGB8, else Format7 mode 0 cut to 640x480 in either coding.
    dc1394video_modes_t modes;
    if (dc1394_video_get_supported_modes(cam, &modes) != DC1394_SUCCESS) {
        close();
        return error(CameraErrorKind::Device, "could not read the video modes" + takeLog());
    }
    const auto offered = [&](dc1394video_mode_t m) {
        for (uint32_t i = 0; i < modes.num; ++i)
            if (modes.modes[i] == m) return true;
        return false;
    };
    dc1394video_mode_t mode = DC1394_VIDEO_MODE_640x480_YUV422;
    bool format7 = false;
    if (!offered(mode)) mode = DC1394_VIDEO_MODE_640x480_RGB8;
    if (!offered(mode)) {
        mode = DC1394_VIDEO_MODE_FORMAT7_0;
        format7 = offered(mode);
        if (!format7) {
            close();
            return error(CameraErrorKind::Device, "offers neither 640x480 YUV 4:2:2, RGB8 nor Format7");
        }
    }
    dc1394_video_set_operation_mode(cam, DC1394_OPERATION_MODE_1394B);
    dc1394operation_mode_t opMode;
    const bool b = dc1394_video_get_operation_mode(cam, &opMode) == DC1394_SUCCESS && opMode == DC1394_OPERATION_MODE_1394B;
    dc1394_video_set_iso_speed(cam, b ? DC1394_ISO_SPEED_800 : DC1394_ISO_SPEED_400);
    if (dc1394_video_set_mode(cam, mode) != DC1394_SUCCESS) {
        close();
        return error(CameraErrorKind::Device, "refused the video mode" + takeLog());
    }
    if (format7) {
        if (dc1394_format7_set_roi(cam, mode, DC1394_COLOR_CODING_YUV422, DC1394_USE_MAX_AVAIL, 0, 0, 640, 480) !=
                DC1394_SUCCESS &&
            dc1394_format7_set_roi(cam, mode, DC1394_COLOR_CODING_RGB8, DC1394_USE_MAX_AVAIL, 0, 0, 640, 480) !=
                DC1394_SUCCESS) {
            close();
            return error(CameraErrorKind::Device, "refused a 640x480 Format7 region" + takeLog());
        }
    } else {
        dc1394_video_set_framerate(cam, nearestRate(cam, mode, options_.frameRate));
    }
    mode_ = int(mode);
    size_ = {640, 480};
    return std::nullopt;
}

std::optional<CameraError> Dc1394Camera::start()
{
    if (!camera_) return error(CameraErrorKind::NotStarted, "start() before open()");
    auto* cam = static_cast<dc1394camera_t*>(camera_);
    if (dc1394_capture_setup(cam, uint32_t(std::max(options_.ringBuffers, 2)), DC1394_CAPTURE_FLAGS_DEFAULT) != DC1394_SUCCESS)
        return error(CameraErrorKind::Device, "could not set up DMA capture (is another program using the camera?)" + takeLog());
    if (dc1394_video_set_transmission(cam, DC1394_ON) != DC1394_SUCCESS) {
        dc1394_capture_stop(cam);
        return error(CameraErrorKind::Device, "would not start sending" + takeLog());
    }
    started_ = true;
    refreshSettings();
    firstTimestampUs_ = -1;
    return std::nullopt;
}

std::optional<CameraError> Dc1394Camera::grab(Frame& out)
{
    if (!started_) return error(CameraErrorKind::NotStarted, "grab() before start()");
    auto* cam = static_cast<dc1394camera_t*>(camera_);
    // Wait (bounded) for a frame, then take the newest: older ones in the ring go straight back.
    pollfd pfd{dc1394_capture_get_fileno(cam), POLLIN, 0};
    const int ready = ::poll(&pfd, 1, 1000);
    if (ready <= 0 || (pfd.revents & (POLLERR | POLLHUP | POLLNVAL))) {
        stop();
        return error(CameraErrorKind::Unplugged, "no frame for a second: the camera stopped answering (unplugged?)");
    }
    dc1394video_frame_t* frame = nullptr;
    if (dc1394_capture_dequeue(cam, DC1394_CAPTURE_POLICY_POLL, &frame) != DC1394_SUCCESS || !frame) {
        stop();
        return error(CameraErrorKind::Unplugged, "lost the camera while capturing (unplugged?)" + takeLog());
    }
    int dropped = 0;
    while (frame->frames_behind > 0) {
        dc1394video_frame_t* newer = nullptr;
        if (dc1394_capture_dequeue(cam, DC1394_CAPTURE_POLICY_POLL, &newer) != DC1394_SUCCESS || !newer) break;
        dc1394_capture_enqueue(cam, frame);
        frame = newer;
        ++dropped;
    }
    const int w = int(frame->size[0]), h = int(frame->size[1]);
    if (frame->color_coding == DC1394_COLOR_CODING_YUV422) {
        convertUyvyToBgr(cv::Mat(h, w, CV_8UC2, frame->image), out.image);
    } else if (frame->color_coding == DC1394_COLOR_CODING_RGB8) {
        cv::cvtColor(cv::Mat(h, w, CV_8UC3, frame->image), out.image, cv::COLOR_RGB2BGR);
    } else {
        dc1394_capture_enqueue(cam, frame);
        return error(CameraErrorKind::Device, "sends a colour coding OmniTune does not read (" +
                                                  std::to_string(int(frame->color_coding)) + ")");
    }
    if (firstTimestampUs_ < 0) firstTimestampUs_ = double(frame->timestamp);
    out.timestampS = (double(frame->timestamp) - firstTimestampUs_) * 1e-6;
    dc1394_capture_enqueue(cam, frame);
    index_ += dropped;
    out.index = index_++;
    out.format = PixelFormat::Bgr8;
    out.camera = settings_;
    return std::nullopt;
}

void Dc1394Camera::stop()
{
    if (!started_) return;
    auto* cam = static_cast<dc1394camera_t*>(camera_);
    dc1394_video_set_transmission(cam, DC1394_OFF);
    dc1394_capture_stop(cam);
    started_ = false;
}

void Dc1394Camera::close()
{
    stop();
    if (camera_) dc1394_camera_free(static_cast<dc1394camera_t*>(camera_));
    if (context_) dc1394_free(static_cast<dc1394_t*>(context_));
    camera_ = context_ = nullptr;
    size_ = {};
}

void Dc1394Camera::refreshSettings()
{
    CameraSettings s;
    s.model = name_;
    settings_ = readCameraSettings(*this, s);
}

std::vector<CameraFeature> Dc1394Camera::features()
{
    std::vector<CameraFeature> out;
    if (!camera_) return out;
    dc1394featureset_t set;
    if (dc1394_feature_get_all(static_cast<dc1394camera_t*>(camera_), &set) != DC1394_SUCCESS) return out;
    for (CameraFeatureId id : kAllCameraFeatures) {
        const dc1394feature_info_t& f = set.feature[*dcFeature(id) - DC1394_FEATURE_MIN];
        if (!f.available) continue;
        int value = int(f.value);
        if (id == CameraFeatureId::WhiteBalanceBlue) value = int(f.BU_value);
        if (id == CameraFeatureId::WhiteBalanceRed) value = int(f.RV_value);
        out.push_back({id, int(f.min), int(f.max), value, hasMode(f, DC1394_FEATURE_MODE_AUTO),
                       f.current_mode == DC1394_FEATURE_MODE_AUTO});
    }
    return out;
}

std::optional<CameraError> Dc1394Camera::writeFeature(CameraFeatureId id, int value)
{
    auto* cam = static_cast<dc1394camera_t*>(camera_);
    const dc1394feature_t f = *dcFeature(id);
    dc1394_feature_set_power(cam, f, DC1394_ON);
    dc1394_feature_set_mode(cam, f, DC1394_FEATURE_MODE_MANUAL);
    dc1394error_t err;
    if (f == DC1394_FEATURE_WHITE_BALANCE) {
        uint32_t ub = 0, vr = 0;
        err = dc1394_feature_whitebalance_get_value(cam, &ub, &vr);
        if (err == DC1394_SUCCESS)
            err = id == CameraFeatureId::WhiteBalanceBlue ? dc1394_feature_whitebalance_set_value(cam, uint32_t(value), vr)
                                                          : dc1394_feature_whitebalance_set_value(cam, ub, uint32_t(value));
    } else {
        err = dc1394_feature_set_value(cam, f, uint32_t(value));
    }
    if (err != DC1394_SUCCESS)
        return error(CameraErrorKind::Device, "refused " + std::string(cameraFeatureName(id)) + " " +
                                                  std::to_string(value) + takeLog());
    refreshSettings();
    return std::nullopt;
}

std::optional<CameraError> Dc1394Camera::writeAuto(CameraFeatureId id, bool on)
{
    auto* cam = static_cast<dc1394camera_t*>(camera_);
    if (dc1394_feature_set_mode(cam, *dcFeature(id), on ? DC1394_FEATURE_MODE_AUTO : DC1394_FEATURE_MODE_MANUAL) !=
        DC1394_SUCCESS)
        return error(CameraErrorKind::Device, "refused to turn " + std::string(cameraFeatureName(id)) + "'s auto mode " +
                                                  (on ? "on" : "off") + takeLog());
    refreshSettings();
    return std::nullopt;
}

}  // namespace omnitune
