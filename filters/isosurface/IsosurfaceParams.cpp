#include "filters/isosurface/IsosurfaceParams.h"

#include <cmath>

#include "fieldviz/core/ParamRanges.h"

namespace fluidviz::isosurface {

void validateIsosurfaceParams(const IsosurfaceParams& p) {
  params::checkRanges(p);
  if (p.array.empty()) throw ParamError("array", "is empty; name the point array to contour");
  if (!std::isfinite(p.value)) throw ParamError("value", "must be a finite number");
}

}  // namespace fluidviz::isosurface
