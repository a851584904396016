#pragma once
// How much of the processed ring (between geometry.inner_radius and outer_radius around the
// robot centre) lies inside the image. A mirror slightly cut by the frame is normal (the rim
// of a 480-high image often is); a ring mostly or wholly off the image is a wrong centre or
// radius, which checkConfig refuses (none of it inside) or omnitune-config --check warns about.
#include "core/Geometry.h"

namespace omnitune {

// Share 0..1 of the ring's area inside the image rectangle [0, width] x [0, height]; 0 for a
// ring of no area.
double ringShareInImage(const GeometryOptions& geometry);

// Share 0..1 of the ring's pixels inside the image that `mask` (CV_8UC1, non-zero = process,
// the geometry's image size) lets through; 1 for an empty mask.
double maskProcessedShare(const cv::Mat& mask, const GeometryOptions& geometry);

// Below this share --check warns that the used ring is mostly off the image, and the config
// loader that a mask leaves most of the ring out (a mask of the opposite convention).
inline constexpr double kRingMostlyOffImageShare = 0.5;

}  // namespace omnitune
