#pragma once
// Camera parameters the thesis calibrates for a good colour image (ch. 4): exposure, white
// balance, gain, brightness, in the camera's own register units (IIDC / libdc1394 features).
#include <string>

namespace omnitune {

struct CameraSettings {
    std::string model;           // free text, e.g. "PointGrey Flea2"; informational
    // Which camera the window and omnitune-camera open: "dc1394", "dc1394:GUID", "v4l2",
    // "v4l2:/dev/videoN", "simulated"; empty: the first camera found. The settings below are
    // written to it when it opens.
    std::string source;
    double frameRate = 30.0;     // frames/s
    int exposure = 300;          // IIDC EXPOSURE register value, 0..4095
    int whiteBalanceBlue = 500;  // IIDC WHITE_BALANCE U/B, 0..1023
    int whiteBalanceRed = 500;   // IIDC WHITE_BALANCE V/R, 0..1023
    int gain = 200;              // IIDC GAIN, 0..1023
    int brightness = 100;        // IIDC BRIGHTNESS, 0..1023
    // The workbench's live view, not the camera's registers:
    double replaySeconds = 10.0;  // s of live frames kept to step through after a pause
    int recordMinFreeMb = 500;    // MB: a recording stops when its disk has less free space
};

}  // namespace omnitune
