#include "fieldviz/resample/InterpolationKernel.h"

#include "fieldviz/core/Params.h"
#include "fieldviz/resample/ResampleParams.h"

namespace fluidviz::resample {

InterpolationKernel makeInterpolationKernel(const std::string& name, double h, int dimension) {
  if (name == "cubic_spline") return sph::KernelCubicSpline(h, dimension);
  if (name == "wendland_c2") return sph::KernelWendlandC2(h, dimension);
  if (name == "poly6") return sph::KernelPoly6(h, dimension);
  std::string allowed;
  for (const std::string& n : kernelNames()) allowed += (allowed.empty() ? "" : ", ") + n;
  throw ParamError("kernel", "is \"" + name + "\", allowed one of {" + allowed + "}");
}

}  // namespace fluidviz::resample
