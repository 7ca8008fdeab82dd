#include "filters/resample/ResampleParams.h"

#include <sstream>

#include "fieldviz/core/ParamRanges.h"

namespace fluidviz::resample {

void validateResampleParams(const ParticleResampleParams& p) {
  params::checkRanges(p);
  if (p.dimension == 1)
    throw ParamError("dimension", "is 1; allowed 0 (automatic), 2 or 3");
}

std::vector<std::string> splitArrayList(const std::string& list) {
  std::vector<std::string> names;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto first = item.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    const auto last = item.find_last_not_of(" \t");
    names.push_back(item.substr(first, last - first + 1));
  }
  return names;
}

}  // namespace fluidviz::resample
