#pragma once
// One number per validated candidate from all the validation tests, so that among several
// valid candidates the most ball-like one is chosen. The thesis chooses by the best
// circularity, then the most votes; with several maxima per area (and OpenCV's circles
// joining) that lets a line corner with one more edge ray beat a ball that is better on every
// other test.
#include "core/BallCandidate.h"

namespace omnitune {

// 0..1: a weighted mean of circularity, the non-green and non-black shares, the share of rays
// that do not run on, how tightly the border hugs one radius, and the Hough support (votes
// relative to a full ring at the expected radius; for an OpenCV circle, how close its radius
// is to the expected one). Depends only on the candidate: the same candidate, the same score.
double candidateScore(const BallCandidate& c);

// Whether `a` is to be preferred to `b`: by score (byScore) or by the thesis' rule (the higher
// circularity, then the more votes). Ties keep the earlier candidate.
bool preferCandidate(const BallCandidate& a, const BallCandidate& b, bool byScore);

}  // namespace omnitune
