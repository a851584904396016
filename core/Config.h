#pragma once
// Everything the detector needs, as plain option structs whose defaults are the thesis'
// numbers. Ranges, units and meanings live once in ConfigSchema; docs/config.md is made from it.
#include "Algorithm.h"
#include "BallModel.h"
#include "CameraSettings.h"
#include "ColorLut.h"
#include "DistanceMap.h"
#include "Edges.h"
#include "Geometry.h"
#include "OpenCvHough.h"
#include "RadialSensors.h"
#include "SpecificHough.h"
#include "Validation.h"

#include <opencv2/core.hpp>

namespace omnitune {

struct Config {
    CameraSettings camera;
    ColorLutOptions colors;
    GeometryOptions geometry;
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
