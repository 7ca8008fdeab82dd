#include "filters/streamlines/StreamlineParams.h"

#include <sstream>

#include "fieldviz/core/ParamRanges.h"

namespace fluidviz::streamlines {

void validateStreamlineParams(const StreamlineParams& p) {
  params::checkRanges(p);
  if (p.integrator != Integrator::rk45) return;
  std::ostringstream s;
  s.precision(10);
  if (p.min_step > p.max_step) {
    s << "is " << p.min_step << " cells, larger than max_step = " << p.max_step;
    throw ParamError("min_step", s.str());
  }
  if (p.step < p.min_step || p.step > p.max_step) {
    s << "is " << p.step << " cells; with integrator rk45 it is the first step and must lie in "
      << "[min_step, max_step] = [" << p.min_step << ", " << p.max_step << "]";
    throw ParamError("step", s.str());
  }
}

}  // namespace fluidviz::streamlines
