#include "core/Algorithm.h"

namespace omnitune {

std::string_view algorithmName(Algorithm a)
{
    switch (a) {
    case Algorithm::Specific: return "specific";
    case Algorithm::OpenCv: return "opencv";
    case Algorithm::Combined: return "combined";
    }
    return "specific";
}

std::optional<Algorithm> parseAlgorithm(std::string_view name)
{
    for (Algorithm a : {Algorithm::Specific, Algorithm::OpenCv, Algorithm::Combined})
        if (algorithmName(a) == name) return a;
    return std::nullopt;
}

}  // namespace omnitune
