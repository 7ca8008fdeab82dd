#pragma once
// The SPH kernels of solvers/sph, chosen by name at run time. A std::variant rather than a
// virtual base: callers std::visit once per grid and run their inner loop on the concrete kernel
// type, so W(r) inlines (it is evaluated ~50 times per grid node).
#include <string>
#include <variant>

#include "fieldviz/particles/KernelCubicSpline.h"
#include "fieldviz/particles/KernelWendlandC2.h"
#include "fieldviz/particles/KernelsMuller2003.h"
#include "filters/resample/ResampleParams.h"

namespace fluidviz::resample {

using InterpolationKernel =
    std::variant<particles::KernelCubicSpline, particles::KernelWendlandC2, particles::KernelPoly6>;

/// The kernel `kind` with smoothing length h (m, > 0) in `dimension` (2 or 3).
InterpolationKernel makeInterpolationKernel(ResampleKernel kind, double h, int dimension);

/// Support radius of the kernel (2h for every kernel here), m.
inline double supportRadius(const InterpolationKernel& kernel) {
  return std::visit([](const auto& k) { return k.support(); }, kernel);
}

/// W(r) (1/m^d).
inline double evaluate(const InterpolationKernel& kernel, double r) {
  return std::visit([r](const auto& k) { return k.W(r); }, kernel);
}

}  // namespace fluidviz::resample
