#include "filters/resample/InterpolationKernel.h"

#include "fieldviz/core/Params.h"
#include "filters/resample/ResampleParams.h"

namespace fluidviz::resample {

InterpolationKernel makeInterpolationKernel(const std::string& name, double h, int dimension) {
  if (name == "cubic_spline") return particles::KernelCubicSpline(h, dimension);
  if (name == "wendland_c2") return particles::KernelWendlandC2(h, dimension);
  if (name == "poly6") return particles::KernelPoly6(h, dimension);
  std::string allowed;
  for (const std::string& n : kernelNames()) allowed += (allowed.empty() ? "" : ", ") + n;
  throw ParamError("kernel", "is \"" + name + "\", allowed one of {" + allowed + "}");
}

}  // namespace fluidviz::resample
