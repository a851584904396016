#include "calib/fit/RimFit.h"

#include "calib/fit/FitText.h"
#include "calib/fit/GrayFrames.h"
#include "core/Pi.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace omnitune {

namespace {

constexpr double kStepPx = 0.5;  // sampling step along a ray

float sampleAt(const cv::Mat& img, double x, double y)
{
    const int x0 = std::clamp(int(std::floor(x)), 0, img.cols - 2);
    const int y0 = std::clamp(int(std::floor(y)), 0, img.rows - 2);
    const double fx = x - x0;
    const double fy = y - y0;
    const float* r0 = img.ptr<float>(y0);
    const float* r1 = img.ptr<float>(y0 + 1);
    return float((1 - fy) * ((1 - fx) * r0[x0] + fx * r0[x0 + 1]) + fy * ((1 - fx) * r1[x0] + fx * r1[x0 + 1]));
}

// Distance from `c` (inside the frame) along `dir` to the last point inside the pixel centres.
double distanceToBorder(cv::Point2d c, cv::Point2d dir, cv::Size size)
{
    double t = 1e12;
    if (dir.x > 1e-12) t = std::min(t, (size.width - 1 - c.x) / dir.x);
    if (dir.x < -1e-12) t = std::min(t, -c.x / dir.x);
    if (dir.y > 1e-12) t = std::min(t, (size.height - 1 - c.y) / dir.y);
    if (dir.y < -1e-12) t = std::min(t, -c.y / dir.y);
    return std::max(0.0, t);
}

double meanOf(const std::vector<float>& p, int from, int to)  // inclusive, clamped
{
    from = std::max(from, 0);
    to = std::min(to, int(p.size()) - 1);
    if (from > to) return p.empty() ? 0.0 : p.back();
    double s = 0;
    for (int i = from; i <= to; ++i) s += p[std::size_t(i)];
    return s / (to - from + 1);
}

// The rim along one ray: walked inwards from the frame border, the first bright stretch after a
// dark one; located at the crossing of the level halfway between the local dark and bright.
std::optional<double> rimAlongRay(const std::vector<float>& p, double threshold, double darkest,
                                  const RimFitOptions& o)
{
    const int n = int(p.size());
    const int darkRun = std::max(1, int(std::ceil(o.darkRunPx / kStepPx)));
    const int brightRun = std::max(1, int(std::ceil(o.brightRunPx / kStepPx)));
    for (int j = n - 1; j >= 0; --j) {
        if (p[std::size_t(j)] < threshold) continue;
        if (n - 1 - j < darkRun) return std::nullopt;  // the ray met the border inside the mirror
        if (j - brightRun < 0) return std::nullopt;
        if (meanOf(p, j - brightRun, j) < threshold) continue;  // a bright speck in the housing
        const double bright = meanOf(p, j - 2 * brightRun, j - brightRun);
        const double dark = meanOf(p, j + darkRun, j + 2 * darkRun);
        if (dark > darkest) return std::nullopt;  // not the housing: a mirror overfilling the frame
        const double mid = 0.5 * (bright + dark);
        for (int k = std::min(n - 2, j + darkRun); k >= std::max(0, j - brightRun); --k) {
            const double a = p[std::size_t(k)];
            const double b = p[std::size_t(k + 1)];
            if (a >= mid && b < mid) return (k + (a - mid) / (a - b)) * kStepPx;
        }
        const double a = p[std::size_t(j)];
        const double b = p[std::size_t(j + 1)];
        return (j + (a - threshold) / std::max(a - b, 1e-6)) * kStepPx;
    }
    return std::nullopt;
}

std::vector<cv::Point2d> castRays(const cv::Mat& mean, cv::Point2d centre, double threshold, double darkest,
                                  const RimFitOptions& o)
{
    std::vector<cv::Point2d> points;
    std::vector<float> profile;
    for (int k = 0; k < o.rays; ++k) {
        const double a = 2 * kPi * k / o.rays;
        const cv::Point2d dir(std::cos(a), std::sin(a));
        const double length = distanceToBorder(centre, dir, mean.size());
        profile.clear();
        for (double r = 0; r <= length; r += kStepPx)
            profile.push_back(sampleAt(mean, centre.x + r * dir.x, centre.y + r * dir.y));
        if (const auto r = rimAlongRay(profile, threshold, darkest, o)) points.push_back(centre + *r * dir);
    }
    return points;
}

// Degrees of the circle around `c` that the kept points span: 360 minus the widest gap.
double coverageDeg(const std::vector<cv::Point2d>& pts, const std::vector<bool>& keep, cv::Point2d c)
{
    std::vector<double> angles;
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (keep[i]) angles.push_back(std::atan2(pts[i].y - c.y, pts[i].x - c.x) * 180 / kPi);
    if (angles.size() < 2) return 0.0;
    std::sort(angles.begin(), angles.end());
    double gap = angles.front() + 360 - angles.back();
    for (std::size_t i = 1; i < angles.size(); ++i) gap = std::max(gap, angles[i] - angles[i - 1]);
    return 360 - gap;
}

FitError noRim(const std::string& why)
{
    return {FitErrorKind::NoRim, "no mirror rim found: " + why +
                                     "; use frames in which the mirror's edge and the dark outside are visible, or set the "
                                     "centre and outer radius by hand"};
}

}  // namespace

