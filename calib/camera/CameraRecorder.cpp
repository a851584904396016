#include "calib/camera/CameraRecorder.h"

#include "calib/camera/CameraSettingsIo.h"
#include "calib/session/SessionWriter.h"

#include <filesystem>

namespace omnitune {

CameraRecorder::Start CameraRecorder::start(Camera& camera, const std::string& folder, const CameraRecorderOptions& options)
{
    Start out;
    SessionInfo info;
    info.camera = readCameraSettings(camera, options.config ? options.config->camera : CameraSettings{});
    info.width = camera.frameSize().width;
    info.height = camera.frameSize().height;
    info.frameRate = info.camera.frameRate;
    info.notes = options.notes.empty() ? "recorded from " + camera.description() : options.notes;
    SessionCreate created = SessionWriter::create(folder, info);
    if (!created.ok()) {
        out.error = created.error->toString();
        return out;
    }
    if (options.config)
        if (auto err = created.writer->writeConfig(*options.config)) {
            out.error = err->toString();
            return out;  // the empty session is closed by its writer
        }
    std::unique_ptr<CameraRecorder> r(new CameraRecorder);
    r->folder_ = folder;
    r->minFreeBytes_ = options.minFreeBytes;
    r->queueFrames_ = std::size_t(std::max(options.queueFrames, 1));
    r->writer_ = std::make_unique<SessionWriter>(std::move(*created.writer));
    r->status_.running = true;
    r->thread_ = std::thread(&CameraRecorder::run, r.get());
    out.recorder = std::move(r);
    return out;
}

CameraRecorder::~CameraRecorder() { finish(); }

bool CameraRecorder::push(const Frame& frame, bool wait)
{
    std::unique_lock<std::mutex> lock(mutex_);
    if (!status_.running || stopping_) return false;
    if (lastIndex_ >= 0) status_.dropped += std::max(frame.index - lastIndex_ - 1, 0);
    lastIndex_ = frame.index;
    if (firstTime_ < 0) firstTime_ = frame.timestampS;
    status_.seconds = frame.timestampS - firstTime_;
    if (wait)
        changed_.wait(lock, [this] { return queue_.size() < queueFrames_ || !status_.running; });
    if (!status_.running) return false;
    if (queue_.size() >= queueFrames_) {
        ++status_.dropped;
        return true;
    }
    queue_.push_back(frame.image);
    changed_.notify_all();
    return true;
}

CameraRecorderStatus CameraRecorder::status() const
{
    std::lock_guard<std::mutex> lock(mutex_);
    return status_;
}

CameraRecorderStatus CameraRecorder::finish()
{
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
    if (thread_.joinable()) thread_.join();
    return status();
}

std::optional<std::string> CameraRecorder::checkSpace()
{
    std::error_code ec;
    const std::filesystem::space_info space = std::filesystem::space(folder_, ec);
    if (ec) return std::nullopt;  // unknown: the write itself will tell
    {
        std::lock_guard<std::mutex> lock(mutex_);
        status_.freeBytes = space.available;
    }
    if (space.available >= minFreeBytes_) return std::nullopt;
    constexpr std::uint64_t kMb = 1024 * 1024;
    return "recording stopped: " + std::to_string(space.available / kMb) + " MB free on the disk of " + folder_
           + ", less than camera.record_min_free_mb (" + std::to_string(minFreeBytes_ / kMb) + " MB)";
}

void CameraRecorder::run()
{
    std::optional<std::string> error = checkSpace();
    while (!error) {
        cv::Mat image;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            changed_.wait(lock, [this] { return !queue_.empty() || stopping_; });
            if (queue_.empty()) break;  // stopping, and everything queued is written
            image = queue_.front();
            queue_.pop_front();
        }
        changed_.notify_all();  // room in the queue for a waiting push()
        if ((error = checkSpace())) break;
        if (auto err = writer_->appendFrame(image)) {
            error = err->toString();
            break;
        }
        std::lock_guard<std::mutex> lock(mutex_);
        ++status_.written;
    }
    const auto finished = writer_->finish();
    std::lock_guard<std::mutex> lock(mutex_);
    if (!error && finished) error = finished->toString();
    status_.error = error;
    status_.dropped += int(queue_.size());  // left unwritten after an error
    queue_.clear();
    status_.running = false;
    changed_.notify_all();
}

}  // namespace omnitune
