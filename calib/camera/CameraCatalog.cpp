#include "calib/camera/CameraCatalog.h"

#include "calib/camera/Dc1394Camera.h"
#include "calib/camera/V4l2Camera.h"

namespace omnitune {

namespace {

CameraOpen opened(std::unique_ptr<Camera> camera)
{
    CameraOpen out;
    if (auto err = camera->open())
        out.error = err;
    else
        out.camera = std::move(camera);
    return out;
}

CameraOpen refuse(CameraErrorKind kind, std::string message)
{
    CameraOpen out;
    out.error = CameraError{kind, std::move(message)};
    return out;
}

}  // namespace

CameraScan listCameras()
{
    CameraScan all = listDc1394Cameras();
    CameraScan v4l2 = listV4l2Cameras();
    all.cameras.insert(all.cameras.end(), v4l2.cameras.begin(), v4l2.cameras.end());
    all.notes.insert(all.notes.end(), v4l2.notes.begin(), v4l2.notes.end());
    return all;
}

CameraOpen openCamera(const std::string& source, double frameRate, const SimulatedCameraOptions& simulated)
{
    const std::size_t colon = source.find(':');
    const std::string kind = source.substr(0, colon);
    const std::string arg = colon == std::string::npos ? "" : source.substr(colon + 1);
    if (kind == "simulated" && arg.empty()) {
        SimulatedCameraOptions o = simulated;
        o.frameRate = frameRate;
        return opened(std::make_unique<SimulatedCamera>(o));
    }
    if (kind == "dc1394") {
        std::optional<std::uint64_t> guid;
        if (!arg.empty()) {
            guid = parseGuid(arg);
            if (!guid)
                return refuse(CameraErrorKind::NoDevice,
                              "dc1394:" + arg + ": not a GUID (a 64-bit hex number such as 0x00b09d0100a01a9a)");
        }
        Dc1394Options o;
        o.frameRate = frameRate;
        return opened(std::make_unique<Dc1394Camera>(guid, o));
    }
    if (kind == "v4l2") return opened(std::make_unique<V4l2Camera>(arg, frameRate));
    if (source.empty()) {
        const CameraScan scan = listCameras();
        if (scan.cameras.empty()) {
            std::string why = "no camera found";
            for (const std::string& n : scan.notes) why += "; " + n;
            return refuse(CameraErrorKind::NoDevice, why + " (--source simulated runs the simulated camera)");
        }
        return openCamera(scan.cameras.front().source, frameRate, simulated);
    }
    return refuse(CameraErrorKind::NoDevice,
                  "unknown camera source '" + source + "': use dc1394[:GUID], v4l2[:DEVICE] or simulated");
}

}  // namespace omnitune
