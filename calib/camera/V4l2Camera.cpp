#include "calib/camera/V4l2Camera.h"

#include "calib/camera/CameraSettingsIo.h"

#include <opencv2/imgproc.hpp>

#include <fcntl.h>
#include <linux/videodev2.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

namespace omnitune {

namespace {

int xioctl(int fd, unsigned long request, void* arg)
{
    int r;
    do r = ::ioctl(fd, request, arg);
    while (r < 0 && errno == EINTR);
    return r;
}

struct ControlMap {
    unsigned value = 0;  // V4L2_CID_* of the value
    unsigned automatic = 0;  // V4L2_CID_* of its auto switch, 0 when none
    int autoOn = 1, autoOff = 0;  // values of that switch
};

std::optional<ControlMap> controlFor(CameraFeatureId id)
{
    switch (id) {
    case CameraFeatureId::Exposure:
        return ControlMap{V4L2_CID_EXPOSURE_ABSOLUTE, V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_APERTURE_PRIORITY, V4L2_EXPOSURE_MANUAL};
    case CameraFeatureId::Gain: return ControlMap{V4L2_CID_GAIN, V4L2_CID_AUTOGAIN, 1, 0};
    case CameraFeatureId::Brightness: return ControlMap{V4L2_CID_BRIGHTNESS, 0, 1, 0};
    case CameraFeatureId::WhiteBalanceBlue: return ControlMap{V4L2_CID_BLUE_BALANCE, V4L2_CID_AUTO_WHITE_BALANCE, 1, 0};
    case CameraFeatureId::WhiteBalanceRed: return ControlMap{V4L2_CID_RED_BALANCE, V4L2_CID_AUTO_WHITE_BALANCE, 1, 0};
    case CameraFeatureId::Gamma: return ControlMap{V4L2_CID_GAMMA, 0, 1, 0};
    case CameraFeatureId::Saturation: return ControlMap{V4L2_CID_SATURATION, 0, 1, 0};
    case CameraFeatureId::Shutter: break;  // V4L2 has one exposure control
    }
    return std::nullopt;
}

bool controlExists(int fd, unsigned id, v4l2_queryctrl& q)
{
    std::memset(&q, 0, sizeof q);
    q.id = id;
    return xioctl(fd, VIDIOC_QUERYCTRL, &q) == 0 && !(q.flags & V4L2_CTRL_FLAG_DISABLED);
}

std::optional<int> controlValue(int fd, unsigned id)
{
    v4l2_control c{id, 0};
    if (xioctl(fd, VIDIOC_G_CTRL, &c) != 0) return std::nullopt;
    return c.value;
}

bool isCaptureDevice(const std::string& path, std::string* card)
{
    const int fd = ::open(path.c_str(), O_RDWR | O_NONBLOCK);
    if (fd < 0) return false;
    v4l2_capability cap{};
    const bool ok = xioctl(fd, VIDIOC_QUERYCAP, &cap) == 0 &&
                    ((cap.capabilities & V4L2_CAP_DEVICE_CAPS ? cap.device_caps : cap.capabilities) & V4L2_CAP_VIDEO_CAPTURE);
    if (ok && card) *card = reinterpret_cast<const char*>(cap.card);
    ::close(fd);
    return ok;
}

std::vector<std::string> videoDevices()
{
    std::vector<std::string> out;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator("/dev", ec))
        if (e.path().filename().string().rfind("video", 0) == 0) out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

CameraScan listV4l2Cameras()
{
    CameraScan scan;
    for (const std::string& dev : videoDevices()) {
        std::string card;
        if (isCaptureDevice(dev, &card)) scan.cameras.push_back({"v4l2:" + dev, card});
    }
    if (scan.cameras.empty()) scan.notes.push_back("v4l2: no video capture device (/dev/video*)");
    return scan;
}

V4l2Camera::V4l2Camera(std::string device, double frameRate) : device_(std::move(device)), frameRate_(frameRate) {}

V4l2Camera::~V4l2Camera() { close(); }

std::string V4l2Camera::description() const
{
    return "v4l2 camera " + (device_.empty() ? std::string("(first found)") : device_) + (card_.empty() ? "" : " (" + card_ + ")");
}

std::optional<CameraError> V4l2Camera::open()
{
    close();
    if (device_.empty()) {
        for (const std::string& dev : videoDevices())
            if (isCaptureDevice(dev, nullptr)) {
                device_ = dev;
                break;
            }
        if (device_.empty()) return error(CameraErrorKind::NoDevice, "no video capture device (/dev/video*)");
    }
    fd_ = ::open(device_.c_str(), O_RDWR | O_NONBLOCK);
    if (fd_ < 0) {
        const int e = errno;
        return error(e == ENOENT || e == ENODEV || e == ENXIO ? CameraErrorKind::NoDevice : CameraErrorKind::Device,
                     "cannot open " + device_ + ": " + std::strerror(e));
    }
    v4l2_capability cap{};
    if (xioctl(fd_, VIDIOC_QUERYCAP, &cap) != 0) {
        close();
        return error(CameraErrorKind::NoDevice, device_ + " is not a V4L2 device");
    }
    const unsigned caps = cap.capabilities & V4L2_CAP_DEVICE_CAPS ? cap.device_caps : cap.capabilities;
    if (!(caps & V4L2_CAP_VIDEO_CAPTURE) || !(caps & V4L2_CAP_STREAMING)) {
        close();
        return error(CameraErrorKind::NoDevice, device_ + " does not capture video by streaming");
    }
    card_ = reinterpret_cast<const char*>(cap.card);
    for (unsigned fourcc : {unsigned(V4L2_PIX_FMT_YUYV), unsigned(V4L2_PIX_FMT_UYVY)}) {
        v4l2_format fmt{};
        fmt.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        fmt.fmt.pix.width = 640;
        fmt.fmt.pix.height = 480;
        fmt.fmt.pix.pixelformat = fourcc;
        fmt.fmt.pix.field = V4L2_FIELD_NONE;
        if (xioctl(fd_, VIDIOC_S_FMT, &fmt) == 0 && fmt.fmt.pix.pixelformat == fourcc) {
            pixelFormat_ = fourcc;
            size_ = {int(fmt.fmt.pix.width), int(fmt.fmt.pix.height)};
            break;
        }
    }
    if (!pixelFormat_) {
        close();
        return error(CameraErrorKind::Device, "offers neither YUYV nor UYVY");
    }
    v4l2_streamparm parm{};
    parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    parm.parm.capture.timeperframe = {1, unsigned(std::lround(frameRate_))};
    xioctl(fd_, VIDIOC_S_PARM, &parm);  // a driver without rate control keeps its own
    return std::nullopt;
}

std::optional<CameraError> V4l2Camera::start()
{
    if (fd_ < 0) return error(CameraErrorKind::NotStarted, "start() before open()");
    v4l2_requestbuffers req{};
    req.count = 4;
    req.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    req.memory = V4L2_MEMORY_MMAP;
    if (xioctl(fd_, VIDIOC_REQBUFS, &req) != 0 || req.count < 2)
        return error(CameraErrorKind::Device, "no capture buffers (" + std::string(std::strerror(errno)) + ")");
    buffers_.assign(req.count, {});
    for (unsigned i = 0; i < req.count; ++i) {
        v4l2_buffer buf{};
        buf.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        buf.memory = V4L2_MEMORY_MMAP;
        buf.index = i;
        if (xioctl(fd_, VIDIOC_QUERYBUF, &buf) != 0) return error(CameraErrorKind::Device, "cannot query a buffer");
        void* p = ::mmap(nullptr, buf.length, PROT_READ | PROT_WRITE, MAP_SHARED, fd_, buf.m.offset);
        if (p == MAP_FAILED) return error(CameraErrorKind::Device, "cannot map a buffer");
        buffers_[i] = {p, buf.length};
        if (xioctl(fd_, VIDIOC_QBUF, &buf) != 0) return error(CameraErrorKind::Device, "cannot queue a buffer");
    }
    v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (xioctl(fd_, VIDIOC_STREAMON, &type) != 0)
        return error(CameraErrorKind::Device, "would not start streaming (" + std::string(std::strerror(errno)) + ")");
    started_ = true;
    refreshSettings();
    firstTimestampS_ = -1;
    return std::nullopt;
}

std::optional<CameraError> V4l2Camera::unplugged(const std::string& what)
{
    stop();
    return error(CameraErrorKind::Unplugged, what + " (unplugged?)");
}

std::optional<CameraError> V4l2Camera::grab(Frame& out)
{
    if (!started_) return error(CameraErrorKind::NotStarted, "grab() before start()");
    pollfd pfd{fd_, POLLIN, 0};
    if (::poll(&pfd, 1, 1000) <= 0 || (pfd.revents & (POLLERR | POLLHUP | POLLNVAL)))
        return unplugged("no frame for a second: the camera stopped answering");
    // Take every filled buffer, keep the newest, give the older ones straight back.
    v4l2_buffer newest{};
    bool have = false;
    int dropped = -1;
    while (true) {
        v4l2_buffer buf{};
        buf.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        buf.memory = V4L2_MEMORY_MMAP;
        if (xioctl(fd_, VIDIOC_DQBUF, &buf) != 0) {
            if (errno == EAGAIN) break;
            if (errno == ENODEV) return unplugged("the device went away");
            return error(CameraErrorKind::Device, "cannot take a frame (" + std::string(std::strerror(errno)) + ")");
        }
        if (have) xioctl(fd_, VIDIOC_QBUF, &newest);
        newest = buf;
        have = true;
        ++dropped;
    }
    if (!have) return error(CameraErrorKind::Device, "woke up without a frame");
    const cv::Mat raw(size_, CV_8UC2, buffers_[newest.index].start);
    if (pixelFormat_ == V4L2_PIX_FMT_YUYV)
        cv::cvtColor(raw, out.image, cv::COLOR_YUV2BGR_YUYV);
    else
        cv::cvtColor(raw, out.image, cv::COLOR_YUV2BGR_UYVY);
    const double t = newest.timestamp.tv_sec + newest.timestamp.tv_usec * 1e-6;
    if (firstTimestampS_ < 0) firstTimestampS_ = t;
    out.timestampS = t - firstTimestampS_;
    xioctl(fd_, VIDIOC_QBUF, &newest);
    index_ += std::max(dropped, 0);
    out.index = index_++;
    out.format = PixelFormat::Bgr8;
    out.camera = settings_;
    return std::nullopt;
}

void V4l2Camera::stop()
{
    if (!started_) return;
    v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    xioctl(fd_, VIDIOC_STREAMOFF, &type);
    for (const Buffer& b : buffers_)
        if (b.start) ::munmap(b.start, b.length);
    buffers_.clear();
    started_ = false;
}

void V4l2Camera::close()
{
    stop();
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    size_ = {};
    pixelFormat_ = 0;
}

void V4l2Camera::refreshSettings()
{
    CameraSettings s;
    s.model = card_;
    settings_ = readCameraSettings(*this, s);
}

std::vector<CameraFeature> V4l2Camera::features()
{
    std::vector<CameraFeature> out;
    if (fd_ < 0) return out;
    for (CameraFeatureId id : kAllCameraFeatures) {
        const auto map = controlFor(id);
        v4l2_queryctrl q;
        if (!map || !controlExists(fd_, map->value, q)) continue;
        CameraFeature f{id, q.minimum, q.maximum, controlValue(fd_, map->value).value_or(q.default_value), false, false};
        v4l2_queryctrl qa;
        if (map->automatic && controlExists(fd_, map->automatic, qa)) {
            f.autoCapable = true;
            f.autoOn = controlValue(fd_, map->automatic).value_or(map->autoOff) != map->autoOff;
        }
        out.push_back(f);
    }
    return out;
}

std::optional<CameraError> V4l2Camera::writeFeature(CameraFeatureId id, int value)
{
    const ControlMap map = *controlFor(id);
    v4l2_queryctrl qa;
    if (map.automatic && controlExists(fd_, map.automatic, qa)) {
        v4l2_control off{map.automatic, map.autoOff};
        xioctl(fd_, VIDIOC_S_CTRL, &off);
    }
    v4l2_control c{map.value, value};
    if (xioctl(fd_, VIDIOC_S_CTRL, &c) != 0) {
        if (errno == ENODEV) return unplugged("the device went away");
        return error(CameraErrorKind::Device, "refused " + std::string(cameraFeatureName(id)) + " " +
                                                  std::to_string(value) + " (" + std::strerror(errno) + ")");
    }
    refreshSettings();
    return std::nullopt;
}

std::optional<CameraError> V4l2Camera::writeAuto(CameraFeatureId id, bool on)
{
    const ControlMap map = *controlFor(id);
    if (!map.automatic) return std::nullopt;  // nothing automatic to turn off
    v4l2_control c{map.automatic, on ? map.autoOn : map.autoOff};
    if (xioctl(fd_, VIDIOC_S_CTRL, &c) != 0 && on)
        return error(CameraErrorKind::Device, "refused to turn " + std::string(cameraFeatureName(id)) + "'s auto mode on (" +
                                                  std::strerror(errno) + ")");
    refreshSettings();
    return std::nullopt;
}

}  // namespace omnitune
