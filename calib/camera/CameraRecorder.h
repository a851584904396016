#pragma once
// Writes a live camera's frames into a session folder (calib/session/SessionWriter) on a
// thread of its own, so that the one who grabs (the window's live view, omnitune-camera
// --record) never waits for a PNG to be compressed and flushed. Frames go through a bounded
// queue: a full queue either drops the new frame (the window: the live view must not stall)
// or makes push() wait (the command line: every frame the camera gives is written). The
// session gets the camera's settings read back at the start as its camera snapshot
// (session.yml) and, when given, the config in use (config.yml). Before each frame the free
// space of the folder's disk is checked; below `minFreeBytes` the recording stops cleanly with
// a message. Everything written stays: the session is closed on stop, on an error and in the
// destructor, and SessionWriter keeps a killed recording readable.
#include "calib/camera/Camera.h"
#include "core/Config.h"

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace omnitune {

class SessionWriter;

struct CameraRecorderOptions {
    std::string notes;                 // session.yml notes; empty: "recorded from CAMERA"
    std::optional<Config> config;      // written as the session's config.yml
    int queueFrames = 8;               // frames waiting for the writer at most, >= 1
    std::uint64_t minFreeBytes = 0;    // stop below this much free disk space (config camera.record_min_free_mb)
};

struct CameraRecorderStatus {
    int written = 0;                   // frames in the session
    int dropped = 0;                   // frames the camera gave (or skipped) that were not written
    double seconds = 0;                // camera time from the first frame to the last one pushed
    std::uint64_t freeBytes = 0;       // free space on the folder's disk, at the last check
    bool running = false;              // false once stopped, finished or failed
    std::optional<std::string> error;  // why it stopped by itself (disk full, a write failed)
};

class CameraRecorder {
public:
    struct Start {
        std::unique_ptr<CameraRecorder> recorder;  // set when ok()
        std::string error;
        bool ok() const { return recorder != nullptr; }
    };
    // Creates the session in `folder` (new or empty, SessionWriter's rules) for `camera`'s
    // frames and starts the writer thread. The camera is only read here (settings, size).
    static Start start(Camera& camera, const std::string& folder, const CameraRecorderOptions& options = {});

    ~CameraRecorder();
    CameraRecorder(const CameraRecorder&) = delete;
    CameraRecorder& operator=(const CameraRecorder&) = delete;

    // Hands `frame` (BGR, the camera's size) to the writer. `wait`: blocks while the queue is
    // full; else a full queue drops it (counted). Gaps in the camera's frame index count as
    // dropped too. False once the recording has stopped.
    bool push(const Frame& frame, bool wait);
    CameraRecorderStatus status() const;
    // Writes what is queued, closes the session and ends the thread; the final status. Again: no-op.
    CameraRecorderStatus finish();
    const std::string& folder() const { return folder_; }

private:
    CameraRecorder() = default;
    void run();
    std::optional<std::string> checkSpace();

    std::string folder_;
    std::uint64_t minFreeBytes_ = 0;
    std::size_t queueFrames_ = 8;
    std::unique_ptr<SessionWriter> writer_;  // the writer thread's alone once started
    std::thread thread_;
    mutable std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<cv::Mat> queue_;
    CameraRecorderStatus status_;
    bool stopping_ = false;
    int lastIndex_ = -1;
    double firstTime_ = -1;
};

}  // namespace omnitune
