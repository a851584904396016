#pragma once
// How the simulated camera's sensor turns scene radiance into an 8-bit BGR frame under the
// camera's settings, like a real IIDC sensor does:
//   value = radiance * sensitivity_c * exposure/exposure_ref * 2^((gain - gain_ref)/gain_doubling)
//           * wb_c / wb_ref + brightness / brightness_step + noise,   clipped to 0..255
// with wb_c the white balance U/B register on blue, V/R on red (green has none), and noise
// Gaussian with a read part that the gain amplifies and a shot part that grows with the signal.
// The raw sensor is not neutral (sensitivity), so white balance has real work to do. These are
// the simulated sensor's physics, not tuning: the automatic calibration never reads them.
#include "core/CameraSettings.h"

#include <opencv2/core.hpp>

namespace omnitune {

struct SensorModel {
    double exposureRef = 300.0;  // register: exposure at which radiance passes 1:1 (at gain_ref)
    double gainRef = 200.0;      // register: gain of factor 1
    double gainDoubling = 256.0; // register steps that double the signal
    double wbRef = 512.0;        // register: white-balance gain 1
    cv::Vec3d sensitivity{0.8, 1.0, 1.2};  // BGR: the raw sensor sees blue weakly, red strongly
    double brightnessStep = 16.0;          // register steps per grey level of black offset
    double readNoise = 0.6;      // grey levels at gain 0, doubling with every gain_doubling steps
    double shotNoise = 0.12;     // grey levels per sqrt(grey level) of signal
};

// `radiance`: CV_32FC3 BGR, grey levels the scene would give at exposure_ref, gain_ref and a
// white balance of wb_ref on a neutral sensor. Returns CV_8UC3. Same inputs and rng state, same bytes.
cv::Mat exposeSensor(const cv::Mat& radiance, const CameraSettings& settings, const SensorModel& model, cv::RNG& rng);

}  // namespace omnitune
