#include "core/ConfigSchema.h"

#include "core/ColourClassesYaml.h"
#include "core/RingCoverage.h"
#include "core/YamlText.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace omnitune {

namespace {

// Builders: `ref` is a generic lambda returning the field of a (const or mutable) Config.
template <class F>
ConfigKey intKey(std::string path, std::string unit, int min, int max, bool thesis, std::string meaning, F ref)
{
    ConfigKey k{std::move(path), ValueType::Int, std::move(unit), double(min), double(max), std::move(meaning), {}, thesis, {}, {}};
    k.get = [ref](const Config& c) { return ConfigValue(int(ref(c))); };
    k.set = [ref](Config& c, const ConfigValue& v) { ref(c) = std::get<int>(v); };
    return k;
}

template <class F>
ConfigKey doubleKey(std::string path, std::string unit, double min, double max, bool thesis, std::string meaning, F ref)
{
    ConfigKey k{std::move(path), ValueType::Double, std::move(unit), min, max, std::move(meaning), {}, thesis, {}, {}};
    k.get = [ref](const Config& c) { return ConfigValue(double(ref(c))); };
    k.set = [ref](Config& c, const ConfigValue& v) { ref(c) = std::get<double>(v); };
    return k;
}

template <class F>
ConfigKey boolKey(std::string path, bool thesis, std::string meaning, F ref)
{
    ConfigKey k{std::move(path), ValueType::Bool, "", 0, 1, std::move(meaning), {}, thesis, {}, {}};
    k.get = [ref](const Config& c) { return ConfigValue(bool(ref(c))); };
    k.set = [ref](Config& c, const ConfigValue& v) { ref(c) = std::get<bool>(v); };
    return k;
}

template <class F>
ConfigKey textKey(std::string path, std::string meaning, F ref)
{
    ConfigKey k{std::move(path), ValueType::Text, "", 0, 0, std::move(meaning), {}, false, {}, {}};
    k.get = [ref](const Config& c) { return ConfigValue(std::string(ref(c))); };
    k.set = [ref](Config& c, const ConfigValue& v) { ref(c) = std::get<std::string>(v); };
    return k;
}

template <class F>
ConfigKey listKey(std::string path, std::string unit, double min, double max, bool thesis, std::string meaning, F ref)
{
    ConfigKey k{std::move(path), ValueType::DoubleList, std::move(unit), min, max, std::move(meaning), {}, thesis, {}, {}};
    k.get = [ref](const Config& c) { return ConfigValue(std::vector<double>(ref(c))); };
    k.set = [ref](Config& c, const ConfigValue& v) { ref(c) = std::get<std::vector<double>>(v); };
    return k;
}

std::vector<ConfigKey> buildSchema()
{
    std::vector<ConfigKey> s;
    // camera
    s.push_back(textKey("camera.model", "Camera model, informational (e.g. \"PointGrey Flea2\")",
                        [](auto& c) -> auto& { return c.camera.model; }));
    s.push_back(doubleKey("camera.frame_rate", "frames/s", 1, 240, true, "Acquisition rate; the per-frame time budget is its inverse",
                          [](auto& c) -> auto& { return c.camera.frameRate; }));
    s.push_back(intKey("camera.exposure", "register", 0, 4095, false, "IIDC exposure; too high blurs a moving ball, too low darkens the carpet",
                       [](auto& c) -> auto& { return c.camera.exposure; }));
    s.push_back(intKey("camera.white_balance_blue", "register", 0, 1023, false, "IIDC white balance U/B",
                       [](auto& c) -> auto& { return c.camera.whiteBalanceBlue; }));
    s.push_back(intKey("camera.white_balance_red", "register", 0, 1023, false, "IIDC white balance V/R",
                       [](auto& c) -> auto& { return c.camera.whiteBalanceRed; }));
    s.push_back(intKey("camera.gain", "register", 0, 1023, false, "IIDC gain; high gain adds noise that breaks edges",
                       [](auto& c) -> auto& { return c.camera.gain; }));
    s.push_back(intKey("camera.brightness", "register", 0, 1023, false, "IIDC brightness (black level)",
                       [](auto& c) -> auto& { return c.camera.brightness; }));
    s.push_back(textKey("camera.source",
                        "Camera to open: dc1394, dc1394:GUID, v4l2, v4l2:/dev/videoN or simulated; empty: the first camera found. "
                        "The settings above are written to it when it opens",
                        [](auto& c) -> auto& { return c.camera.source; }));
    s.push_back(doubleKey("camera.replay_seconds", "s", 1, 120, false,
                          "Live frames the window keeps to step through after a pause (memory: this x frame rate x one frame)",
                          [](auto& c) -> auto& { return c.camera.replaySeconds; }));
    s.push_back(intKey("camera.record_min_free_mb", "MB", 0, 100000000, false,
                       "A recording from the window or omnitune-camera stops cleanly when its disk has less free space",
                       [](auto& c) -> auto& { return c.camera.recordMinFreeMb; }));

    // automatic camera calibration (ref. [31] of the thesis)
    const auto autoInt = [&s](const char* key, const char* unit, int min, int max, const char* meaning, auto ref) {
        s.push_back(intKey(std::string("camera_auto.") + key, unit, min, max, false, meaning, ref));
    };
    const auto autoDouble = [&s](const char* key, const char* unit, double min, double max, const char* meaning, auto ref) {
        s.push_back(doubleKey(std::string("camera_auto.") + key, unit, min, max, false, meaning, ref));
    };
    autoInt("histogram_regions", "regions", 2, 16, "Regions of equal width the intensity histogram is cut into; the MSV is their mean index, 1..regions",
            [](auto& c) -> auto& { return c.cameraAuto.histogramRegions; });
    autoDouble("msv_target", "MSV", 1, 16, "Mean sample value exposure and gain aim for; the middle of the regions is neutral, lower is darker",
               [](auto& c) -> auto& { return c.cameraAuto.msvTarget; });
    autoDouble("msv_tolerance", "MSV", 0.01, 2, "Accepted distance of the MSV from its target; too small never settles in noise",
               [](auto& c) -> auto& { return c.cameraAuto.msvTolerance; });
    autoDouble("exposure_kp", "range/MSV", 0, 1, "Proportional gain of the exposure controller, in fractions of the exposure range per MSV",
               [](auto& c) -> auto& { return c.cameraAuto.exposureKp; });
    autoDouble("exposure_ki", "range/MSV", 0, 1, "Integral gain of the exposure controller per iteration; too high oscillates, too low is slow",
               [](auto& c) -> auto& { return c.cameraAuto.exposureKi; });
    autoDouble("gain_kp", "range/MSV", 0, 1, "Proportional gain of the gain controller, in fractions of the gain range per MSV",
               [](auto& c) -> auto& { return c.cameraAuto.gainKp; });
    autoDouble("gain_ki", "range/MSV", 0, 1, "Integral gain of the gain controller per iteration",
               [](auto& c) -> auto& { return c.cameraAuto.gainKi; });
    autoInt("exposure_max", "register", 0, 65535, "Exposure is never raised above this (a long exposure blurs a moving ball); gain takes over",
            [](auto& c) -> auto& { return c.cameraAuto.exposureMax; });
    autoInt("gain_min", "register", 0, 65535, "Gain is lowered to this before exposure is lowered",
            [](auto& c) -> auto& { return c.cameraAuto.gainMin; });
    autoInt("gain_max", "register", 0, 65535, "Gain is never raised above this (high gain adds noise that breaks edges)",
            [](auto& c) -> auto& { return c.cameraAuto.gainMax; });
    autoDouble("chroma_target", "0..255", 0, 255, "U and V of the white region for neutral white (8-bit YCbCr: grey is the middle of the range)",
               [](auto& c) -> auto& { return c.cameraAuto.chromaTarget; });
    autoDouble("chroma_tolerance", "0..255", 0.1, 64, "Accepted distance of the white region's U and V from the target",
               [](auto& c) -> auto& { return c.cameraAuto.chromaTolerance; });
    autoDouble("white_clip", "0..255", 1, 255, "A white-region channel whose mean reaches this is clipped: its white-balance gain comes down first, and a clipped green ends the run",
               [](auto& c) -> auto& { return c.cameraAuto.whiteClip; });
    autoDouble("white_balance_kp", "range/level", 0, 1, "Proportional gain of the white-balance controllers (U/B from U, V/R from V)",
               [](auto& c) -> auto& { return c.cameraAuto.whiteBalanceKp; });
    autoDouble("white_balance_ki", "range/level", 0, 1, "Integral gain of the white-balance controllers per iteration",
               [](auto& c) -> auto& { return c.cameraAuto.whiteBalanceKi; });
    autoDouble("black_target", "0..255", 0, 255, "Mean grey level the black region should have; 0 clips the dark colours' noise",
               [](auto& c) -> auto& { return c.cameraAuto.blackTarget; });
    autoDouble("black_tolerance", "0..255", 0.1, 64, "Accepted distance of the black region's level from the target",
               [](auto& c) -> auto& { return c.cameraAuto.blackTolerance; });
    autoDouble("brightness_kp", "range/level", 0, 1, "Proportional gain of the brightness controller",
               [](auto& c) -> auto& { return c.cameraAuto.brightnessKp; });
    autoDouble("brightness_ki", "range/level", 0, 1, "Integral gain of the brightness controller per iteration",
               [](auto& c) -> auto& { return c.cameraAuto.brightnessKi; });
    autoInt("skip_frames", "frames", 0, 30, "Frames dropped after a write before measuring, so the new setting has taken effect",
            [](auto& c) -> auto& { return c.cameraAuto.skipFrames; });
    autoInt("max_iterations", "iterations", 1, 1000, "Iterations before the calibration gives up",
            [](auto& c) -> auto& { return c.cameraAuto.maxIterations; });
    autoInt("limit_iterations", "iterations", 1, 100, "Iterations a needed feature may sit at its limit before the calibration reports it cannot converge",
            [](auto& c) -> auto& { return c.cameraAuto.limitIterations; });
    autoInt("white_x", "px", 0, 4096, "White reference region (a white card on the robot), left", [](auto& c) -> auto& { return c.cameraAuto.whiteX; });
    autoInt("white_y", "px", 0, 4096, "White reference region, top", [](auto& c) -> auto& { return c.cameraAuto.whiteY; });
    autoInt("white_width", "px", 1, 4096, "White reference region, width", [](auto& c) -> auto& { return c.cameraAuto.whiteWidth; });
    autoInt("white_height", "px", 1, 4096, "White reference region, height", [](auto& c) -> auto& { return c.cameraAuto.whiteHeight; });
    autoInt("black_x", "px", 0, 4096, "Black reference region (a black card on the robot), left", [](auto& c) -> auto& { return c.cameraAuto.blackX; });
    autoInt("black_y", "px", 0, 4096, "Black reference region, top", [](auto& c) -> auto& { return c.cameraAuto.blackY; });
    autoInt("black_width", "px", 1, 4096, "Black reference region, width", [](auto& c) -> auto& { return c.cameraAuto.blackWidth; });
    autoInt("black_height", "px", 1, 4096, "Black reference region, height", [](auto& c) -> auto& { return c.cameraAuto.blackHeight; });

    // colour classes
    s.push_back(intKey("colors.lut_bits", "bits", 4, 8, false,
                       "LUT index bits per channel: the table has 2^(3*bits) entries; more bits leave the L2 cache (see docs/performance.md), fewer coarsen class borders",
                       [](auto& c) -> auto& { return c.colors.bits; }));
    s.push_back(boolKey("colors.black_relative", false,
                        "Black relative to each frame's carpet: black (the first class of role black) is what is darker than "
                        "black_v_ratio x the median V of the field classes, whatever its hue, and field classes have no V floor "
                        "(the black classes' boxes and the field boxes' V min unused; the black boxes' highest V max only when a "
                        "frame shows no carpet). Off: thesis, black is its fixed HSV box, which in dim "
                        "light turns the carpet into black speckle (simulated dim tours: 0-2 % of balls found, 82-90 % with it on)",
                        [](auto& c) -> auto& { return c.colors.blackRelative; }));
    s.push_back(doubleKey("colors.black_v_ratio", "ratio", 0.05, 0.95, false,
                          "With black_relative: black is V <= this x the carpet's median V (measured per frame on 1/8 of the "
                          "ring's pixels); higher takes in shadows and dark carpet, lower leaves dim robots non-black",
                          [](auto& c) -> auto& { return c.colors.blackVRatio; }));
    s.push_back(doubleKey("colors.sample_outlier_percent", "%", 0.0, 25.0, false,
                          "Colours tab sampling: share of a stroke's colours ignored at each end of H, S and V when a box grows "
                          "to hold them (stray pixels at a ball's blurred rim); 0 covers every sample. Not used by the detector",
                          [](auto& c) -> auto& { return c.colors.sampleOutlierPct; }));

    // frame denoise (before segmentation)
    s.push_back(doubleKey("denoise.above_noise", "levels", 0.0, 255.0, false,
                          "A frame whose sensor noise (sigma of the green channel over the ring, estimated from the frame: "
                          "core/FrameNoise.h) is above this is blurred before segmentation (3x3 Gaussian, blur_sigma): "
                          "noise turns carpet pixels into other classes and breaks a small ball's outline. Clean frames read "
                          "1.5-3, noisy ones 5-6 on the optics matrix; a clean frame is not blurred, which would cost far balls "
                          "their contrast. A UYVY frame's green is rebuilt from Y, U and V; its pairs share their colour, so "
                          "the same noise reads about three quarters as high (noisy 3.9-4.5), and only its U and V are blurred. "
                          "0: never (thesis)",
                          [](auto& c) -> auto& { return c.denoise.aboveNoise; }));
    s.push_back(doubleKey("denoise.blur_sigma", "px", 0.1, 3.0, false,
                          "above_noise: the 3x3 Gaussian's sigma; larger smooths more noise and blurs small balls more",
                          [](auto& c) -> auto& { return c.denoise.blurSigma; }));

    // geometry
    s.push_back(intKey("geometry.image_width", "px", 16, 4096, true, "Frame width this geometry belongs to; other frame sizes are refused",
                       [](auto& c) -> auto& { return c.geometry.imageWidth; }));
    s.push_back(intKey("geometry.image_height", "px", 16, 4096, true, "Frame height this geometry belongs to",
                       [](auto& c) -> auto& { return c.geometry.imageHeight; }));
    s.push_back(doubleKey("geometry.center_x", "px", 0, 4096, false, "Robot centre (mirror axis) in the image, x",
                          [](auto& c) -> auto& { return c.geometry.centerX; }));
    s.push_back(doubleKey("geometry.center_y", "px", 0, 4096, false, "Robot centre in the image, y",
                          [](auto& c) -> auto& { return c.geometry.centerY; }));
    s.push_back(doubleKey("geometry.inner_radius", "px", 0, 2048, false, "Pixels closer to the centre are the robot itself and never processed",
                          [](auto& c) -> auto& { return c.geometry.innerRadius; }));
    s.push_back(doubleKey("geometry.outer_radius", "px", 1, 2048, true, "Pixels farther from the centre are outside the mirror and never processed",
                          [](auto& c) -> auto& { return c.geometry.outerRadius; }));
    s.push_back(textKey("geometry.mask_file", "Mask image beside config.yml, white = process, black = robot body, rods, reflections; empty: none",
                        [](auto& c) -> auto& { return c.geometry.maskFile; }));

    // radial sensors
    s.push_back(intKey("sensors.count", "rays", 1, 720, false, "Radial sensors evenly spread over 360 degrees (line and obstacle search)",
                       [](auto& c) -> auto& { return c.sensors.count; }));
    s.push_back(doubleKey("sensors.inner_radius", "px", 0, 2048, false, "Where each sensor ray starts",
                          [](auto& c) -> auto& { return c.sensors.innerRadius; }));
    s.push_back(doubleKey("sensors.outer_radius", "px", 1, 2048, false, "Where each sensor ray ends",
                          [](auto& c) -> auto& { return c.sensors.outerRadius; }));
    s.push_back(doubleKey("sensors.angle_offset", "deg", 0, 360, false,
                          "Direction of the first ray, counter-clockwise from the image's +x axis; the others follow evenly",
                          [](auto& c) -> auto& { return c.sensors.angleOffsetDeg; }));

    // distance map
    s.push_back(listKey("distance_map.pixel_radii", "px", 0, 4096, false, "Calibration points: image distance from the centre, strictly increasing",
                        [](auto& c) -> auto& { return c.distanceMap.pixelRadii; }));
    s.push_back(listKey("distance_map.ground_distances", "m", 0, 100, false, "Ground distance seen at each pixel_radii entry, strictly increasing",
                        [](auto& c) -> auto& { return c.distanceMap.groundDistances; }));
    s.push_back(doubleKey("distance_map.viewpoint_height", "m", 0.05, 5, false, "Height of the mirror's effective viewpoint above the ground (ball-height correction)",
                          [](auto& c) -> auto& { return c.distanceMap.viewpointHeight; }));
    s.push_back(doubleKey("distance_map.ball_radius", "m", 0.01, 1, false, "Real ball radius: its centre is this high (ball-height correction)",
                          [](auto& c) -> auto& { return c.distanceMap.ballRadius; }));

    // ball model
    s.push_back(doubleKey("ball.c0", "px", -1000, 1000, false, "Expected radius r(d) = c0 + c1*d + c2*d^2 (thesis Fig. 4.7), constant term",
                          [](auto& c) -> auto& { return c.ball.c0; }));
    s.push_back(doubleKey("ball.c1", "px/px", -100, 100, false, "Linear term of r(d)",
                          [](auto& c) -> auto& { return c.ball.c1; }));
    s.push_back(doubleKey("ball.c2", "px/px^2", -10, 10, false, "Quadratic term of r(d)",
                          [](auto& c) -> auto& { return c.ball.c2; }));
    s.push_back(doubleKey("ball.min_radius", "px", 1, 100, true, "r(d) is never below this (far ball)",
                          [](auto& c) -> auto& { return c.ball.minRadius; }));
    s.push_back(doubleKey("ball.max_radius", "px", 1, 200, true, "r(d) is never above this (ball engaged in the robot)",
                          [](auto& c) -> auto& { return c.ball.maxRadius; }));
    s.push_back(doubleKey("ball.square_ratio", "ratio", 0.2, 2, false,
                          "Validation square side over the ball diameter; below ~0.7 it sees only the ball's middle, above 1 carpet enters and the non-green test fails",
                          [](auto& c) -> auto& { return c.ball.squareRatio; }));
    s.push_back(doubleKey("ball.direction_cos", "ratio", -0.5, 0.5, false,
                          "Off-axis mirror: r(d) is scaled by 1 + direction_cos*cos(a) + direction_sin*sin(a), a the ball's image "
                          "angle about the centre (atan2(dy, dx), y down); 0 = the same in every direction",
                          [](auto& c) -> auto& { return c.ball.directionCos; }));
    s.push_back(doubleKey("ball.direction_sin", "ratio", -0.5, 0.5, false, "Sine term of the per-direction correction (see ball.direction_cos)",
                          [](auto& c) -> auto& { return c.ball.directionSin; }));
    s.push_back(doubleKey("ball.squash_c0", "ratio", -10, 10, false,
                          "The ball's image is an ellipse whose radial over tangential semi-axis is k(d) = squash_c0 + squash_c1*d + "
                          "squash_c2*d^2 (a spherical mirror squashes the far field radially; validation.radial_squash uses it); "
                          "1, 0, 0: a circle. calib/fit/BallSquashFit derives it from the distance map (the optics matrix's calibration does)",
                          [](auto& c) -> auto& { return c.ball.squashC0; }));
    s.push_back(doubleKey("ball.squash_c1", "1/px", -1, 1, false, "Linear term of the squash k(d) (see ball.squash_c0)",
                          [](auto& c) -> auto& { return c.ball.squashC1; }));
    s.push_back(doubleKey("ball.squash_c2", "1/px^2", -0.1, 0.1, false, "Quadratic term of the squash k(d) (see ball.squash_c0)",
                          [](auto& c) -> auto& { return c.ball.squashC2; }));

    // edges
    s.push_back(intKey("edges.canny_low", "gradient", 0, 1020, true, "Canny low threshold on the L1 gradient |dx|+|dy|: edges grow along pixels above it. On the "
                       "green / non-green image (levels 0 and 255) every gradient is a multiple of 510, so any value below 510 "
                       "gives the same edges; up to 1019 only rings around one-pixel specks drop out, from 1020 borders break apart. "
                       "With white_level the smallest step is min(white_level, 255 - white_level): keep both thresholds below "
                       "2 x that (below 254 at level 128). With input: gray it is an ordinary Canny threshold on the frame's "
                       "grayscale (a step of d grey levels gives about 4 x d)",
                       [](auto& c) -> auto& { return c.edges.cannyLow; }));
    s.push_back(intKey("edges.canny_high", "gradient", 0, 1020, true, "Canny high threshold on the L1 gradient |dx|+|dy|: edges start above it. On the "
                       "green / non-green image (levels 0 and 255) every gradient is a multiple of 510, so any value below 510 "
                       "gives the same edges; up to 1019 only rings around one-pixel specks drop out; from 1020 edges start only "
                       "at steps and corners (straight borders vanish), from 1530 none. With white_level the smallest step is "
                       "min(white_level, 255 - white_level): keep it below 2 x that. With input: gray an ordinary Canny "
                       "threshold (a step of d grey levels gives about 4 x d)",
                       [](auto& c) -> auto& { return c.edges.cannyHigh; }));
    s.push_back(intKey("edges.white_level", "0..255", 0, 240, false,
                       "Level of white (line) pixels in the binary image, used rounded down to a multiple of 16 (the Hough reads the "
                       "binary image's low bits as \"not green\"); 0: thesis, white is non-green like "
                       "the ball, so a ball touching a line merges with it into one blob. 128: an edge also runs between the "
                       "ball and the line",
                       [](auto& c) -> auto& { return c.edges.whiteLevel; }));
    s.push_back(boolKey("edges.drop_specks", false,
                        "On the binary input, Canny runs with both thresholds raised to just below a straight border's "
                        "gradient (4 x the smallest step between the image's levels, less one): the rings of edges around "
                        "one-pixel specks (dim light's black freckles on the carpet) drop out and every border stays. With "
                        "white_level the smallest step is the line's, so black specks on green stay. Off: the thresholds as set",
                        [](auto& c) -> auto& { return c.edges.dropSpecks; }));
    ConfigKey edgeInput{"edges.input", ValueType::Choice, "", 0, 0,
                        "What Canny (and cv::HoughCircles) run on: binary, the green / non-green image (thesis ch. 4); gray, "
                        "the frame's own grayscale without colour segmentation (thesis solutions 2 and 4; the colour classes "
                        "still serve validation)",
                        {"binary", "gray"}, true, {}, {}};
    edgeInput.get = [](const Config& c) { return ConfigValue(std::string(edgeInputName(c.edges.input))); };
    edgeInput.set = [](Config& c, const ConfigValue& v) {
        if (auto e = parseEdgeInput(std::get<std::string>(v))) c.edges.input = *e;
    };
    s.push_back(std::move(edgeInput));

    // specific Hough
    s.push_back(doubleKey("hough.near_robot_radius", "px", 0, 2048, true, "Votes for centres closer than this count near_robot_weight times (the ball there is half hidden)",
                          [](auto& c) -> auto& { return c.hough.nearRobotRadius; }));
    s.push_back(intKey("hough.near_robot_weight", "votes", 1, 10, true, "Weight of a vote near the robot",
                       [](auto& c) -> auto& { return c.hough.nearRobotWeight; }));
    s.push_back(boolKey("hough.multiple_maxima", true, "One maximum per radial area (thesis 4.1.2) instead of one absolute maximum (4.1.1)",
                        [](auto& c) -> auto& { return c.hough.multipleMaxima; }));
    s.push_back(listKey("hough.area_bounds", "px", 1, 4096, true, "Outer bounds of the radial areas, increasing; area i spans (bound[i-1], bound[i]]",
                        [](auto& c) -> auto& { return c.hough.areaBounds; }));
    s.push_back(intKey("hough.min_accumulator", "votes", 1, 100000, false, "A maximum whose vote sum over its nine-pixel neighbourhood is below this gives no candidate; higher: fewer, stronger candidates",
                       [](auto& c) -> auto& { return c.hough.minAccumulator; }));
    s.push_back(boolKey("hough.radius_at_centre", false,
                        "Vote with the radius expected at the candidate centre's distance; 0: at the edge pixel's (thesis' text, shifts maxima outwards)",
                        [](auto& c) -> auto& { return c.hough.radiusAtCentre; }));
    s.push_back(intKey("hough.maxima_per_area", "maxima", 1, 20, false,
                       "Local maxima kept per radial area after non-maximum suppression (thesis: 1, where any stronger clutter "
                       "maximum in the ball's area hides the ball); more: more candidates to validate",
                       [](auto& c) -> auto& { return c.hough.maximaPerArea; }));
    s.push_back(doubleKey("hough.suppression_radii", "radii", 0.1, 10, false,
                          "A kept maximum suppresses weaker ones closer than this many expected ball radii (same ball, or a ball "
                          "and its own rim maxima); larger: two balls close together give one candidate",
                          [](auto& c) -> auto& { return c.hough.suppressionRadii; }));
    s.push_back(intKey("hough.max_candidates", "candidates", 1, 200, false,
                       "Candidates per frame at most (maxima and blob seeds): each area's strongest, then each area's second, ...; "
                       "bounds the validation time",
                       [](auto& c) -> auto& { return c.hough.maxCandidates; }));
    s.push_back(intKey("hough.max_edge_pixels", "px", 0, 1000000, false,
                       "Edge pixels voting per frame at most; beyond it an even, deterministic subsample votes (the accumulator "
                       "is scaled back up). Bounds the worst frame's time (noise, dim speckle); 0: no cap",
                       [](auto& c) -> auto& { return c.hough.maxEdgePixels; }));
    s.push_back(boolKey("hough.blob_seeds", false,
                        "Also seed candidates at compact non-green blobs whose size matches the ball's at their distance (found "
                        "even when clutter out-votes the ball)",
                        [](auto& c) -> auto& { return c.hough.blobSeeds; }));
    s.push_back(boolKey("hough.masked_centres", false,
                        "Edge pixels also vote for centres on masked pixels inside the ring (a ball behind a support rod), "
                        "judged on their visible part; off: only processed non-green centres (the thesis)",
                        [](auto& c) -> auto& { return c.hough.maskedCentres; }));
    s.push_back(boolKey("hough.rank_by_score", false,
                        "Choose among valid candidates by one score combining every validation test and the votes; 0: the "
                        "thesis' best circularity, then most votes",
                        [](auto& c) -> auto& { return c.hough.rankByScore; }));
    s.push_back(doubleKey("hough.prefilter_non_green", "fraction", 0, 1, false,
                          "Hough maxima and blob seeds whose ball square is less non-green (by colour class) than this fraction "
                          "of validation.min_non_green_pct take no candidate slot: validation would refuse them, and line "
                          "crossings otherwise crowd a ball's weaker maximum out of its radial area. 0: off (every maximum is a "
                          "candidate); 1: as strict as validation without carpet_by_colour",
                          [](auto& c) -> auto& { return c.hough.prefilterNonGreen; }));
    s.push_back(boolKey("hough.prefilter_rim", false,
                        "With validation.refuse_at_rim, maxima and seeds whose circle reaches past the rim take no candidate slot",
                        [](auto& c) -> auto& { return c.hough.prefilterRim; }));
    s.push_back(boolKey("hough.prefilter_rim_test", false,
                        "prefilter_rim: with validation.rim_test, a maximum or seed whose circle reaches the rim takes a slot only "
                        "when it passes that test (width, inward side, rim_min_contrast), so rim clutter does not crowd a far "
                        "ball out of the far ring; off: every circle within rim_max_overhang_px takes one",
                        [](auto& c) -> auto& { return c.hough.prefilterRimTest; }));
    s.push_back(doubleKey("hough.prefilter_non_black", "fraction", 0, 1, false,
                          "Hough maxima and blob seeds whose ball square is less non-black (by colour class) than this fraction "
                          "of validation.min_non_black_pct take no candidate slot (a robot beside the ball); with "
                          "validation.black_by_local_carpet a refused one is asked again with black judged as validation judges it "
                          "(against the carpet around it); 0: off",
                          [](auto& c) -> auto& { return c.hough.prefilterNonBlack; }));
    s.push_back(intKey("hough.prefilter_checks", "maxima", 1, 10000, false,
                       "Maxima per radial area the prefilter tests at most (each reads one ball square); bounds its time on a "
                       "cluttered frame",
                       [](auto& c) -> auto& { return c.hough.prefilterChecks; }));
    s.push_back(boolKey("hough.seeds_without_black", false,
                        "Blob seeds are flooded with the black classes as background, so a ball beside a robot is a blob of its "
                        "own (else one region with the robot, too large for a seed); off: every non-green pixel joins a blob",
                        [](auto& c) -> auto& { return c.hough.seedsWithoutBlack; }));
    s.push_back(boolKey("hough.seeds_squashed", false,
                        "A blob seed's bounding box may be as long as the ball's tangential axis where ball.squash_* flattens "
                        "it radially (a far ball in a spherical mirror); off: no side longer than the area-equivalent diameter",
                        [](auto& c) -> auto& { return c.hough.seedsSquashed; }));

    // OpenCV Hough
    s.push_back(doubleKey("opencv_hough.dp", "ratio", 1, 4, true, "Inverse accumulator resolution of cv::HoughCircles (1: the image's, larger: coarser and faster)",
                          [](auto& c) -> auto& { return c.opencvHough.dp; }));
    s.push_back(doubleKey("opencv_hough.min_dist", "px", 1, 1000, true, "Minimum distance between circle centres; too small duplicates a ball, too large misses balls",
                          [](auto& c) -> auto& { return c.opencvHough.minDist; }));
    s.push_back(doubleKey("opencv_hough.canny_high", "gradient", 1, 1020, true, "High threshold of HoughCircles' internal Canny (its low threshold is half). On the green / non-green image "
                          "every gradient is a multiple of 510, so any value below 510 gives the same circles; with drop_specks it is raised "
                          "on the binary input (never lowered)",
                          [](auto& c) -> auto& { return c.opencvHough.cannyHigh; }));
    s.push_back(doubleKey("opencv_hough.acc_threshold", "votes", 1, 1000, false, "Accumulator votes a circle centre needs; lower: more (and false) circles, higher: small balls missed",
                          [](auto& c) -> auto& { return c.opencvHough.accThreshold; }));
    s.push_back(intKey("opencv_hough.min_radius", "px", 1, 200, true, "Smallest circle searched; smaller circles are pixel noise, not a ball",
                       [](auto& c) -> auto& { return c.opencvHough.minRadius; }));
    s.push_back(intKey("opencv_hough.max_radius", "px", 1, 200, true, "Largest circle searched (the ball engaged in the robot)",
                       [](auto& c) -> auto& { return c.opencvHough.maxRadius; }));
    s.push_back(doubleKey("opencv_hough.max_radius_ratio", "ratio", 0.5, 3, false,
                          "A circle above expected radius x this is rejected (thesis: 1.0; HoughCircles overestimates a true ball's radius by up to ~1.23)",
                          [](auto& c) -> auto& { return c.opencvHough.maxRadiusRatio; }));
    s.push_back(doubleKey("opencv_hough.min_radius_ratio", "ratio", 0, 1, false,
                          "A circle below expected radius x this is rejected too (thesis: 0, no lower bound); a speck or a line end",
                          [](auto& c) -> auto& { return c.opencvHough.minRadiusRatio; }));
    s.push_back(intKey("opencv_hough.max_circles", "circles", 1, 50, false,
                       "Circles of plausible radius validated per frame, strongest first (thesis: 1, the strongest circle of any "
                       "radius, on a real field nearly always a rim artefact)",
                       [](auto& c) -> auto& { return c.opencvHough.maxCircles; }));
    s.push_back(boolKey("opencv_hough.skip_implausible", false,
                        "Circles whose radius does not fit the ball's at their distance (or off the processed area) are reported "
                        "but do not use up max_circles; 0: the strongest max_circles circles of any radius (thesis, with 1)",
                        [](auto& c) -> auto& { return c.opencvHough.skipImplausible; }));
    s.push_back(boolKey("opencv_hough.refine_centre", false,
                        "Moves each plausible circle's centre to the centroid of the non-green pixels within the expected radius "
                        "(HoughCircles' centre is often a few px off a small ball); 0: the circle as found (thesis)",
                        [](auto& c) -> auto& { return c.opencvHough.refineCentre; }));
    s.push_back(boolKey("opencv_hough.join_ranking", false,
                        "Combined algorithm: OpenCV always runs and its valid circles join the specific candidates in the "
                        "ranking; 0: OpenCV runs only when the specific search found nothing valid (thesis 4.3)",
                        [](auto& c) -> auto& { return c.opencvHough.joinRanking; }));
    s.push_back(intKey("opencv_hough.max_edge_pixels", "px", 0, 1000000, false,
                       "Combined algorithm: the OpenCV search is skipped on a frame with more edge pixels than this in the "
                       "processed ring (its time grows with them: dim speckle, noise); bounds the worst frame's time. 0: never "
                       "skipped (thesis). The OpenCV algorithm alone always runs it",
                       [](auto& c) -> auto& { return c.opencvHough.maxEdgePixels; }));
    s.push_back(doubleKey("opencv_hough.band_radius_span", "ratio", 0, 10, false,
                          "Per-ring search: the processed area is cut into distance rings in which the ball's expected radius varies "
                          "by at most this ratio, and cv::HoughCircles runs in each with the ring's own radius range (x min/max_radius_ratio), "
                          "accumulator threshold and min_dist, so a small far ball is not outranked by larger clutter circles. 0: one "
                          "search over min_radius..max_radius (thesis)",
                          [](auto& c) -> auto& { return c.opencvHough.bandRadiusSpan; }));
    s.push_back(doubleKey("opencv_hough.band_votes_per_px", "votes/px", 0, 10, false,
                          "Per-ring search: accumulator votes a centre needs per px of the ring's smallest expected circumference "
                          "(never below band_acc_threshold; 0: band_acc_threshold in every ring)",
                          [](auto& c) -> auto& { return c.opencvHough.bandVotesPerPx; }));
    s.push_back(doubleKey("opencv_hough.band_min_dist_ratio", "ratio", 0, 10, false,
                          "Per-ring search: minimum distance between circle centres as a multiple of the ring's smallest expected "
                          "radius (replaces min_dist)",
                          [](auto& c) -> auto& { return c.opencvHough.bandMinDistRatio; }));
    s.push_back(intKey("opencv_hough.band_circles", "circles", 1, 50, false,
                       "Per-ring search: circles of plausible radius validated per ring, strongest first (replaces max_circles)",
                       [](auto& c) -> auto& { return c.opencvHough.bandCircles; }));
    s.push_back(doubleKey("opencv_hough.band_dp", "ratio", 1, 4, false,
                          "Per-ring search: inverse accumulator resolution (replaces dp; 1: the image's, which the farthest, smallest balls need)",
                          [](auto& c) -> auto& { return c.opencvHough.bandDp; }));
    s.push_back(doubleKey("opencv_hough.band_acc_threshold", "votes", 1, 1000, false,
                          "Per-ring search: accumulator votes a circle centre needs at least (replaces acc_threshold)",
                          [](auto& c) -> auto& { return c.opencvHough.bandAccThreshold; }));
    s.push_back(intKey("opencv_hough.mask_fill_px", "px", 0, 50, false,
                       "Masked pixels of the ring (support rods) within this distance of a non-green pixel are non-green in "
                       "HoughCircles' input, so a ball behind a rod is one disc again; a rod across bare carpet stays green. "
                       "0: masked pixels are green, a ball behind a rod is cut in two (thesis)",
                       [](auto& c) -> auto& { return c.opencvHough.maskFillPx; }));
    s.push_back(boolKey("opencv_hough.masked_centres", false,
                        "A circle centred on a masked pixel of the ring (a ball behind a support rod) is validated on its visible "
                        "part, as hough.masked_centres does for the specific search; off: refused as outside the area (thesis)",
                        [](auto& c) -> auto& { return c.opencvHough.maskedCentres; }));
    s.push_back(boolKey("opencv_hough.drop_specks", false,
                        "On the binary input, HoughCircles' Canny runs with canny_high raised to just below a straight border's "
                        "gradient (four steps between the image's levels, less one), as edges.drop_specks does for the "
                        "specific search: the rings around one-pixel specks drop out, every border stays, and a dim noisy frame's "
                        "search stays fast. Off: canny_high as set",
                        [](auto& c) -> auto& { return c.opencvHough.dropSpecks; }));

    // validation
    s.push_back(doubleKey("validation.min_non_green_pct", "%", 0, 100, true, "Non-green share the ball square needs; lower lets carpet patches through",
                          [](auto& c) -> auto& { return c.validation.minNonGreenPct; }));
    s.push_back(doubleKey("validation.min_non_black_pct", "%", 0, 100, false, "Non-black share the ball square needs; higher rejects part-black balls, lower lets robots through (thesis: 50, which on the optics matrix found two points fewer balls and no fewer false positives)",
                          [](auto& c) -> auto& { return c.validation.minNonBlackPct; }));
    s.push_back(doubleKey("validation.min_circularity_pct", "%", 0, 100, true, "Share of the circle found as edges; higher loses blurred moving balls, lower accepts lines and feet",
                          [](auto& c) -> auto& { return c.validation.minCircularityPct; }));
    s.push_back(doubleKey("validation.min_circularity_clear_pct", "%", 0, 100, false,
                          "Circularity a candidate in the clear needs (its square at least clear_min_non_black_pct non-black: "
                          "no robot hides it, every ray is its own border; at least clear_min_radius_px; its fitted radius within "
                          "clear_max_fit_error of the expected); lower finds blurred "
                          "and noisy balls that lose a few rays, and lets more feet and line ends through; at or above "
                          "min_circularity_pct: one threshold for all (thesis)",
                          [](auto& c) -> auto& { return c.validation.minCircularityClearPct; }));
    s.push_back(doubleKey("validation.clear_min_non_black_pct", "%", 0, 100, false,
                          "Non-black share of the ball square that puts a candidate in the clear for "
                          "min_circularity_clear_pct; lower lets a robot's corner, judged on its own outline, pass",
                          [](auto& c) -> auto& { return c.validation.clearMinNonBlackPct; }));
    s.push_back(doubleKey("validation.clear_min_radius_px", "px", 0, 100, false,
                          "Expected radius from which min_circularity_clear_pct applies; lower lets far line junctions and "
                          "line ends, as round as a small ball, through; 0: at every radius",
                          [](auto& c) -> auto& { return c.validation.clearMinRadiusPx; }));
    s.push_back(doubleKey("validation.clear_max_fit_error", "fraction", 0, 1, false,
                          "min_circularity_clear_pct applies only when the circle fit's radius is within this fraction of the "
                          "expected radius (circle_fit): a ball's blurred border still fits its size, clutter that reaches the lower "
                          "threshold mostly does not; 1: no such condition",
                          [](auto& c) -> auto& { return c.validation.clearMaxFitError; }));
    s.push_back(doubleKey("validation.radius_tolerance", "fraction", 0, 1, true, "Edges count within expected radius +- this fraction",
                          [](auto& c) -> auto& { return c.validation.radiusTolerance; }));
    s.push_back(doubleKey("validation.min_radius_band_px", "px", 0, 10, false, "The +- band is never thinner than this (radius_tolerance of a small ball is under a pixel; borders blur ~1 px inwards)",
                          [](auto& c) -> auto& { return c.validation.minRadiusBandPx; }));
    s.push_back(doubleKey("validation.min_radius_px", "px", 0, 100, false,
                          "Candidates whose expected radius is below this are rejected: by shape a smaller ball looks like a line corner",
                          [](auto& c) -> auto& { return c.validation.minRadiusPx; }));
    s.push_back(boolKey("validation.first_edge_only", false,
                        "A ray counts only if the first edge from the centre lies in the band; 0: any edge in the band (thesis' text, passes line corners)",
                        [](auto& c) -> auto& { return c.validation.firstEdgeOnly; }));
    s.push_back(boolKey("validation.border_into_carpet", false,
                        "A ray counts only if carpet (or an unprocessed pixel) lies beyond_edge_px beyond its edge; rejects line corners",
                        [](auto& c) -> auto& { return c.validation.borderIntoCarpet; }));
    s.push_back(boolKey("validation.ignore_occluded_rays", false,
                        "Rays whose border leads into black (a robot hiding part of the ball) are not judged; 0: they count as misses",
                        [](auto& c) -> auto& { return c.validation.ignoreOccludedRays; }));
    s.push_back(doubleKey("validation.max_run_on_pct", "%", 0, 100, false,
                          "Rejects a candidate when on more of its rays the centre's colour runs on past run_on_reach (line corners and ends); 100: off",
                          [](auto& c) -> auto& { return c.validation.maxRunOnPct; }));
    s.push_back(doubleKey("validation.run_on_reach", "radii", 1, 3, false,
                          "How far out, in expected radii, the centre's colour must run on for a ray to count in the run-on test; "
                          "lower: balls beside a line run on too, higher: far line corners pass",
                          [](auto& c) -> auto& { return c.validation.runOnReach; }));
    s.push_back(doubleKey("validation.run_on_chroma_step", "chroma (0-255)", 0, 255, false,
                          "In the run-on test an unclassified pixel ends the run of an unclassified centre when it is "
                          "greyer by more than this (chroma, max - min of B, G, R) and no darker (mean of B, G, R): line paint. A coloured ball "
                          "in dim light touching a grey line (both unclassified) no longer runs on along the line; lower: "
                          "faint colour differences end runs too. 0: off, the class alone",
                          [](auto& c) -> auto& { return c.validation.runOnChromaStep; }));
    s.push_back(doubleKey("validation.run_on_hue_step", "hue (0-179)", 0, 90, false,
                          "In the run-on test an unclassified pixel ends the run of an unclassified centre when their hues lie "
                          "this far apart (the shorter way round), both at least run_on_hue_min_chroma in chroma: another "
                          "object's colour, such as a robot's marker band a ball lies against in dim light; lower: noise and "
                          "shading end runs too. 0: off",
                          [](auto& c) -> auto& { return c.validation.runOnHueStep; }));
    s.push_back(doubleKey("validation.run_on_hue_min_chroma", "chroma (0-255)", 0, 255, false,
                          "run_on_hue_step: only pixels (and a centre) with at least this chroma (max - min of B, G, R) have a "
                          "hue to compare; lower: noise on grey and dark pixels decides their hue",
                          [](auto& c) -> auto& { return c.validation.runOnHueMinChroma; }));
    s.push_back(doubleKey("validation.run_on_colour_step", "levels (B+G+R)", 0, 765, false,
                          "In the run-on test an unclassified pixel ends the run of an unclassified centre when their colours "
                          "differ by more than this, the three channels' absolute differences added, and the pixel is no darker: "
                          "another object, such as the hall floor beyond the carpet a ball lies against; lower: shading along a "
                          "line ends runs too. 0: off",
                          [](auto& c) -> auto& { return c.validation.runOnColourStep; }));
    s.push_back(doubleKey("validation.min_usable_ray_share", "fraction", 0, 1, false,
                          "Circularity is judged only when this share of the circle's rays crosses processed pixels (the rest lie on "
                          "the robot body or rods); below it the candidate fails; lower: judges a mostly hidden circle by a few rays",
                          [](auto& c) -> auto& { return c.validation.minUsableRayShare; }));
    s.push_back(doubleKey("validation.min_unoccluded_ray_share", "fraction", 0, 1, false,
                          "Of the usable rays and those whose border leads into a robot's black or marker band, at least this "
                          "share must be usable (masked rays and rays into a line do not count); below it the candidate fails "
                          "circularity (a circle inside a robot at its marker band); higher: refuses balls further behind a "
                          "robot. 0: off",
                          [](auto& c) -> auto& { return c.validation.minUnoccludedRayShare; }));
    s.push_back(doubleKey("validation.beyond_edge_px", "px", 0.5, 10, false,
                          "How far beyond a ray's edge its colour is read (border_into_carpet, ignore_occluded_rays); smaller: reads "
                          "the blurred border itself, larger: reaches a neighbouring line or robot",
                          [](auto& c) -> auto& { return c.validation.beyondEdgePx; }));
    s.push_back(boolKey("validation.masked_rays_unknown", false,
                        "Rays that reach masked or out-of-mirror pixels before the ball's border are left out of the circularity, so a ball "
                        "half behind a rod is judged on its visible half; off: they count as misses",
                        [](auto& c) -> auto& { return c.validation.maskedRaysUnknown; }));
    s.push_back(boolKey("validation.circle_fit", false,
                        "Circularity around a circle fitted to the rays' borders (a ball the radius model misjudges by a few px, a blurred "
                        "ball, still pass; the fitted radius and centre must be within fit_max_radius_error(_px)); off: the thesis' band "
                        "around the expected radius",
                        [](auto& c) -> auto& { return c.validation.circleFit; }));
    s.push_back(doubleKey("validation.fit_max_radius_error_px", "px", 0, 20, false,
                          "circle_fit: how far the fitted radius and centre may be off the expected ones (or fit_max_radius_error "
                          "of the radius, whichever is larger); larger accepts round things of other sizes",
                          [](auto& c) -> auto& { return c.validation.fitMaxRadiusErrorPx; }));
    s.push_back(doubleKey("validation.fit_max_radius_error", "fraction", 0, 1, false,
                          "circle_fit: the same allowance as a fraction of the expected radius (near, big balls)",
                          [](auto& c) -> auto& { return c.validation.fitMaxRadiusError; }));
    s.push_back(boolKey("validation.fit_visible_border", false,
                        "circle_fit: a fitted circle whose centre or radius is off still passes when its border lies within the "
                        "allowance of the expected border along every usable ray (a ball half behind our body or a rod shows one "
                        "arc, whose fit slides along it); never looser for a ball seen whole; off: centre and radius alone",
                        [](auto& c) -> auto& { return c.validation.fitVisibleBorder; }));
    s.push_back(doubleKey("validation.fit_visible_min_share", "fraction", 0, 1, false,
                          "fit_visible_border: applies only when at least this share of the rays is usable (a ball at our body "
                          "shows over half of them, a line crossing a rod about a third)",
                          [](auto& c) -> auto& { return c.validation.fitVisibleMinShare; }));
    s.push_back(boolKey("validation.hall_rays_by_colour", false,
                        "A ray outwards (hall_outward_cos) that finds no border and runs out over the hall floor to the mirror's "
                        "rim within hall_reach_radii (no carpet, no mask) is judged by colour: the ball's border is where the "
                        "pixels stop differing from the floor's colour (a far ball at the carpet's edge, half over the floor); "
                        "off: such a ray is a miss",
                        [](auto& c) -> auto& { return c.validation.hallRaysByColour; }));
    s.push_back(doubleKey("validation.hall_colour_step", "levels (B+G+R)", 0, 765, false,
                          "hall_rays_by_colour: the border is past the outermost pixel whose colour differs from the floor's (read "
                          "just past the search band) by at least this, the three channels' absolute differences added; lower "
                          "lets floor noise pass as ball",
                          [](auto& c) -> auto& { return c.validation.hallColourStep; }));
    s.push_back(doubleKey("validation.hall_reach_radii", "radii", 0, 20, false,
                          "hall_rays_by_colour: the ray must reach the mirror's rim within this many expected radii past its band "
                          "without meeting carpet; larger takes robots and blobs farther from the rim for the hall",
                          [](auto& c) -> auto& { return c.validation.hallReachRadii; }));
    s.push_back(doubleKey("validation.hall_outward_cos", "cosine", -1, 1, false,
                          "hall_rays_by_colour: only rays within the half-angle of this cosine of the direction away from the "
                          "mirror centre are hall rays",
                          [](auto& c) -> auto& { return c.validation.hallOutwardCos; }));
    s.push_back(boolKey("validation.carpet_by_colour", false,
                        "Green pixels are carpet only when their hue and saturation match the carpet measured around the candidate; "
                        "green panels of a ball then count as ball (non-green test, borders); off: every green pixel is carpet",
                        [](auto& c) -> auto& { return c.validation.carpetByColour; }));
    s.push_back(doubleKey("validation.carpet_colour_sigmas", "spreads", 0, 10, false,
                          "carpet_by_colour: a pixel is carpet within this many spreads of the surrounding carpet's hue and saturation",
                          [](auto& c) -> auto& { return c.validation.carpetTolerance.sigmas; }));
    s.push_back(doubleKey("validation.carpet_hue_tolerance", "hue (0-179)", 0, 90, false,
                          "carpet_by_colour: the hue tolerance is never tighter than this; smaller tells closer greens apart, and noise "
                          "from the carpet",
                          [](auto& c) -> auto& { return c.validation.carpetTolerance.hue; }));
    s.push_back(doubleKey("validation.carpet_saturation_tolerance", "saturation (0-255)", 0, 255, false,
                          "carpet_by_colour: the saturation tolerance is never tighter than this",
                          [](auto& c) -> auto& { return c.validation.carpetTolerance.saturation; }));
    s.push_back(doubleKey("validation.carpet_value_tolerance", "value (0-255)", 0, 255, false,
                          "carpet_by_colour: brightness is judged too when above 0 (never tighter than this); tells a shaded green "
                          "panel from the carpet, but also a shadow on the carpet",
                          [](auto& c) -> auto& { return c.validation.carpetTolerance.value; }));
    s.push_back(doubleKey("validation.square_shade_tolerance", "value (0-255)", 0, 255, false,
                          "carpet_by_colour: in the non-green test's square, a carpet-coloured pixel darker than the carpet around "
                          "by more than this (or carpet_colour_sigmas spreads) is the ball's shaded side, when green_panel_min_own_pct "
                          "of the square is neither carpet nor black; the borders never judge it. 0: off (colour alone)",
                          [](auto& c) -> auto& { return c.validation.squareShadeTolerance; }));
    s.push_back(doubleKey("validation.carpet_ring_inner", "radii", 1, 10, false,
                          "carpet_by_colour: the carpet's colour is measured from this many expected radii (plus carpet_ring_margin_px) "
                          "out; smaller: the ball's blurred border and contact shadow enter the carpet's colour",
                          [](auto& c) -> auto& { return c.validation.carpetRingInner; }));
    s.push_back(doubleKey("validation.carpet_ring_outer", "radii", 1, 20, false,
                          "carpet_by_colour: ... to this many expected radii (plus 2 x carpet_ring_margin_px); larger: reaches lines, "
                          "robots and vignetting farther away",
                          [](auto& c) -> auto& { return c.validation.carpetRingOuter; }));
    s.push_back(doubleKey("validation.carpet_ring_margin_px", "px", 0, 20, false,
                          "carpet_by_colour: added to the ring's inner radius (twice to its outer one), so a small ball's ring stays a "
                          "few pixels wide",
                          [](auto& c) -> auto& { return c.validation.carpetRingMarginPx; }));
    s.push_back(doubleKey("validation.border_blend_px", "px", 0, 20, false,
                          "How wide the blend of ball and carpet colours at a border may be (motion blur, optics): a ray's edge leads "
                          "into carpet when the carpet's own green starts within this many px past beyond_edge_px",
                          [](auto& c) -> auto& { return c.validation.borderBlendPx; }));
    s.push_back(boolKey("validation.black_by_local_carpet", false,
                        "The non-black test counts a black-class pixel only when it is also darker than local_black_v_ratio x the "
                        "carpet's mean V around the candidate (carpet_ring_*): a ball's shaded side in a vignetted corner or the dim "
                        "half of an unevenly lit hall is not black (hough.prefilter_non_black asks the same before refusing a maximum); "
                        "off: the colour class alone (black relative to the whole frame)",
                        [](auto& c) -> auto& { return c.validation.blackByLocalCarpet; }));
    s.push_back(doubleKey("validation.local_black_v_ratio", "ratio", 0.05, 1, false,
                          "black_by_local_carpet: black is V <= this x the mean V of the carpet around the candidate; higher keeps "
                          "more of a dark ball black (fails non-black), lower lets dim robots through",
                          [](auto& c) -> auto& { return c.validation.localBlackVRatio; }));
    s.push_back(boolKey("validation.border_at_pixel", false,
                        "Circularity: a ray's border point is the centre of the edge pixel it met, not where along the ray it met it "
                        "(up to ~0.7 px off, much of a small ball's min_radius_band_px band); off: the ray's step. On finds a few more "
                        "small balls on the optics matrix but also passes a blurred round floor reflection, hence off",
                        [](auto& c) -> auto& { return c.validation.borderAtPixel; }));
    s.push_back(textKey("validation.ball_hint_class",
                        "The ball's colour class when known (a class name of colors.classes, not a field class): where enough of its "
                        "square has it (ball_hint_min_pct), the non-green and non-black tests are passed; none: no hint",
                        [](auto& c) -> auto& { return c.validation.ballHint; }));
    s.push_back(doubleKey("validation.ball_hint_min_pct", "%", 0, 100, false,
                          "ball_hint_class: share of the square's processed pixels of that class that counts as the ball's colour",
                          [](auto& c) -> auto& { return c.validation.ballHintMinPct; }));
    s.push_back(boolKey("validation.green_panels", false,
                        "Non-green test and borders: a carpet-green pixel inside the expected circle counts as ball when walking out from it "
                        "the ball's white (any non-field class) comes before the border: a green panel enclosed by white ones, which "
                        "colour cannot tell from the carpet; off: every carpet-green pixel is carpet",
                        [](auto& c) -> auto& { return c.validation.greenPanels; }));
    s.push_back(doubleKey("validation.green_panel_margin_px", "px", 0, 2, false,
                          "green_panels: the walks from a green pixel stop this far inside the expected circle (the border's own "
                          "pixels blend ball and carpet); smaller counts more panels near the border and more carpet beside lines",
                          [](auto& c) -> auto& { return c.validation.greenPanelMarginPx; }));
    s.push_back(intKey("validation.green_panel_min_directions", "directions (of 8)", 0, 8, false,
                       "green_panels: a green pixel that meets the ball's white before the border in at least this many compass "
                       "directions is a panel too (one at the ball's silhouette has white inwards and on both sides: 5); lower "
                       "also takes carpet in line corners, 0: only the walk outwards decides",
                       [](auto& c) -> auto& { return c.validation.greenPanelMinDirections; }));
    s.push_back(doubleKey("validation.green_panel_min_own_pct", "%", 0, 100, false,
                          "green_panels: the panels count in the non-green test only when the square's non-green share by colour "
                          "alone (the ball's white) reaches this; a green-and-white ball shows just over half, carpet beside a line less",
                          [](auto& c) -> auto& { return c.validation.greenPanelMinOwnPct; }));
    s.push_back(intKey("validation.recentre_refused", "candidates", 0, 100, false,
                       "Maxima the prefilter refused on the non-green test (a green-and-white ball's lies on its white half) are "
                       "moved to the centroid of the pixels around them not of the carpet's colour and validated there, at most "
                       "this many per frame, strongest first; 0: they stay refused",
                       [](auto& c) -> auto& { return c.validation.recentreRefused; }));
    s.push_back(doubleKey("validation.recentre_min_non_green_pct", "%", 0, 100, false,
                          "recentre_refused: only refusals whose square is at least this non-green by colour class (carpet "
                          "crossed by a line shows less)",
                          [](auto& c) -> auto& { return c.validation.recentreMinNonGreenPct; }));
    s.push_back(doubleKey("validation.recentre_min_panel_pct", "%", 0, 100, false,
                          "recentre_refused: a moved candidate that passes validation replaces the refusal only when validation's "
                          "non-green share (green panels counted) is this far above the share by colour class: a line corner "
                          "or a line end, which the move centres too, has no green of its own",
                          [](auto& c) -> auto& { return c.validation.recentreMinPanelPct; }));
    s.push_back(doubleKey("validation.recentre_min_radius_px", "px", 0, 100, false,
                          "recentre_refused: only refusals whose expected radius is at least this: farther out a line's bend "
                          "or its end at a rod, centred by the move, looks like a small ball",
                          [](auto& c) -> auto& { return c.validation.recentreMinRadiusPx; }));
    s.push_back(intKey("validation.refit_recentre", "candidates", 0, 100, false,
                       "circle_fit: candidates refused on circularity whose border fits a circle (a Hough maximum a few pixels "
                       "off the ball's centre) are moved to the fitted centre and validated there, at most this many per "
                       "frame; 0: they stay refused",
                       [](auto& c) -> auto& { return c.validation.refitRecentre; }));
    s.push_back(doubleKey("validation.refit_min_radius_px", "px", 0, 100, false,
                          "refit_recentre: only moves whose expected radius at the fitted centre is at least this: far out, a "
                          "robot's marker patch or a pale blob in dim light fits a circle of its own",
                          [](auto& c) -> auto& { return c.validation.refitMinRadiusPx; }));

    // validation at the mirror rim (issue 9: where the optics matrix's false positives sat)
    s.push_back(boolKey("validation.refuse_at_rim", false,
                        "A candidate whose expected circle reaches past geometry.outer_radius less rim_margin_px is refused: a circle "
                        "cut by the rim is judged on its inner part alone, which cut-off line ends and robot markers pass; off: judged "
                        "like any other (and a ball cut by the rim can be found)",
                        [](auto& c) -> auto& { return c.validation.refuseAtRim; }));
    s.push_back(doubleKey("validation.rim_margin_px", "px", -50, 50, false,
                          "refuse_at_rim: how far inside the outer radius a candidate's circle must end; larger refuses more of the "
                          "far ring (balls there too), negative lets circles reach past the outer radius",
                          [](auto& c) -> auto& { return c.validation.rimMarginPx; }));
    s.push_back(boolKey("validation.radial_squash", false,
                        "Circularity and run-on look for the ellipse of ball.squash_c0..c2 (radial over tangential semi-axis) around "
                        "the candidate instead of a circle: a spherical mirror squashes a ball at 1-2 m to ~0.7; off: a circle (thesis)",
                        [](auto& c) -> auto& { return c.validation.radialSquash; }));
    s.push_back(doubleKey("validation.squash_min_radius_px", "px", 0, 100, false,
                          "radial_squash: candidates whose expected radius is below this keep the circle (a small ball's squash lies "
                          "inside the band anyway, and the ellipse's longer reach meets clutter at the rim)",
                          [](auto& c) -> auto& { return c.validation.squashMinRadiusPx; }));
    s.push_back(boolKey("validation.rim_test", false,
                        "refuse_at_rim: a circle reaching up to rim_max_overhang_px past the rim is judged instead of refused "
                        "when its inward side is closed (rim_min_closed_pct of its inward rays meet carpet at its border): a far "
                        "ball on the carpet passes, a robot marker or a line end cut by the rim does not; off: refused",
                        [](auto& c) -> auto& { return c.validation.rimTest; }));
    s.push_back(doubleKey("validation.rim_max_overhang_px", "px", 0, 50, false,
                          "rim_test: how far past geometry.outer_radius less rim_margin_px a judged circle may reach (also "
                          "what hough.prefilter_rim lets through); larger judges balls farther into the rim, and more clutter",
                          [](auto& c) -> auto& { return c.validation.rimMaxOverhangPx; }));
    s.push_back(doubleKey("validation.rim_min_closed_pct", "%", 0, 100, false,
                          "rim_test: the share of the inward rays (towards the mirror centre) whose first carpet pixel (with "
                          "rim_skip_inner_field: the first from rim_band_px inside the border on) lies within rim_band_px of the "
                          "expected radius; lower passes more balls in shade, and more markers",
                          [](auto& c) -> auto& { return c.validation.rimMinClosedPct; }));
    s.push_back(doubleKey("validation.rim_band_px", "px", 0, 20, false,
                          "rim_test: how far from the expected radius an inward ray's first carpet pixel (rim_min_closed_pct) may lie",
                          [](auto& c) -> auto& { return c.validation.rimBandPx; }));
    s.push_back(doubleKey("validation.rim_inward_cos", "cosine", -1, 1, false,
                          "rim_test: the rays judged are those within the half-angle of this cosine of the direction to the "
                          "mirror centre; larger judges fewer rays, nearer the inward direction",
                          [](auto& c) -> auto& { return c.validation.rimInwardCos; }));
    s.push_back(doubleKey("validation.rim_min_width", "fraction", 0, 10, false,
                          "rim_test: the candidate's non-field run along its arc (through its centre, both ways) must be at "
                          "least this share of the ball's expected width there (the squashed ellipse's tangential axis): robot "
                          "markers and line ends cut by the rim are narrower than a ball",
                          [](auto& c) -> auto& { return c.validation.rimMinWidth; }));
    s.push_back(doubleKey("validation.rim_max_width", "fraction", 0, 10, false,
                          "rim_test: and at most this share of it: a line along the rim, or a ball merged with clutter, runs on",
                          [](auto& c) -> auto& { return c.validation.rimMaxWidth; }));
    s.push_back(doubleKey("validation.rim_arc_carpet_px", "px", 0, 10, false,
                          "rim_test: the run along the arc ends at carpet only where the arc stays carpet this much further: "
                          "a speck of carpet noise in a dim hall floor at the rim does not end it (the floor then runs on "
                          "past rim_max_width); 0: at the first carpet pixel",
                          [](auto& c) -> auto& { return c.validation.rimArcCarpetPx; }));
    s.push_back(doubleKey("validation.rim_arc_offset_px", "px", 0, 10, false,
                          "rim_test: rim_min_width is met by the widest run along the arcs up to this far radially in and out "
                          "of the candidate's centre (a far ball's centre found a px or two off crosses it off its widest "
                          "chord); rim_max_width reads the arc through the centre; 0: that arc alone",
                          [](auto& c) -> auto& { return c.validation.rimArcOffsetPx; }));
    s.push_back(boolKey("validation.rim_arc_masked_mirrors", false,
                        "rim_test: a way of the arc run that stops at a masked pixel (a support rod) counts as long as "
                        "the other way: a far ball half behind a rod is not a narrow marker; off: the mask ends the run",
                        [](auto& c) -> auto& { return c.validation.rimArcMaskedMirrors; }));
    s.push_back(boolKey("validation.rim_skip_inner_field", false,
                        "rim_test: an inward ray's carpet pixels more than rim_band_px inside the ball's border (a green panel, "
                        "noise in its shadow) are skipped, and the first one from there on must lie within the band; off: the "
                        "ray's first carpet pixel decides",
                        [](auto& c) -> auto& { return c.validation.rimSkipInnerField; }));
    s.push_back(doubleKey("validation.rim_min_radius_px", "px", 0, 100, false,
                          "rim_test: a circle that passes it is validated from this expected radius on, instead of "
                          "min_radius_px (its closed inward side is what a small line corner lacks)",
                          [](auto& c) -> auto& { return c.validation.rimMinRadiusPx; }));
    s.push_back(doubleKey("validation.rim_min_contrast", "levels (B+G+R)", 0, 765, false,
                          "rim_test: a circle at the rim passes only when the mean colour inside it differs from the mean "
                          "colour of its surroundings off the carpet (the hall floor, the dark past the rim) by at least this, "
                          "the three channels' absolute differences added: a patch of dim, noisy floor has the floor's colour; "
                          "needs the frame's colours; 0: off",
                          [](auto& c) -> auto& { return c.validation.rimMinContrast; }));

    // validation of a ball touching a field line (issue 9: ball and line are one blob)
    s.push_back(boolKey("validation.line_rays_unknown", false,
                        "Circularity rays that leave the candidate's colours into a field line (crossing only the candidate's "
                        "colours out to line_contact_min_entry, then a line class going on past line_contact_reach) are left out, "
                        "like rays into a robot: a ball touching a line is judged on the rays that open onto carpet; off: such a "
                        "ray finds no border (ball and line are one blob) and is a miss",
                        [](auto& c) -> auto& { return c.validation.lineRaysUnknown; }));
    s.push_back(doubleKey("validation.line_contact_min_entry", "radii", 0, 10, false,
                          "line_rays_unknown: the line must start this many expected radii or more from the centre, the ray "
                          "crossing only the candidate's colours before it; smaller: a line corner whose centre pixel is "
                          "unclassified counts its own line as contact",
                          [](auto& c) -> auto& { return c.validation.lineContactMinEntry; }));
    s.push_back(doubleKey("validation.line_contact_reach", "radii", 1, 10, false,
                          "line_rays_unknown: how far out (expected radii from the centre) the line class must go on for a ray to "
                          "have met a line; shorter: a white panel ending at the ball's blurred border counts as a line too",
                          [](auto& c) -> auto& { return c.validation.lineContactReach; }));
    s.push_back(boolKey("validation.foreign_rays_unknown", false,
                        "When the candidate's centre has a ball class (the team's ball colour), circularity rays that leave that "
                        "class (crossing only it, or black, out to line_contact_min_entry) into an object that is neither carpet "
                        "nor line, going on past line_contact_reach, are left out like rays into a robot: a ball at a person's "
                        "feet or a robot's grey side; off: such a ray finds no border and is a miss",
                        [](auto& c) -> auto& { return c.validation.foreignRaysUnknown; }));
    s.push_back(boolKey("validation.marker_rays_unknown", false,
                        "With ignore_occluded_rays, rays whose border leads into a team-marker class (a robot's coloured band) are "
                        "left out like rays into black: the marker is part of a robot hiding the ball; off: they count as misses",
                        [](auto& c) -> auto& { return c.validation.markerRaysUnknown; }));
    s.push_back(boolKey("validation.line_arms", false,
                        "A candidate that passes every test is rejected (line junction) when field lines leave it like spokes: two "
                        "line arms at less than line_arms_max_angle_deg, or three or more (a corner or a V of the far lines at "
                        "the horizon, round and of a far ball's size); a ball lying on a line has its two arms opposite; off: "
                        "no such test (thesis)",
                        [](auto& c) -> auto& { return c.validation.lineArms; }));
    s.push_back(doubleKey("validation.line_arms_reach", "radii", 1, 10, false,
                          "line_arms: an arm is line class on every step from the circle out to this many expected radii; "
                          "shorter also takes a ball touching a wide line, longer misses bent or broken lines",
                          [](auto& c) -> auto& { return c.validation.lineArmsReach; }));
    s.push_back(doubleKey("validation.line_arms_lateral_px", "px", 0, 5, false,
                          "line_arms: a line pixel this far beside the ray still counts (lines bend, the centre is a pixel off); "
                          "larger takes a line passing beside the ball for an arm",
                          [](auto& c) -> auto& { return c.validation.lineArmsLateralPx; }));
    s.push_back(doubleKey("validation.line_arms_max_angle_deg", "degrees", 0, 180, false,
                          "line_arms: two arms less than this apart make a junction; farther apart they are one line through the "
                          "candidate (a ball lying on it); 0 lets every two-armed candidate pass",
                          [](auto& c) -> auto& { return c.validation.lineArmsMaxAngleDeg; }));
    s.push_back(boolKey("validation.line_arms_pale", false,
                        "line_arms: pale pixels count as line too (saturation at most pale_line_max_saturation, brightness at "
                        "least pale_line_min_value_ratio x the carpet's around the candidate): in dim and uneven light the far "
                        "lines leave the line class and their junctions lose their arms; off: the line class alone",
                        [](auto& c) -> auto& { return c.validation.lineArmsPale; }));
    s.push_back(intKey("validation.pale_line_max_saturation", "0..255", 0, 255, false,
                       "line_arms_pale: the most saturation a pale line pixel has (a line is grey or white, the carpet and "
                       "the ball's panels coloured)",
                       [](auto& c) -> auto& { return c.validation.paleLineMaxSaturation; }));
    s.push_back(doubleKey("validation.pale_line_min_value_ratio", "ratio", 1, 10, false,
                          "line_arms_pale: a pale line pixel's brightness (V) is at least this many times the carpet's mean V "
                          "in the ring around the candidate (carpet_ring_inner..carpet_ring_outer)",
                          [](auto& c) -> auto& { return c.validation.paleLineMinValueRatio; }));
    s.push_back(doubleKey("validation.pale_line_value_cap", "V (0-255)", 0, 255, false,
                          "line_arms_pale: a pale pixel at least this bright (V) is bright enough whatever the carpet's V. In "
                          "bright light pale_line_min_value_ratio x the carpet's V lies past 255 and no line pixel was pale: a "
                          "clipped spot on a line near the rim passed as a far ball; 0: the ratio alone",
                          [](auto& c) -> auto& { return c.validation.paleLineValueCap; }));
    s.push_back(doubleKey("validation.pale_line_carpet_value_ratio", "ratio", 0, 10, false,
                          "line_arms_pale: a pale pixel of the carpet's own class counts as line too when its brightness (V) is "
                          "at least this many times the carpet's mean V around the candidate and its hue and saturation are not "
                          "the carpet's (carpet_colour_sigmas): in dim light a far line is barely brighter than the carpet and "
                          "falls in its class, so a junction of far lines lost its arms; 0: the carpet's class is never line",
                          [](auto& c) -> auto& { return c.validation.paleLineCarpetValueRatio; }));
    s.push_back(doubleKey("validation.line_arms_max_radius_px", "px", 0, 100, false,
                          "line_arms: candidates whose expected radius is larger are not judged (a line junction looks round only "
                          "at a far ball's size; a near ball's border meets lines at many angles)",
                          [](auto& c) -> auto& { return c.validation.lineArmsMaxRadiusPx; }));
    s.push_back(doubleKey("validation.line_blob_min_pct", "%", 0, 100, false,
                          "line_arms: a candidate with a single line arm is rejected too when this share of its inside "
                          "(line_blob_disc) is line colour: a line's end, or a narrow V whose arms merged; lower also loses "
                          "white balls touching a far line, 100 turns it off",
                          [](auto& c) -> auto& { return c.validation.lineBlobMinPct; }));
    s.push_back(doubleKey("validation.line_blob_disc", "radii", 0, 2, false,
                          "line_blob_min_pct: the disc (expected radii around the centre) whose line share is measured, inside "
                          "the ball's blurred border",
                          [](auto& c) -> auto& { return c.validation.lineBlobDisc; }));
    s.push_back(doubleKey("validation.line_blob_armless_min_pct", "%", 0, 100, false,
                          "line_arms: a candidate with no line arm is rejected (\"line blob\") when this share of its inside "
                          "(line_blob_disc) is line colour and masked or outside pixels lie within line_blob_cut_reach: a "
                          "line's end cut by the rim, a rod or our body (its arm ended there); 100 turns it off",
                          [](auto& c) -> auto& { return c.validation.lineBlobArmlessMinPct; }));
    s.push_back(doubleKey("validation.line_blob_cut_reach", "radii", 0, 5, false,
                          "line_blob_armless_min_pct: the disc (expected radii around the centre) that must reach a masked or "
                          "outside pixel; 0 judges every armless blob, the penalty spot and a plain white ball in the open too",
                          [](auto& c) -> auto& { return c.validation.lineBlobCutReach; }));
    s.push_back(doubleKey("validation.line_blob_cut_max_radius_px", "px", 0, 200, false,
                          "line_blob_armless_min_pct: candidates larger than line_arms_max_radius_px are judged too, as "
                          "armless, up to this expected radius (a penalty spot or a line's end half behind a support rod), "
                          "unless their line_blob_cut_reach disc reaches our body (a ball touching it is cut by it); at or "
                          "below line_arms_max_radius_px only the far candidates are",
                          [](auto& c) -> auto& { return c.validation.lineBlobCutMaxRadiusPx; }));
    s.push_back(doubleKey("validation.line_blob_armless_max_panel_pct", "%", 0, 100, false,
                          "line_blob_armless_min_pct: not applied when more than this share of the disc has a class with the "
                          "black, ball or marker role (a white ball's dark or coloured panels; no line has them)",
                          [](auto& c) -> auto& { return c.validation.lineBlobArmlessMaxPanelPct; }));

    // algorithm
    ConfigKey alg{"algorithm.method", ValueType::Choice, "", 0, 0,
                  "Ball search: specific Hough (4.1), cv::HoughCircles (4.2), or specific then OpenCV when it fails (4.3)",
                  {"specific", "opencv", "combined"}, true, {}, {}};
    alg.get = [](const Config& c) { return ConfigValue(std::string(algorithmName(c.algorithm))); };
    alg.set = [](Config& c, const ConfigValue& v) {
        if (auto a = parseAlgorithm(std::get<std::string>(v))) c.algorithm = *a;
    };
    s.push_back(std::move(alg));
    return s;
}

std::string formatNumber(double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

ConfigIssue issue(ConfigIssueKind kind, const std::string& file, const std::string& key, const std::string& message)
{
    return ConfigIssue{kind, file, 0, key, message};
}

// A Markdown table cell: "|dx|+|dy|" would otherwise split the row into more columns.
std::string escapeTableCell(const std::string& text)
{
    std::string out;
    for (char ch : text) out += ch == '|' ? std::string("\\|") : std::string(1, ch);
    return out;
}

bool strictlyIncreasing(const std::vector<double>& v)
{
    for (std::size_t i = 1; i < v.size(); ++i)
        if (!(v[i] > v[i - 1])) return false;
    return true;
}

}  // namespace

std::string_view valueTypeName(ValueType t)
{
    switch (t) {
    case ValueType::Int: return "integer";
    case ValueType::Double: return "number";
    case ValueType::Bool: return "boolean";
    case ValueType::Text: return "text";
    case ValueType::Choice: return "choice";
    case ValueType::DoubleList: return "list of numbers";
    }
    return "?";
}

const std::vector<ConfigKey>& configSchema()
{
    static const std::vector<ConfigKey> schema = buildSchema();
    return schema;
}

std::vector<std::string> splitConfigPath(const std::string& path)
{
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (std::size_t dot; (dot = path.find('.', start)) != std::string::npos; start = dot + 1)
        parts.push_back(path.substr(start, dot - start));
    parts.push_back(path.substr(start));
    return parts;
}

const ConfigKey* findConfigKey(std::string_view path)
{
    for (const ConfigKey& k : configSchema())
        if (k.path == path) return &k;
    return nullptr;
}

std::string formatConfigValue(const ConfigValue& v)
{
    if (const int* i = std::get_if<int>(&v)) return std::to_string(*i);
    if (const double* d = std::get_if<double>(&v)) return formatNumber(*d);
    if (const bool* b = std::get_if<bool>(&v)) return *b ? "true" : "false";
    if (const std::string* s = std::get_if<std::string>(&v)) return *s;
    std::string out = "[";
    for (double d : std::get<std::vector<double>>(v)) out += (out.size() > 1 ? ", " : "") + formatNumber(d);
    return out + "]";
}

std::vector<ConfigIssue> checkConfig(const Config& c, const std::string& file)
{
    std::vector<ConfigIssue> out;
    for (const ConfigKey& k : configSchema()) {
        const ConfigValue v = k.get(c);
        const std::string range = formatNumber(k.min) + ".." + formatNumber(k.max);
        auto outside = [&](double x) { return !(x >= k.min && x <= k.max); };  // NaN is outside
        if (k.type == ValueType::Int || k.type == ValueType::Double) {
            const double x = k.type == ValueType::Int ? double(std::get<int>(v)) : std::get<double>(v);
            if (outside(x))
                out.push_back(issue(ConfigIssueKind::OutOfRange, file, k.path,
                                    formatConfigValue(v) + " is outside " + range + (k.unit.empty() ? "" : " " + k.unit)));
        } else if (k.type == ValueType::Text) {
            const std::string& s = std::get<std::string>(v);
            if (s.size() > kMaxYamlTextBytes)
                out.push_back(issue(ConfigIssueKind::OutOfRange, file, k.path,
                                    "is " + std::to_string(s.size()) + " characters long; at most " +
                                        std::to_string(kMaxYamlTextBytes) + " can be saved and read back"));
            else if (const std::size_t at = findUnsavableCharacter(s); at != std::string::npos)
                out.push_back(issue(ConfigIssueKind::WrongType, file, k.path,
                                    "contains a control character (at " + std::to_string(at) +
                                        "), which could not be saved back"));
        } else if (k.type == ValueType::DoubleList) {
            for (double x : std::get<std::vector<double>>(v))
                if (outside(x)) {
                    out.push_back(issue(ConfigIssueKind::OutOfRange, file, k.path,
                                        "element " + formatNumber(x) + " is outside " + range + " " + k.unit));
                    break;
                }
        }
    }
    auto inconsistent = [&](const std::string& key, const std::string& message) {
        out.push_back(issue(ConfigIssueKind::Inconsistent, file, key, message));
    };
    if (c.edges.cannyLow > c.edges.cannyHigh)
        inconsistent("edges.canny_low", "canny_low (" + std::to_string(c.edges.cannyLow) + ") is above canny_high (" +
                                            std::to_string(c.edges.cannyHigh) + ")");
    if (!(c.geometry.innerRadius < c.geometry.outerRadius))
        inconsistent("geometry.inner_radius", "inner_radius must be below outer_radius");
    if (c.geometry.centerX >= c.geometry.imageWidth || c.geometry.centerY >= c.geometry.imageHeight)
        inconsistent("geometry.center_x", "the robot centre lies outside the " + std::to_string(c.geometry.imageWidth) + "x" +
                                              std::to_string(c.geometry.imageHeight) + " image");
    else if (c.geometry.innerRadius < c.geometry.outerRadius && ringShareInImage(c.geometry) <= 0.0)
        inconsistent("geometry.inner_radius", "the processed ring (inner_radius " + formatNumber(c.geometry.innerRadius) +
                                                  " to outer_radius " + formatNumber(c.geometry.outerRadius) +
                                                  " px around the centre) lies entirely outside the image");
    if (!(c.sensors.innerRadius < c.sensors.outerRadius))
        inconsistent("sensors.inner_radius", "inner_radius must be below outer_radius");
    const auto& dm = c.distanceMap;
    if (dm.pixelRadii.size() < 2 || dm.pixelRadii.size() != dm.groundDistances.size())
        inconsistent("distance_map.ground_distances", "pixel_radii has " + std::to_string(dm.pixelRadii.size()) +
                                                          " points and ground_distances " + std::to_string(dm.groundDistances.size()) +
                                                          "; both need the same number, at least 2");
    if (!strictlyIncreasing(dm.pixelRadii)) inconsistent("distance_map.pixel_radii", "must be strictly increasing");
    if (!strictlyIncreasing(dm.groundDistances)) inconsistent("distance_map.ground_distances", "must be strictly increasing");
    if (!(dm.viewpointHeight > dm.ballRadius))
        inconsistent("distance_map.viewpoint_height", "the viewpoint must be above the ball centre (ball_radius)");
    if (c.ball.minRadius > c.ball.maxRadius) inconsistent("ball.min_radius", "min_radius is above max_radius");
    if (c.hough.areaBounds.empty()) inconsistent("hough.area_bounds", "needs at least one bound");
    if (c.hough.areaBounds.size() > 254) inconsistent("hough.area_bounds", "at most 254 areas");
    if (!strictlyIncreasing(c.hough.areaBounds)) inconsistent("hough.area_bounds", "must be strictly increasing");
    if (c.opencvHough.minRadiusRatio >= c.opencvHough.maxRadiusRatio)
        inconsistent("opencv_hough.min_radius_ratio", "min_radius_ratio must be below max_radius_ratio");
    if (c.opencvHough.minRadius > c.opencvHough.maxRadius)
        inconsistent("opencv_hough.min_radius", "min_radius is above max_radius");
    for (ConfigIssue& i : checkColourClasses(c.colors.classes, file)) out.push_back(std::move(i));
    if (c.validation.ballHint != "none") {
        const int hint = findColourClass(c.colors.classes, c.validation.ballHint);
        if (hint < 0)
            inconsistent("validation.ball_hint_class", "\"" + c.validation.ballHint + "\" is no class of colors.classes (or none)");
        else if (c.colors.classes[std::size_t(hint)].role == ColourRole::Field)
            inconsistent("validation.ball_hint_class", "\"" + c.validation.ballHint + "\" is a field class: the ball is never carpet");
    }
    if (!(c.validation.carpetRingInner < c.validation.carpetRingOuter))
        inconsistent("validation.carpet_ring_inner", "carpet_ring_inner must be below carpet_ring_outer");
    if (!c.mask.empty() && c.mask.type() != CV_8UC1)
        out.push_back(issue(ConfigIssueKind::MaskError, file, "geometry.mask_file",
                            "the mask has " + std::to_string(c.mask.channels()) + " channel(s) of depth " +
                                std::to_string(c.mask.depth()) + "; it must be one 8-bit channel"));
    else if (!c.mask.empty() && (c.mask.cols != c.geometry.imageWidth || c.mask.rows != c.geometry.imageHeight))
        out.push_back(issue(ConfigIssueKind::MaskError, file, "geometry.mask_file",
                            "the mask is " + std::to_string(c.mask.cols) + "x" + std::to_string(c.mask.rows) +
                                " but the image is " + std::to_string(c.geometry.imageWidth) + "x" +
                                std::to_string(c.geometry.imageHeight)));
    return out;
}

std::string configSchemaMarkdown()
{
    static const std::pair<const char*, const char*> sections[] = {
        {"camera", "Camera settings (IIDC features through libdc1394), in the camera's register units."},
        {"camera_auto", "Automatic camera calibration (thesis ch. 4, ref. [31]; docs/cameras.md): exposure then gain "
                        "bring the mean sample value (MSV) of the intensity histogram over the geometry's ring to its "
                        "target, white balance makes the white region neutral, brightness brings the black region to "
                        "its level. Controller gains are fractions of the feature's range per unit of error."},
        {"colors", "The colour table's size and relative black. The colour classes themselves are the list "
                   "`colors.classes`, described below the table."},
        {"denoise", "A blur of noisy frames before segmentation (not in the thesis)."},
        {"geometry", "Where the robot is in the image and which pixels are processed."},
        {"sensors", "Radial sensors for line and obstacle search (thesis Fig. 4.3)."},
        {"distance_map", "Image distance (px) to ground distance (m), monotone cubic through the calibration points; "
                         "the ball position is scaled by (viewpoint_height - ball_radius) / viewpoint_height."},
        {"ball", "Expected ball radius in the image by distance to the centre (thesis Fig. 4.7), and the validation square."},
        {"edges", "Canny on the green / non-green image (thesis 4, Fig. 4.6), or on the frame's grayscale."},
        {"hough", "Specific circular Hough transform (thesis 4.1)."},
        {"opencv_hough", "cv::HoughCircles with HOUGH_GRADIENT (thesis 4.2)."},
        {"validation", "Candidate validation (thesis 4.4): the three tests and our rules must all pass."},
        {"algorithm", "Which search runs (thesis 4.1-4.3)."},
    };
    const Config defaults;
    std::ostringstream md;
    md << "# config.yml reference\n\n"
       << "<!-- Generated from core/ConfigSchema.cpp by `omnitune-config --doc`; do not edit by hand.\n"
       << "     The test core/config_schema fails when this file is out of date. -->\n\n"
       << "`config.yml` is written and read with OpenCV's `cv::FileStorage` (YAML), so the robot needs nothing\n"
       << "beyond OpenCV to read it. It starts with `schema: " << kConfigSchemaVersion << "`; a file with another\n"
       << "schema version is refused. Files OmniTune writes also carry `saved_by` at the top and `complete: 1`\n"
       << "at the end: a saved file without the end marker was cut short and is refused. A missing key takes its\n"
       << "default with a warning; an unknown key is reported as a warning (a typo?). A key or section written\n"
       << "twice, an integer beyond the integer range or with a leading zero (`0100`, octal in YAML: write `100`),\n"
       << "nesting deeper than 64 levels and files above 1 MiB are refused with the line. Saving writes a\n"
       << "temporary file and renames it over `config.yml`; `config.yml.bak` keeps the file as it was before\n"
       << "OmniTune first saved over it and is never overwritten (delete it to take a fresh backup).\n\n"
       << "Defaults marked (thesis) are the numbers published in the thesis (chapter 4); the others are\n"
       << "OmniTune's choices for the bundled simulated camera and should be tuned per robot.\n";
    for (const auto& [name, text] : sections) {
        md << "\n## " << name << "\n\n" << text << "\n\n"
           << "| key | type | unit | default | range | meaning |\n|---|---|---|---|---|---|\n";
        for (const ConfigKey& k : configSchema()) {
            if (k.path.compare(0, std::string(name).size() + 1, std::string(name) + ".") != 0) continue;
            std::string range;
            if (k.type == ValueType::Choice) {
                for (const auto& ch : k.choices) range += (range.empty() ? "" : ", ") + ("`" + ch + "`");
            } else if (k.type == ValueType::Int || k.type == ValueType::Double || k.type == ValueType::DoubleList) {
                range = formatNumber(k.min) + " .. " + formatNumber(k.max);
            }
            std::string def = formatConfigValue(k.get(defaults));
            if (def.empty()) def = "(empty)";
            md << "| `" << k.path << "` | " << valueTypeName(k.type) << " | " << k.unit << " | `" << def << "`"
               << (k.fromThesis ? " (thesis)" : "") << " | " << range << " | " << escapeTableCell(k.meaning) << " |\n";
        }
        if (std::string(name) == "colors") md << colourClassesMarkdown();
    }
    return md.str();
}

}  // namespace omnitune
