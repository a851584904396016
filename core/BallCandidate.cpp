#include "core/BallCandidate.h"

namespace omnitune {

std::string_view candidateSourceName(CandidateSource s)
{
    switch (s) {
    case CandidateSource::SpecificHough: return "specific";
    case CandidateSource::OpenCvHough: return "opencv";
    case CandidateSource::BlobSeed: return "blob";
    }
    return "?";
}

std::string_view rejectReasonName(RejectReason r)
{
    switch (r) {
    case RejectReason::None: return "accepted";
    case RejectReason::OutsideArea: return "outside processed area";
    case RejectReason::RadiusTooLarge: return "radius too large";
    case RejectReason::TooSmall: return "too far to validate";
    case RejectReason::NonGreen: return "non-green";
    case RejectReason::NonBlack: return "non-black";
    case RejectReason::Circularity: return "circularity";
    case RejectReason::RunsOn: return "runs on";
    case RejectReason::LineJunction: return "line junction";
    case RejectReason::LineBlob: return "line blob";
    case RejectReason::NotChosen: return "valid, not chosen";
    }
    return "?";
}

}  // namespace omnitune