RimFitResult fitRim(const std::vector<cv::Mat>& frames, const RimFitOptions& options, Progress* progress)
{
    RimFitResult result;
    if (frames.empty()) {
        result.error = FitError{FitErrorKind::BadInput, "no frames given: the rim fit needs at least one frame"};
        return result;
    }
    std::vector<cv::Mat> gray;
    if (auto e = toGrayFrames(frames, gray)) {
        result.error = e;
        return result;
    }
    cv::Mat mean = cv::Mat::zeros(gray.front().size(), CV_32F);
    for (std::size_t i = 0; i < gray.size(); ++i) {
        if (progress && progress->isCancelRequested()) {
            result.error = FitError{FitErrorKind::Cancelled, "rim fit cancelled"};
            return result;
        }
        mean += gray[i];
        if (progress) progress->update(60.0 * double(i + 1) / double(gray.size()));
    }
    mean /= double(gray.size());
    if (mean.cols < 8 || mean.rows < 8) {
        result.error = FitError{FitErrorKind::BadInput, "the frames are too small for a rim fit"};
        return result;
    }

    // Dark and bright apart by Otsu; a frame without both is black, blank or overexposed.
    cv::Mat u8;
    mean.convertTo(u8, CV_8U);
    std::vector<int> histogram(256, 0);
    for (int y = 0; y < u8.rows; ++y)
        for (int x = 0; x < u8.cols; ++x) ++histogram[u8.at<std::uint8_t>(y, x)];
    const auto percentile = [&](double share) {
        const double want = share * double(u8.total());
        double seen = 0;
        for (int v = 0; v < 256; ++v)
            if ((seen += histogram[std::size_t(v)]) >= want) return v;
        return 255;
    };
    const int low = percentile(0.02);
    const int high = percentile(0.98);
    if (high - low < options.minContrast) {
        result.error = FitError{FitErrorKind::Uniform,
                                "the frames show no contrast (grey levels " + std::to_string(low) + ".." +
                                    std::to_string(high) +
                                    "): they are black, blank or overexposed; check the camera and use frames that show "
                                    "the field in the mirror"};
        return result;
    }
    const double darkest = low + options.darkShare * (high - low);
    cv::Mat bright;
    const double threshold = cv::threshold(u8, bright, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);

    cv::Point2d guess;
    if (options.initialCentre) {
        guess = *options.initialCentre;
    } else {
        const cv::Moments m = cv::moments(bright, true);
        guess = {m.m10 / m.m00, m.m01 / m.m00};  // m00 > 0: the contrast check found bright pixels
    }
    if (!(guess.x >= 0 && guess.y >= 0 && guess.x <= mean.cols - 1 && guess.y <= mean.rows - 1)) {
        result.error = FitError{FitErrorKind::BadInput, "the first-guess centre (" + fixedText(guess.x) + ", " + fixedText(guess.y) +
                                                            ") lies outside the frame"};
        return result;
    }

    // Twice: the second pass casts its rays from the first fit's centre, so they meet the rim
    // square on and evenly spread.
    RimFit& fit = result.fit;
    fit.threshold = threshold;
    CircleFit circle;
    for (int pass = 0; pass < 2; ++pass) {
        if (progress && progress->isCancelRequested()) {
            result.error = FitError{FitErrorKind::Cancelled, "rim fit cancelled"};
            return result;
        }
        const cv::Point2d from = pass == 0 ? guess : circle.centre;
        if (pass == 1 && !(from.x >= 0 && from.y >= 0 && from.x <= mean.cols - 1 && from.y <= mean.rows - 1)) break;
        std::vector<cv::Point2d> points = castRays(mean, from, threshold, darkest, options);
        if (int(points.size()) < options.minPoints) {
            if (pass == 1) break;  // keep the first pass
            result.error = noRim("only " + std::to_string(points.size()) + " of " + std::to_string(options.rays) +
                                 " rays from (" + fixedText(from.x) + ", " + fixedText(from.y) +
                                 ") met a bright-to-dark edge with dark outside it (" + std::to_string(options.minPoints) +
                                 " needed)");
            return result;
        }
        const CircleFit next = fitCircle(points, options.circle);
        if (!next.ok) {
            if (pass == 1) break;
            result.error = noRim("the edge points do not lie on a circle");
            return result;
        }
        circle = next;
        fit.points = std::move(points);
        fit.raysCast = options.rays;
        if (progress) progress->update(pass == 0 ? 80.0 : 100.0);
    }

    fit.centre = circle.centre;
    fit.rimRadius = circle.radius;
    fit.outerRadius = circle.radius - options.marginPx;
    fit.rmsPx = circle.rms;
    fit.inlier = circle.inlier;
    fit.inliers = circle.inliers;
    fit.coverageDeg = coverageDeg(fit.points, fit.inlier, fit.centre);
    if (fit.inliers < options.minPoints) {
        result.error = noRim("only " + std::to_string(fit.inliers) + " edge points agree on one circle (" +
                             std::to_string(options.minPoints) + " needed)");
    } else if (fit.coverageDeg < options.minCoverageDeg) {
        result.error = noRim("the edge points that agree on a circle span only " + fixedText(fit.coverageDeg) + " deg of it (" +
                             fixedText(options.minCoverageDeg) + " needed)");
    } else if (!(fit.centre.x >= 0 && fit.centre.y >= 0 && fit.centre.x <= mean.cols - 1 &&
                 fit.centre.y <= mean.rows - 1)) {
        result.error = noRim("the circle through the edge points is centred at (" + fixedText(fit.centre.x) + ", " +
                             fixedText(fit.centre.y) + "), outside the frame");
    } else if (fit.outerRadius <= 0) {
        result.error = noRim("the circle through the edge points is only " + fixedText(fit.rimRadius) + " px wide");
    }
    return result;
}

void applyRimFit(const RimFit& fit, cv::Size frameSize, GeometryOptions& geometry)
{
    geometry.imageWidth = frameSize.width;
    geometry.imageHeight = frameSize.height;
    geometry.centerX = fit.centre.x;
    geometry.centerY = fit.centre.y;
    geometry.outerRadius = fit.outerRadius;
}

}  // namespace omnitune
