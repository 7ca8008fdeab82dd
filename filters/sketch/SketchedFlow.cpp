#include "filters/sketch/SketchedFlow.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "filters/sketch/grid/DivergenceFree.h"
#include "filters/sketch/grid/PlaneGrid.h"
#include "filters/sketch/grid/ProjectStrokes.h"
#include "filters/sketch/gvf/GradientVectorFlow.h"

namespace fluidviz::sketch {

namespace {
/// b per node (SketchParams.h, GvfWeight), divided by its largest value.
std::vector<double> gvfWeightOf(const ProjectedStrokes& p, GvfWeight rule) {
  std::vector<double> b(p.coverage.size());
  double largest = 0.0;
  for (std::size_t k = 0; k < b.size(); ++k) {
    const double c = p.coverage[k];
    const double speed = rule == GvfWeight::speed ? p.velocity.values[k].norm() : 1.0;
    b[k] = c * c * speed * speed;
    largest = std::max(largest, b[k]);
  }
  if (largest > 0.0)
    for (double& x : b) x /= largest;
  return b;
}
}  // namespace

SketchedFlow sketchFlow(const std::vector<Stroke>& strokes, const Grid& grid,
                        const SketchParams& params) {
  validateSketchParams(params);
  const PlaneGrid g = PlaneGrid::of(grid, params.gvf.boundary_x, params.gvf.boundary_y);
  const double cell = std::min(g.hx, g.hy);
  SketchedFlow out;
  for (std::size_t k = 0; k < strokes.size(); ++k) {
    try {
      out.strokes.push_back(smoothStroke(resampleStroke(strokes[k], params.resample_spacing * cell),
                                         params.stroke_smoothing * cell));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("stroke " + std::to_string(k + 1) + ": " + e.what());
    }
  }
  ProjectedStrokes projected =
      projectStrokes(out.strokes, grid, g, params.sigma, "projected_velocity");
  out.weight = gvfWeightOf(projected, params.weight);
  out.projected = std::move(projected.velocity);
  GvfResult gvf = gradientVectorFlow(out.projected, out.weight, params.gvf);
  out.gvfIterations = gvf.iterations;
  out.gvfResidual = gvf.residual;
  out.velocity = std::move(gvf.field);
  out.velocity.name = "velocity";
  if (params.divergence_free) {
    DivergenceFreeResult d = projectDivergenceFree(out.velocity, g);
    out.divergenceBefore = d.divergenceBefore;
    out.divergenceAfter = d.divergenceAfter;
    out.velocity = std::move(d.field);
  }
  return out;
}

}  // namespace fluidviz::sketch
