#include "calib/camera/SensorModel.h"

#include <cmath>

namespace omnitune {

cv::Mat exposeSensor(const cv::Mat& radiance, const CameraSettings& s, const SensorModel& m, cv::RNG& rng)
{
    CV_Assert(radiance.type() == CV_32FC3);
    const double common = s.exposure / m.exposureRef * std::pow(2.0, (s.gain - m.gainRef) / m.gainDoubling);
    const cv::Vec3d wb{s.whiteBalanceBlue / m.wbRef, 1.0, s.whiteBalanceRed / m.wbRef};
    const cv::Vec3f scale(float(common * m.sensitivity[0] * wb[0]), float(common * m.sensitivity[1]),
                          float(common * m.sensitivity[2] * wb[2]));
    const float offset = float(s.brightness / m.brightnessStep);
    const float readSigma = float(m.readNoise * std::pow(2.0, s.gain / m.gainDoubling));
    const float shot = float(m.shotNoise);

    cv::Mat noise(radiance.size(), CV_32FC3);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, 1.0);
    cv::Mat out(radiance.size(), CV_8UC3);
    for (int y = 0; y < radiance.rows; ++y) {
        const cv::Vec3f* r = radiance.ptr<cv::Vec3f>(y);
        const cv::Vec3f* n = noise.ptr<cv::Vec3f>(y);
        cv::Vec3b* o = out.ptr<cv::Vec3b>(y);
        for (int x = 0; x < radiance.cols; ++x)
            for (int c = 0; c < 3; ++c) {
                const float signal = std::max(r[x][c] * scale[c], 0.0f);
                const float sigma = std::sqrt(readSigma * readSigma + shot * shot * signal);
                o[x][c] = cv::saturate_cast<uchar>(signal + offset + sigma * n[x][c]);
            }
    }
    return out;
}

}  // namespace omnitune
