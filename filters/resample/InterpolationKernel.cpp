#include "filters/resample/InterpolationKernel.h"

namespace fluidviz::resample {

InterpolationKernel makeInterpolationKernel(ResampleKernel kind, double h, int dimension) {
  switch (kind) {
    case ResampleKernel::cubic_spline: return particles::KernelCubicSpline(h, dimension);
    case ResampleKernel::wendland_c2: return particles::KernelWendlandC2(h, dimension);
    case ResampleKernel::poly6: return particles::KernelPoly6(h, dimension);
  }
  throw ParamError("kernel", "is not a kernel (" + std::to_string(static_cast<int>(kind)) + ")");
}

}  // namespace fluidviz::resample
