#pragma once
// The simulated camera: the optics simulator's scene (calib/sim/optics/) rendered as radiance
// and seen through a SensorModel whose exposure, gain, brightness and white balance act like a
// real sensor's. A written setting takes effect 1 or 2 frames later (drawn from the seed), as
// on an IIDC camera, so control loops meet the delay they meet at the venue. The robot moves
// along a tour of `poses` places, `framesPerPose` frames each, so frames change. A white and a
// black card sit on the robot's top plate (image centre), where the automatic calibration's
// default reference regions look. Frames come as fast as they are grabbed; timestamps follow
// the configured frame rate (no waiting). The places are rendered once, in tour order, on a
// thread of the camera's own started by the first open(), so a grab only waits for a place not
// rendered yet (the first) instead of stalling the grabbing thread (the window's GUI thread) at
// every new place. Deterministic: same options, same frames.
#include "calib/camera/Camera.h"
#include "calib/camera/SensorModel.h"
#include "core/CameraSettings.h"
#include "core/Config.h"

#include <atomic>
#include <condition_variable>
#include <deque>
#include <memory>
#include <optional>
#include <mutex>
#include <string>
#include <thread>

namespace omnitune {

class OpticsRenderer;
class CatadioptricCamera;

// How badly set the camera starts: `good` (the config defaults), `dark` (short exposure, no
// gain), `bright` (long exposure, high gain: whites clip), `tinted` (white balance far off).
enum class SimulatedStart { Good, Dark, Bright, Tinted };
std::string_view simulatedStartName(SimulatedStart s);
std::optional<SimulatedStart> parseSimulatedStart(std::string_view name);
// The settings a start state begins with.
CameraSettings simulatedStartSettings(SimulatedStart s);

struct SimulatedCameraOptions {
    SimulatedStart start = SimulatedStart::Good;
    unsigned seed = 1;
    cv::Size image{640, 480};
    int poses = 6;            // places along the tour
    int framesPerPose = 15;   // frames the robot stays at each
    double frameRate = 30.0;  // frames/s of the timestamps
    cv::Rect whiteCard{300, 180, 16, 10};  // px: the white reference card on the top plate
    cv::Rect blackCard{300, 290, 16, 10};  // px: the black reference card
    SensorModel sensor;
    bool settingsDelay = true;  // false: a write shows in the very next frame (for unit tests of other parts)
};

class SimulatedCamera : public Camera {
public:
    explicit SimulatedCamera(const SimulatedCameraOptions& options = {});
    ~SimulatedCamera() override;

    std::string description() const override;
    std::optional<CameraError> open() override;
    std::optional<CameraError> start() override;
    std::optional<CameraError> grab(Frame& out) override;
    void stop() override { started_ = false; }
    void close() override;
    bool isOpen() const override { return open_; }
    bool isStarted() const override { return started_; }
    cv::Size frameSize() const override { return open_ ? options_.image : cv::Size(); }
    std::vector<CameraFeature> features() override;

    // What the sensor applies now (the last frame's settings), unlike the registers features() reads.
    const CameraSettings& effectiveSettings() const { return effective_; }
    // The config a team would fit to this camera's optics (calib/fit/MeasuredCalibration.h:
    // rim, body, mask, distance map and ball model from the optics' measurements, never its
    // truth), starting from `base` (colours and thresholds stay). Slow the first time per
    // image size (the measurements are rendered, about a second), cached after; thread-safe.
    // Empty with `error` set when the fit fails.
    std::optional<Config> fittedConfig(const Config& base, std::string* error = nullptr) const;
    // Test hook: the next grab() fails as if the cable were pulled; later calls fail too until open().
    void simulateUnplug() { unplugged_ = true; }

protected:
    std::optional<CameraError> writeFeature(CameraFeatureId id, int value) override;
    std::optional<CameraError> writeAuto(CameraFeatureId id, bool on) override;

private:
    struct PendingWrite {
        int effectiveAt = 0;  // frame index from which the value applies
        CameraFeatureId id;
        int value = 0;
    };
    // The pose's radiance once the render thread has it; false (and `why`) when rendering failed.
    bool radiance(int pose, cv::Mat& out, std::string& why);
    void renderAll();  // the render thread

    SimulatedCameraOptions options_;
    std::unique_ptr<CatadioptricCamera> optics_;
    std::unique_ptr<OpticsRenderer> renderer_;
    std::vector<cv::Mat> radiance_;  // CV_32FC3 per pose, written once by the render thread (renderMutex_)
    std::string renderError_;        // why rendering stopped (renderMutex_)
    std::mutex renderMutex_;
    std::condition_variable rendered_;
    std::atomic<bool> stopRendering_{false};
    std::thread renderThread_;
    CameraSettings registers_;       // what was last written
    CameraSettings effective_;       // what the sensor applies
    std::deque<PendingWrite> pending_;
    cv::RNG delayRng_;
    int next_ = 0;  // index of the next frame
    bool open_ = false;
    bool started_ = false;
    bool unplugged_ = false;
};

}  // namespace omnitune
