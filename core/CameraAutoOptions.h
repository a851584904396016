#pragma once
// The automatic camera calibration (calib/camera/CameraAutoCalibration.h; thesis ch. 4 and its
// ref. [31], Neves, Cunha, Pinho, Pinheiro 2009): PI controllers drive exposure, then gain, so
// that the mean sample value (MSV) of the intensity histogram reaches its target; white balance
// so that a white reference region has neutral chroma; brightness so that a black reference
// region reaches its level. Controller gains are in fractions of the feature's range per unit of
// error, so one set serves cameras whose registers differ. Ranges and meanings: ConfigSchema.
namespace omnitune {

struct CameraAutoOptions {
    int histogramRegions = 5;      // regions of the intensity histogram the MSV sums over (ref. [31])
    double msvTarget = 2.5;        // MSV the exposure and gain aim for, 1..regions (ref. [31])
    double msvTolerance = 0.2;     // |MSV - target| accepted as converged
    double exposureKp = 0.01;      // range/MSV: proportional gain on exposure
    double exposureKi = 0.03;      // range/MSV per iteration: integral gain on exposure
    double gainKp = 0.02;          // range/MSV: proportional gain on gain
    double gainKi = 0.06;          // range/MSV per iteration: integral gain on gain
    int exposureMax = 4095;        // register: exposure is not raised above this (motion blur); gain takes over
    int gainMin = 0;               // register: gain is lowered to this before exposure is
    int gainMax = 1023;            // register: gain is not raised above this (noise)
    double chromaTarget = 128.0;   // U and V of the white region for neutral white (8-bit YCbCr)
    double chromaTolerance = 3.0;  // |U - target| and |V - target| accepted
    double whiteClip = 250.0;      // a white-region channel mean at or above this is clipped
    double whiteBalanceKp = 0.001; // range/level: proportional gain on white balance U/B and V/R
    double whiteBalanceKi = 0.003; // range/level per iteration: integral gain on white balance
    double blackTarget = 20.0;     // mean grey level of the black region
    double blackTolerance = 3.0;   // |black - target| accepted
    double brightnessKp = 0.002;   // range/level: proportional gain on brightness
    double brightnessKi = 0.006;   // range/level per iteration: integral gain on brightness
    int skipFrames = 3;            // frames dropped after a write before measuring (the camera's delay)
    int maxIterations = 40;        // iterations before giving up
    int limitIterations = 3;       // iterations at a feature's limit with the error unchanged in sign: give up
    // Reference regions, px: a white and a black card on the robot's top plate.
    int whiteX = 302, whiteY = 182, whiteWidth = 12, whiteHeight = 6;
    int blackX = 302, blackY = 292, blackWidth = 12, blackHeight = 6;
};

}  // namespace omnitune
