#include "calib/session/SessionExport.h"

#include "calib/session/TruthCsv.h"
#include "core/AtomicFile.h"

#include <opencv2/imgproc.hpp>

#include <filesystem>

namespace omnitune {

namespace fs = std::filesystem;

SessionExportResult exportSession(FrameSource& source, const std::string& folder, const Config& config,
                                  const SessionExportOptions& options, Progress* progress)
{
    SessionExportResult out;
    const int total = source.frameCount();
    // Start from the first frame whatever the source was asked for before.
    Frame frame;
    std::optional<FrameError> err = source.isSeekable() && total > 0 ? source.read(0, frame)
                                                                       : source.read(FrameSource::kNext, frame);
    std::optional<SessionWriter> writer;
    auto advance = [&] { err = source.read(FrameSource::kNext, frame); };
    for (int read = 0;; ++read, advance()) {
        if (progress && progress->isCancelRequested()) {
            out.cancelled = true;
            break;
        }
        if (err && err->kind == FrameErrorKind::OutOfRange) break;  // the end
        if (err) {
            out.skipped.push_back(err->toString());
            continue;
        }
        cv::Mat bgr = frame.image;
        if (frame.format == PixelFormat::Uyvy) cv::cvtColor(frame.image, bgr, cv::COLOR_YUV2BGR_UYVY);
        if (!writer) {  // the first readable frame sets the session's size
            SessionInfo info;
            info.camera = frame.camera.value_or(config.camera);
            info.width = bgr.cols;
            info.height = bgr.rows;
            info.frameRate = config.camera.frameRate;
            info.notes = options.notes.empty() ? "saved from " + source.description() : options.notes;
            SessionCreate created = SessionWriter::create(folder, info, options.writer);
            if (!created.ok()) {
                out.error = created.error;
                return out;
            }
            writer = std::move(created.writer);
            // A config for another camera would make the session unreadable with it: left out.
            if (bgr.size() != cv::Size(config.geometry.imageWidth, config.geometry.imageHeight))
                out.configNote = "config.yml not written: the config is for " + std::to_string(config.geometry.imageWidth) +
                                 "x" + std::to_string(config.geometry.imageHeight) + " frames, these are " +
                                 std::to_string(bgr.cols) + "x" + std::to_string(bgr.rows);
            else if ((out.error = writer->writeConfig(config)))
                return out;
        }
        if (bgr.size() != cv::Size(writer->info().width, writer->info().height)) {
            out.skipped.push_back("frame " + std::to_string(read) + " is " + std::to_string(bgr.cols) + "x" +
                                  std::to_string(bgr.rows) + ", not the session's " +
                                  std::to_string(writer->info().width) + "x" + std::to_string(writer->info().height));
            continue;
        }
        if ((out.error = writer->appendFrame(bgr))) return out;
        ++out.frames;
        if (progress && total > 0) progress->update(100.0 * double(read + 1) / double(total));
    }
    if (!writer) {
        if (!out.cancelled) {
            const std::string why = out.skipped.empty() ? "it has no frames" : "no frame could be read: " + out.skipped.front();
            out.error = SessionIssue{SessionIssueKind::FileUnreadable, source.description(), 0, "",
                                     "nothing to save as a session: " + why};
        }
        return out;
    }
    if ((out.error = writer->finish())) return out;
    // The marks go here; the header alone says which columns they fill.
    const std::string truth = (fs::path(folder) / kSessionTruthFile).string();
    if (auto why = writeFileAtomically(truth, truthCsvHeader() + "\n", false))
        out.error = SessionIssue{SessionIssueKind::WriteError, truth, 0, "", *why};
    return out;
}

}  // namespace omnitune
