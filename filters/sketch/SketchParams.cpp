#include "filters/sketch/SketchParams.h"

#include "fieldviz/core/ParamRanges.h"

namespace fluidviz::sketch {

void validateSketchParams(const SketchParams& p) { params::checkRanges(p); }
void validateGvfParams(const GvfParams& p) { params::checkRanges(p); }

}  // namespace fluidviz::sketch
