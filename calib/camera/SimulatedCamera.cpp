#include "calib/camera/SimulatedCamera.h"

#include "calib/camera/CameraSettingsIo.h"
#include "calib/sim/optics/CatadioptricCamera.h"
#include "calib/sim/optics/OpticsCell.h"
#include "calib/sim/optics/OpticsRenderer.h"

#include <algorithm>

namespace omnitune {

namespace {

// The light the radiance is rendered at: low enough that nothing of the scene clips in the
// renderer's 8 bits, so clipping happens only in the sensor model.
constexpr double kRenderLight = 0.5;
// Reference cards in radiance grey levels (a white sheet, black felt).
const cv::Scalar kWhiteCard(200, 200, 200);
const cv::Scalar kBlackCard(7, 7, 7);

int& field(CameraSettings& s, CameraFeatureId id)
{
    int* f = cameraSettingsField(s, id);
    CV_Assert(f);  // features() lists only features the settings hold
    return *f;
}

}  // namespace

std::string_view simulatedStartName(SimulatedStart s)
{
    switch (s) {
    case SimulatedStart::Good: return "good";
    case SimulatedStart::Dark: return "dark";
    case SimulatedStart::Bright: return "bright";
    case SimulatedStart::Tinted: return "tinted";
    }
    return "?";
}

std::optional<SimulatedStart> parseSimulatedStart(std::string_view name)
{
    for (SimulatedStart s : {SimulatedStart::Good, SimulatedStart::Dark, SimulatedStart::Bright, SimulatedStart::Tinted})
        if (simulatedStartName(s) == name) return s;
    return std::nullopt;
}

CameraSettings simulatedStartSettings(SimulatedStart s)
{
    CameraSettings c;
    c.model = "OmniTune simulated camera";
    switch (s) {
    case SimulatedStart::Good: break;
    case SimulatedStart::Dark: c.exposure = 40, c.gain = 0, c.brightness = 0; break;
    case SimulatedStart::Bright: c.exposure = 1600, c.gain = 700, c.brightness = 600; break;
    case SimulatedStart::Tinted: c.whiteBalanceBlue = 250, c.whiteBalanceRed = 900; break;
    }
    return c;
}

SimulatedCamera::SimulatedCamera(const SimulatedCameraOptions& options) : options_(options), delayRng_(options.seed) {}

SimulatedCamera::~SimulatedCamera()
{
    stopRendering_ = true;
    if (renderThread_.joinable()) renderThread_.join();
}

std::string SimulatedCamera::description() const
{
    return "simulated camera (" + std::string(simulatedStartName(options_.start)) + " start, seed " +
           std::to_string(options_.seed) + ")";
}

std::optional<CameraError> SimulatedCamera::open()
{
    if (!optics_) {
        OpticsCell cell;
        cell.image = options_.image;
        optics_ = std::make_unique<CatadioptricCamera>(opticsCellCameraParams(cell));
        renderer_ = std::make_unique<OpticsRenderer>(*optics_);
        radiance_.assign(std::size_t(std::max(options_.poses, 1)), cv::Mat());
        renderThread_ = std::thread(&SimulatedCamera::renderAll, this);
    }
    registers_ = effective_ = simulatedStartSettings(options_.start);
    registers_.frameRate = effective_.frameRate = options_.frameRate;
    pending_.clear();
    delayRng_ = cv::RNG(options_.seed);
    next_ = 0;
    unplugged_ = false;
    open_ = true;
    return std::nullopt;
}

std::optional<CameraError> SimulatedCamera::start()
{
    if (!open_) return error(CameraErrorKind::NotStarted, "start() before open()");
    started_ = true;
    return std::nullopt;
}

void SimulatedCamera::close()
{
    open_ = started_ = false;
}

void SimulatedCamera::renderAll()
{
    for (int pose = 0; pose < int(radiance_.size()) && !stopRendering_; ++pose) {
        cv::Mat r;
        try {
            OpticsCell cell;
            cell.image = options_.image;
            cell.frames = int(radiance_.size());
            cell.seed = options_.seed;
            OpticsScene scene = opticsCellScene(cell, pose, *renderer_);
            scene.light = kRenderLight;
            scene.noiseSigma = 0;  // the sensor model adds its own
            renderer_->render(scene).convertTo(r, CV_32FC3, 1.0 / kRenderLight);
            // The reference cards lie on the top plate, under the hall's light like the floor.
            r(options_.whiteCard & cv::Rect({}, r.size())).setTo(kWhiteCard);
            r(options_.blackCard & cv::Rect({}, r.size())).setTo(kBlackCard);
        } catch (const std::exception& e) {
            const std::lock_guard<std::mutex> lock(renderMutex_);
            renderError_ = std::string("rendering place ") + std::to_string(pose) + " failed: " + e.what();
            rendered_.notify_all();
            return;
        }
        const std::lock_guard<std::mutex> lock(renderMutex_);
        radiance_[std::size_t(pose)] = r;
        rendered_.notify_all();
    }
}

bool SimulatedCamera::radiance(int pose, cv::Mat& out, std::string& why)
{
    std::unique_lock<std::mutex> lock(renderMutex_);
    cv::Mat& r = radiance_[std::size_t(pose)];
    rendered_.wait(lock, [&] { return !r.empty() || !renderError_.empty(); });
    if (r.empty()) {
        why = renderError_;
        return false;
    }
    out = r;  // (shared; never written again)
    return true;
}

std::optional<CameraError> SimulatedCamera::grab(Frame& out)
{
    if (unplugged_) {
        started_ = false;
        return error(CameraErrorKind::Unplugged, "the camera stopped answering (unplugged?)");
    }
    if (!open_ || !started_) return error(CameraErrorKind::NotStarted, "grab() before start()");
    const int index = next_++;
    while (!pending_.empty() && pending_.front().effectiveAt <= index) {
        field(effective_, pending_.front().id) = pending_.front().value;
        pending_.pop_front();
    }
    const int pose = (index / std::max(options_.framesPerPose, 1)) % int(radiance_.size());
    cv::RNG noise(std::uint64_t(options_.seed) * 0x9E3779B97F4A7C15ull + std::uint64_t(index) + 1);
    cv::Mat scene;
    std::string why;
    if (!radiance(pose, scene, why)) return error(CameraErrorKind::Device, why);
    out.image = exposeSensor(scene, effective_, options_.sensor, noise);
    out.format = PixelFormat::Bgr8;
    out.index = index;
    out.timestampS = index / options_.frameRate;
    out.camera = effective_;
    return std::nullopt;
}

std::optional<Config> SimulatedCamera::fittedConfig(const Config& base, std::string* error) const
{
    OpticsCell cell;
    cell.image = options_.image;  // the same camera open() builds: same image size and mirror
    const OpticsCamera camera = opticsCellCamera(cell, base);
    if (!camera.calibration || !camera.calibration->ok()) {
        if (error) *error = camera.calibration && camera.calibration->error ? *camera.calibration->error : "the fit failed";
        return std::nullopt;
    }
    return camera.calibration->config;
}

std::vector<CameraFeature> SimulatedCamera::features()
{
    const auto feature = [&](CameraFeatureId id, int max) {
        return CameraFeature{id, 0, max, field(registers_, id), false, false};
    };
    return {feature(CameraFeatureId::Exposure, 4095), feature(CameraFeatureId::Gain, 1023),
            feature(CameraFeatureId::Brightness, 1023), feature(CameraFeatureId::WhiteBalanceBlue, 1023),
            feature(CameraFeatureId::WhiteBalanceRed, 1023)};
}

std::optional<CameraError> SimulatedCamera::writeFeature(CameraFeatureId id, int value)
{
    if (unplugged_) return error(CameraErrorKind::Unplugged, "the camera stopped answering (unplugged?)");
    field(registers_, id) = value;
    const int delay = options_.settingsDelay ? 1 + delayRng_.uniform(0, 2) : 0;
    // Writes apply in order: a later write never overtakes an earlier one.
    const int at = std::max(next_ + delay, pending_.empty() ? 0 : pending_.back().effectiveAt);
    pending_.push_back({at, id, value});
    return std::nullopt;
}

std::optional<CameraError> SimulatedCamera::writeAuto(CameraFeatureId, bool)
{
    // No feature is auto-capable here, so Camera::setAuto only lets "off" through: nothing to do.
    return std::nullopt;
}

}  // namespace omnitune
