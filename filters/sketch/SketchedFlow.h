#pragma once
// Sketched flows (Judice & Giraldi 2012, "Sketching fluid flows: combining sketch-based
// techniques and GVF for Lattice-Boltzmann initialization"): strokes -> resampled, smoothed
// strokes -> projected velocities v0 (Gaussian normalised convolution) -> Gradient Vector Flow
// over the grid -> optionally the nearest divergence-free field.
#include <vector>

#include "fieldviz/core/Field.h"
#include "filters/sketch/SketchParams.h"
#include "filters/sketch/strokes/Stroke.h"

namespace fluidviz::sketch {

struct SketchedFlow {
  std::vector<Stroke> strokes;  ///< as projected: resampled and smoothed
  VectorField projected;        ///< v0: the drawn velocity around the strokes
  std::vector<double> weight;   ///< GVF's data weight b per node, in [0, 1]
  VectorField velocity;         ///< the GVF field (divergence-free if asked)
  int gvfIterations = 0;
  double gvfResidual = 0.0;
  double divergenceBefore = 0.0;  ///< max |div| of the GVF field (only with divergence_free)
  double divergenceAfter = 0.0;
};

/// Strokes with no two distinct points are refused (std::invalid_argument naming the stroke).
SketchedFlow sketchFlow(const std::vector<Stroke>& strokes, const Grid& grid,
                        const SketchParams& params);

}  // namespace fluidviz::sketch
