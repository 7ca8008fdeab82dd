#include "filters/lic/LicParams.h"

#include "fieldviz/core/ParamRanges.h"

namespace fluidviz::lic {

void validateLicParams(const LicParams& p) {
  params::checkRanges(p);
}

}  // namespace fluidviz::lic
