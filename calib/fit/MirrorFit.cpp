#include "calib/fit/MirrorFit.h"

#include "calib/config/ProvisionalGeometry.h"

#include <algorithm>

namespace omnitune {

MirrorFitResult fitMirror(const std::vector<cv::Mat>& frames, const Config& start, const RimFitOptions& options,
                          bool fitBodyToo, Progress* progress)
{
    MirrorFitResult r;
    if (frames.empty()) {
        r.error = FitError{FitErrorKind::TooFewFrames, "no frame to fit the mirror rim to"};
        return r;
    }
    const cv::Size size = frames.front().size();
    r.config = start;
    if (size != cv::Size(start.geometry.imageWidth, start.geometry.imageHeight)) {
        ProvisionalGeometry p = provisionalGeometry(start, size);
        r.config = std::move(p.config);
        r.adapted = std::move(p.changes);
    }
    const RimFitResult rim = fitRim(frames, options, progress);
    if (!rim.ok()) {
        r.error = rim.error;
        return r;
    }
    r.rim = rim.fit;
    if (fitBodyToo) {
        const BodyFitResult body = fitBody(frames, rim.fit.centre, rim.fit.rimRadius, {}, progress);
        if (!body.ok()) {
            r.error = body.error;
            return r;
        }
        r.body = body.fit;
    }
    GeometryOptions& g = r.config.geometry;
    applyRimFit(r.rim, size, g);
    if (r.body) g.innerRadius = r.body->innerRadius;
    // A body fit can never leave the ring empty; a kept inner radius from another camera can.
    g.innerRadius = std::min(g.innerRadius, 0.9 * g.outerRadius);
    return r;
}

}  // namespace omnitune
