#include "filters/topology/TopologyParams.h"

#include "fieldviz/core/ParamRanges.h"

namespace fluidviz::topology {

void validateTopologyParams(const TopologyParams& p) {
  params::checkRanges(p);
  try {
    streamlines::validateStreamlineParams(p.separatrix_integration);
  } catch (const ParamError& e) {
    throw ParamError("separatrix_integration." + e.key(), e.what());
  }
}

}  // namespace fluidviz::topology
