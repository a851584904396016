#include "calib/camera/CameraAutoCalibration.h"

#include "calib/camera/CameraSettingsIo.h"
#include "calib/camera/MeanSampleValue.h"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <cstdio>

namespace omnitune {

namespace {

std::string fixed(double v, int decimals)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::string rectText(cv::Rect r)
{
    return std::to_string(r.x) + "," + std::to_string(r.y) + " " + std::to_string(r.width) + "x" + std::to_string(r.height);
}

constexpr CameraFeatureId kDriven[] = {CameraFeatureId::Exposure, CameraFeatureId::Gain, CameraFeatureId::Brightness,
                                       CameraFeatureId::WhiteBalanceBlue, CameraFeatureId::WhiteBalanceRed};

}  // namespace

cv::Rect whiteRegion(const CameraAutoOptions& o) { return {o.whiteX, o.whiteY, o.whiteWidth, o.whiteHeight}; }
cv::Rect blackRegion(const CameraAutoOptions& o) { return {o.blackX, o.blackY, o.blackWidth, o.blackHeight}; }

std::optional<std::string> measureCameraFrame(const cv::Mat& bgr, const cv::Mat& usedMask, const CameraAutoOptions& o,
                                              CameraMeasurement& out)
{
    CV_Assert(bgr.type() == CV_8UC3);
    const cv::Rect frame({}, bgr.size());
    const std::string size = std::to_string(bgr.cols) + "x" + std::to_string(bgr.rows);
    if ((whiteRegion(o) & frame) != whiteRegion(o))
        return "the white region (camera_auto.white_*: " + rectText(whiteRegion(o)) + ") is not inside the " + size + " frame";
    if ((blackRegion(o) & frame) != blackRegion(o))
        return "the black region (camera_auto.black_*: " + rectText(blackRegion(o)) + ") is not inside the " + size + " frame";
    if (!usedMask.empty() && usedMask.size() != bgr.size())
        return "the geometry is for " + std::to_string(usedMask.cols) + "x" + std::to_string(usedMask.rows) +
               " frames but the camera gives " + size;
    cv::Mat grey;
    cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
    out.histogram = regionHistogram(grey, usedMask, o.histogramRegions);
    out.msv = meanSampleValue(out.histogram);
    cv::Mat ycrcb;
    cv::cvtColor(bgr(whiteRegion(o)), ycrcb, cv::COLOR_BGR2YCrCb);
    const cv::Scalar white = cv::mean(ycrcb);
    out.v = white[1];
    out.u = white[2];
    const cv::Scalar whiteBgr = cv::mean(bgr(whiteRegion(o)));
    out.white = {whiteBgr[0], whiteBgr[1], whiteBgr[2]};
    out.black = cv::mean(grey(blackRegion(o)))[0];
    return std::nullopt;
}

std::string formatCameraMeasurement(const CameraMeasurement& m)
{
    return "msv=" + fixed(m.msv, 2) + " wb_u=" + fixed(m.u, 1) + " wb_v=" + fixed(m.v, 1) + " black=" + fixed(m.black, 1);
}

CameraAutoCalibration::CameraAutoCalibration(Camera& camera, const CameraAutoOptions& options, cv::Mat usedMask)
    : camera_(camera), options_(options), usedMask_(std::move(usedMask)),
      exposurePi_(options.exposureKp, options.exposureKi), gainPi_(options.gainKp, options.gainKi),
      bluePi_(options.whiteBalanceKp, options.whiteBalanceKi), redPi_(options.whiteBalanceKp, options.whiteBalanceKi),
      brightnessPi_(options.brightnessKp, options.brightnessKi)
{
}

std::optional<CameraError> CameraAutoCalibration::begin()
{
    features_.clear();
    command_.clear();
    limitCount_.clear();
    iteration_ = 0;
    skipped_ = 0;
    reason_.clear();
    for (CameraFeatureId id : kDriven) {
        CameraFeature f;
        const auto err = camera_.readFeature(id, f);
        if (err && err->kind == CameraErrorKind::FeatureUnsupported) continue;
        if (err) return err;
        if (f.autoOn)
            if (auto e = camera_.setAuto(id, false)) return e;
        features_[id] = f;
        command_[id] = f.value;
        *cameraSettingsField(before_, id) = f.value;
    }
    if (!has(CameraFeatureId::Exposure) && !has(CameraFeatureId::Gain)) {
        fail("the camera has neither exposure nor gain to adjust");
        return std::nullopt;
    }
    if (!camera_.isStarted())
        if (auto err = camera_.start()) return err;
    state_ = CameraAutoState::Running;
    return std::nullopt;
}

void CameraAutoCalibration::fail(std::string reason)
{
    state_ = CameraAutoState::Failed;
    reason_ = std::move(reason);
}

bool CameraAutoCalibration::within(const CameraMeasurement& m) const
{
    const auto& o = options_;
    const bool unclipped = std::max({m.white[0], m.white[1], m.white[2]}) < o.whiteClip;
    const bool wb = !has(CameraFeatureId::WhiteBalanceBlue) ||
                    (unclipped && std::abs(m.u - o.chromaTarget) <= o.chromaTolerance &&
                     std::abs(m.v - o.chromaTarget) <= o.chromaTolerance);
    const bool black = !has(CameraFeatureId::Brightness) || std::abs(m.black - o.blackTarget) <= o.blackTolerance;
    return std::abs(m.msv - o.msvTarget) <= o.msvTolerance && wb && black;
}

bool CameraAutoCalibration::move(CameraFeatureId id, double delta, std::optional<int> low, std::optional<int> high)
{
    const auto it = features_.find(id);
    if (it == features_.end()) return false;
    const CameraFeature& f = it->second;
    const double lo = std::max(f.min, low.value_or(f.min));
    const double hi = std::min(f.max, high.value_or(f.max));
    double& cmd = command_[id];
    if ((delta > 0 && cmd >= hi) || (delta < 0 && cmd <= lo)) return false;
    cmd = std::clamp(cmd + delta * (f.max - f.min), lo, hi);
    return true;
}

std::optional<CameraError> CameraAutoCalibration::step(CameraAutoIteration& out)
{
    while (state_ == CameraAutoState::Running) {
        Frame frame;
        if (auto err = camera_.grab(frame)) {
            fail(err->message);
            return err;
        }
        bool measured = false;
        if (auto err = take(frame, out, measured)) return err;
        if (measured) break;
    }
    return std::nullopt;
}

std::optional<CameraError> CameraAutoCalibration::take(const Frame& frame, CameraAutoIteration& out, bool& measured)
{
    measured = false;
    if (state_ != CameraAutoState::Running) return std::nullopt;
    if (skipped_ < options_.skipFrames) {  // taken before the last write had surely taken effect
        ++skipped_;
        return std::nullopt;
    }
    skipped_ = 0;
    measured = true;
    CameraMeasurement m;
    if (auto why = measureCameraFrame(frame.image, usedMask_, options_, m)) {
        fail(*why);
        return std::nullopt;
    }
    ++iteration_;
    out = CameraAutoIteration{};
    out.iteration = iteration_;
    out.measured = m;
    out.settings = frame.camera.value_or(CameraSettings{});
    if (!frame.camera)  // a source that does not know: what the registers say
        for (const auto& [id, f] : features_) *cameraSettingsField(out.settings, id) = int(std::lround(command_[id]));
    out.withinTolerance = within(m);
    if (out.withinTolerance) {
        state_ = CameraAutoState::Converged;
        return std::nullopt;
    }
    const auto& o = options_;
    // Counts iterations a quantity could not be corrected because its features sit at a limit.
    // White and black levels scale with the exposure: their limits count only once the MSV is
    // within tolerance, or a bright start would give up on brightness before exposure came down.
    const bool exposed = std::abs(o.msvTarget - m.msv) <= o.msvTolerance;
    const auto stuck = [&](const std::string& key, bool moved, const std::string& why) {
        int& n = limitCount_[key];
        n = moved || (key != "msv" && !exposed) ? 0 : n + 1;
        if (n >= o.limitIterations && state_ == CameraAutoState::Running) fail(why);
    };

    // "exposure 80" or "no exposure": for the reasons below.
    const auto valueText = [&](CameraFeatureId id) {
        const std::string name(cameraFeatureName(id));
        return has(id) ? name + " " + std::to_string(std::lround(command_[id])) : "no " + name;
    };
    // Exposure first, then gain: too dark raises exposure up to exposure_max, then gain; too
    // bright lowers gain down to gain_min, then exposure.
    const double e = o.msvTarget - m.msv;
    if (std::abs(e) > o.msvTolerance) {
        const bool useExposure = e > 0 ? has(CameraFeatureId::Exposure) && command_[CameraFeatureId::Exposure] < std::min(features_[CameraFeatureId::Exposure].max, o.exposureMax)
                                       : !has(CameraFeatureId::Gain) || command_[CameraFeatureId::Gain] <= std::max(features_[CameraFeatureId::Gain].min, o.gainMin);
        if (useExposure != exposureActive_) {
            exposurePi_.reset();
            gainPi_.reset();
            exposureActive_ = useExposure;
        }
        const bool moved = useExposure ? move(CameraFeatureId::Exposure, exposurePi_.update(e), std::nullopt, o.exposureMax)
                                       : move(CameraFeatureId::Gain, gainPi_.update(e), o.gainMin, o.gainMax);
        stuck("msv", moved,
              e > 0 ? "exposure and gain at their upper limits (" + valueText(CameraFeatureId::Exposure) +
                          ", exposure_max " + std::to_string(o.exposureMax) + "; " + valueText(CameraFeatureId::Gain) +
                          ", gain_max " + std::to_string(o.gainMax) + ") and the image is still too dark: msv " +
                          fixed(m.msv, 2) + ", target " + fixed(o.msvTarget, 2)
                    : "exposure and gain at their lower limits (" + valueText(CameraFeatureId::Exposure) + "; " +
                          valueText(CameraFeatureId::Gain) + ", gain_min " + std::to_string(o.gainMin) +
                          ") and the image is still too bright: msv " + fixed(m.msv, 2) + ", target " +
                          fixed(o.msvTarget, 2));
    }
    // White balance: U below neutral wants more blue, V above neutral less red. A clipped blue
    // or red channel reads as neutral when it is not: its gain comes down first. A clipped green
    // is the exposure's doing, which white balance cannot mend.
    const double clipPush = -2.0 * o.chromaTolerance;
    const double eu = m.white[0] >= o.whiteClip ? std::min(o.chromaTarget - m.u, clipPush) : o.chromaTarget - m.u;
    const double ev = m.white[2] >= o.whiteClip ? std::min(o.chromaTarget - m.v, clipPush) : o.chromaTarget - m.v;
    if (has(CameraFeatureId::WhiteBalanceBlue) && std::abs(eu) > o.chromaTolerance)
        stuck("wb_u", move(CameraFeatureId::WhiteBalanceBlue, bluePi_.update(eu)),
              "white balance U/B at its limit and the white region is still not neutral: u " + fixed(m.u, 1));
    if (has(CameraFeatureId::WhiteBalanceRed) && std::abs(ev) > o.chromaTolerance)
        stuck("wb_v", move(CameraFeatureId::WhiteBalanceRed, redPi_.update(ev)),
              "white balance V/R at its limit and the white region is still not neutral: v " + fixed(m.v, 1));
    if (m.white[1] >= o.whiteClip)
        stuck("white_clip", false,
              "the white region clips (green " + fixed(m.white[1], 0) + ") at the exposure the MSV target asks for: "
              "a greyer card or a lower camera_auto.msv_target");
    if (has(CameraFeatureId::Brightness) && std::abs(m.black - o.blackTarget) > o.blackTolerance)
        stuck("black", move(CameraFeatureId::Brightness, brightnessPi_.update(o.blackTarget - m.black)),
              "brightness at its limit and the black region is still at " + fixed(m.black, 1) + ", target " +
                  fixed(o.blackTarget, 1));
    if (state_ != CameraAutoState::Running) return std::nullopt;
    if (iteration_ >= o.maxIterations) {
        fail("no convergence after " + std::to_string(iteration_) + " iterations (" + formatCameraMeasurement(m) + ")");
        return std::nullopt;
    }
    for (auto& [id, f] : features_) {
        const int value = int(std::lround(command_[id]));
        if (value == f.value) continue;
        if (auto err = camera_.setFeature(id, value)) {
            fail(err->message);
            return err;
        }
        f.value = value;
    }
    return std::nullopt;
}

std::optional<CameraError> CameraAutoCalibration::revert()
{
    for (auto& [id, f] : features_) {
        if (auto err = camera_.setFeature(id, *cameraSettingsField(before_, id))) return err;
        f.value = *cameraSettingsField(before_, id);
        command_[id] = f.value;
    }
    state_ = CameraAutoState::Idle;
    return std::nullopt;
}

CameraAutoResult runCameraAutoCalibration(Camera& camera, const CameraAutoOptions& options, const cv::Mat& usedMask,
                                          const std::function<void(const CameraAutoIteration&)>& onIteration)
{
    CameraAutoResult result;
    CameraAutoCalibration calibration(camera, options, usedMask);
    result.error = calibration.begin();
    while (!result.error && calibration.state() == CameraAutoState::Running) {
        CameraAutoIteration it;
        result.error = calibration.step(it);
        if (it.iteration > 0) {
            result.last = it;
            if (onIteration) onIteration(it);
        }
    }
    result.state = result.error ? CameraAutoState::Failed : calibration.state();
    result.reason = result.error ? result.error->message : calibration.reason();
    result.iterations = calibration.iterations();
    return result;
}

}  // namespace omnitune
