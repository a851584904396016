#include "core/PrefilterRefusals.h"

namespace omnitune {

std::vector<bool> prefilterRefusals(const PipelineResult& result)
{
    std::vector<bool> refused(result.candidates.size(), false);
    int left = result.hough.prefilterListed + result.hough.prefilterUnlisted;
    for (std::size_t i = result.candidates.size(); i-- > 0 && left > 0;) {
        if (result.candidates[i].source == CandidateSource::OpenCvHough) continue;
        refused[i] = true;
        --left;
    }
    return refused;
}

}  // namespace omnitune
