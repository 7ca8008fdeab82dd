#include "filters/lic/LicParams.h"

#include "fieldviz/core/ParamRanges.h"

namespace fluidviz::lic {

void validateLicParams(const LicParams& p) {
  params::checkRanges(p);
  if (!(p.mask_speed < 1.0))
    throw ParamError("mask_speed", "must be < 1 (a fraction of the largest speed)");
}

}  // namespace fluidviz::lic
