#include "calib/mask/MaskImport.h"

#include "core/RingCoverage.h"

#include <opencv2/imgproc.hpp>

#include <string>

namespace omnitune {

MaskImportResult importMask(const cv::Mat& image, MaskConvention convention, const GeometryOptions& geometry)
{
    MaskImportResult r;
    const cv::Size size(geometry.imageWidth, geometry.imageHeight);
    if (image.empty() || image.depth() != CV_8U || (image.channels() != 1 && image.channels() != 3 && image.channels() != 4)) {
        r.error = FitError{FitErrorKind::BadInput, "the mask image must be 8-bit grey or colour"};
        return r;
    }
    if (image.size() != size) {
        r.error = FitError{FitErrorKind::BadInput, "the mask image is " + std::to_string(image.cols) + "x" +
                                                       std::to_string(image.rows) + " but the camera's frames are " +
                                                       std::to_string(size.width) + "x" + std::to_string(size.height)};
        return r;
    }
    // Brightness as the largest channel (HSV's V), so saturated colours count as bright.
    cv::Mat value;
    if (image.channels() == 1) {
        value = image;
    } else {
        std::vector<cv::Mat> channels;
        cv::split(image, channels);
        value = cv::max(cv::max(channels[0], channels[1]), channels[2]);
    }
    const int type = convention == MaskConvention::BrightProcesses ? cv::THRESH_BINARY : cv::THRESH_BINARY_INV;
    cv::threshold(value, r.fit.mask, 127, 255, type);
    // One value everywhere marks nothing: a blank export, or the wrong file.
    const int processed = cv::countNonZero(r.fit.mask);
    if (processed == 0 || processed == r.fit.mask.rows * r.fit.mask.cols) {
        r.error = FitError{FitErrorKind::Uniform,
                           std::string("the mask image is all one value (") +
                               (processed == 0 ? "no pixel" : "every pixel") +
                               " would be processed): it tells robot from field nowhere; choose the mask file itself, "
                               "not a blank or a photo of the field"};
        r.fit = {};
        return r;
    }
    r.fit.processedShare = maskProcessedShare(r.fit.mask, geometry);
    return r;
}

}  // namespace omnitune
