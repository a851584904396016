#pragma once
// Everything the detector needs, as plain option structs whose defaults are the thesis'
// numbers. Ranges, units and meanings live once in ConfigSchema; docs/config.md is made from it.
#include "core/Algorithm.h"
#include "core/BallModel.h"
#include "core/CameraAutoOptions.h"
#include "core/CameraSettings.h"
#include "core/ColorLut.h"
#include "core/DistanceMap.h"
#include "core/Edges.h"
#include "core/FrameDenoise.h"
#include "core/Geometry.h"
#include "core/OpenCvHough.h"
#include "core/RadialSensors.h"
#include "core/SpecificHough.h"
#include "core/Validation.h"

#include <opencv2/core.hpp>

namespace omnitune {

struct Config {
    CameraSettings camera;
    CameraAutoOptions cameraAuto;
    ColorLutOptions colors;
    GeometryOptions geometry;
    DenoiseOptions denoise;
    RadialSensorOptions sensors;
    DistanceMapOptions distanceMap;
    BallModelOptions ball;
    EdgeOptions edges;
    SpecificHoughOptions hough;
    OpenCvHoughOptions opencvHough;
    ValidationOptions validation;
    Algorithm algorithm = Algorithm::Combined;

    // The mask image named by geometry.maskFile (CV_8UC1, 255 = process), loaded beside the
    // config and written back by saveConfig. Empty: no mask beyond the two radii.
    cv::Mat mask;
};

}  // namespace omnitune
