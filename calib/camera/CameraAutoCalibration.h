#pragma once
// Automatic camera calibration, ref. [31] of the thesis (Neves, Cunha, Pinho, Pinheiro 2009),
// one iteration per step() so the window can run it live and the CLI in a loop:
//  1. drop `skip_frames` frames (a write takes effect a frame or two later), grab one, measure
//     the MSV of the intensity histogram over the used pixels, the white region's mean U and V,
//     and the black region's mean grey level;
//  2. if all are within tolerance: converged, nothing is written;
//  3. else PI controllers move exposure then gain (too bright: gain down first, then exposure)
//     towards the MSV target, white balance U/B and V/R towards neutral white, brightness towards
//     the black target, and write the features that changed.
// A feature held at its limit (or missing) while its error keeps its sign for `limit_iterations`
// iterations ends the run with a reason naming it; so does `max_iterations`. revert() writes back
// the settings read at begin(). Every number comes from CameraAutoOptions (config camera_auto.*).
#include "calib/camera/Camera.h"
#include "calib/camera/PiController.h"
#include "core/CameraAutoOptions.h"
#include "core/CameraSettings.h"

#include <opencv2/core.hpp>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace omnitune {

struct CameraMeasurement {
    double msv = 0.0;    // mean sample value, 1..regions
    double u = 0.0;      // white region's mean Cb, 0..255 (128 neutral)
    double v = 0.0;      // white region's mean Cr
    double black = 0.0;  // black region's mean grey level
    cv::Vec3d white;     // white region's mean B, G, R: a clipped channel makes U and V meaningless
    std::vector<double> histogram;  // pixels per intensity region (the MSV's), for the camera panel
};

// Measures a BGR frame. `usedMask` (empty: every pixel) selects the MSV's pixels. Returns a
// reason instead when a reference region is not inside the frame or the mask is of another size.
std::optional<std::string> measureCameraFrame(const cv::Mat& bgr, const cv::Mat& usedMask, const CameraAutoOptions& options,
                                              CameraMeasurement& out);

cv::Rect whiteRegion(const CameraAutoOptions& options);
cv::Rect blackRegion(const CameraAutoOptions& options);

struct CameraAutoIteration {
    int iteration = 0;          // 1-based
    CameraMeasurement measured;
    CameraSettings settings;    // exposure, gain, brightness, white balance the frame was taken with (read back)
    bool withinTolerance = false;
};

enum class CameraAutoState { Idle, Running, Converged, Failed };

class CameraAutoCalibration {
public:
    // `camera` must be open and outlive this. `usedMask`: the pixels the MSV counts (the
    // geometry's ring: Geometry(config.geometry, config.mask).usedMask()); empty: the whole frame.
    CameraAutoCalibration(Camera& camera, const CameraAutoOptions& options, cv::Mat usedMask = {});

    // Reads the settings to revert to and starts the camera if it is not; turns the camera's own
    // auto modes off for the features it drives.
    std::optional<CameraError> begin();
    // One iteration (see above). A camera error ends the run (state Failed) and is returned.
    // Grabs from the camera itself: skip_frames + 1 frames.
    std::optional<CameraError> step(CameraAutoIteration& out);
    // The same fed one frame at a time by a caller that grabs (the window's live view, so the
    // frames the calibration looks at reach the panes): the first `skip_frames` frames after an
    // iteration are only counted; the next is measured (`measured`, `out` filled) and may write.
    // A frame grabbed elsewhere in between is not counted, which only waits longer.
    std::optional<CameraError> take(const Frame& frame, CameraAutoIteration& out, bool& measured);
    // Ends a running run as failed with `reason` (the caller's grab failed).
    void abort(const std::string& reason) { fail(reason); }

    CameraAutoState state() const { return state_; }
    // Why the run failed, in words; empty otherwise.
    const std::string& reason() const { return reason_; }
    int iterations() const { return iteration_; }
    const CameraSettings& before() const { return before_; }
    // Writes back the settings read at begin().
    std::optional<CameraError> revert();

private:
    bool within(const CameraMeasurement& m) const;
    // Moves feature `id` by `delta` (fraction of its range); false when it is missing or at the
    // limit in that direction (`low`, `high`: the limits the calibration may use).
    bool move(CameraFeatureId id, double delta, std::optional<int> low = std::nullopt, std::optional<int> high = std::nullopt);
    bool has(CameraFeatureId id) const { return features_.count(id) > 0; }
    void fail(std::string reason);

    Camera& camera_;
    CameraAutoOptions options_;
    cv::Mat usedMask_;
    std::map<CameraFeatureId, CameraFeature> features_;  // what the camera has, with ranges
    std::map<CameraFeatureId, double> command_;          // unrounded register values the controllers drive
    std::map<std::string, int> limitCount_;              // per quantity: iterations it could not be corrected
    CameraSettings before_;
    CameraAutoState state_ = CameraAutoState::Idle;
    std::string reason_;
    int iteration_ = 0;
    int skipped_ = 0;  // frames taken since the last measurement
    PiController exposurePi_, gainPi_, bluePi_, redPi_, brightnessPi_;
    bool exposureActive_ = true;  // which of exposure and gain the MSV drives now
};

// Runs begin() and step() until converged or failed, calling `onIteration` after every step.
struct CameraAutoResult {
    CameraAutoState state = CameraAutoState::Idle;
    std::string reason;                  // why not converged
    std::optional<CameraError> error;    // a camera error that ended it
    CameraAutoIteration last;            // the last measurement
    int iterations = 0;
};
CameraAutoResult runCameraAutoCalibration(Camera& camera, const CameraAutoOptions& options, const cv::Mat& usedMask,
                                          const std::function<void(const CameraAutoIteration&)>& onIteration = {});

// "msv=2.47 wb_u=127.9 wb_v=128.3 black=20.1": the measurement as the CLI prints it.
std::string formatCameraMeasurement(const CameraMeasurement& m);

}  // namespace omnitune
