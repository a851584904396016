#pragma once
// One camera found on this machine: the --source text that opens it and a name for people.
#include <string>
#include <vector>

namespace omnitune {

struct CameraInfo {
    std::string source;  // "dc1394:0x00b09d0100a01a9a", "v4l2:/dev/video0", "simulated"
    std::string name;    // "Point Grey Research Flea2 FL2-03S2C", "UVC Camera (046d:0825)"
};

// What a look for cameras found: the cameras, and per backend that found none a note why
// ("dc1394: no FireWire bus (...)", "v4l2: no /dev/video* device").
struct CameraScan {
    std::vector<CameraInfo> cameras;
    std::vector<std::string> notes;
};

}  // namespace omnitune
