#pragma once
// The parameters of the FluidvizStreamlines proxy: where lines start and how they are
// integrated, under the keys of a scene's output.streamlines[] entry (seeding.*, integration.*),
// so that property SeedingGridCounts is scene key output.streamlines[].seeding.grid_counts and
// `fluidviz streamlines` flag --seeds grid:nx,ny.
#include "filters/streamlines/Seeding.h"
#include "filters/streamlines/StreamlineParams.h"

namespace fluidviz::paraview {

struct StreamlineProxyParams {
  streamlines::SeedingParams seeding;
  streamlines::StreamlineParams integration;

  template <class V>
  static void describe(V& v) {
    v(&StreamlineProxyParams::seeding, {.key = "seeding", .description = "where lines start"});
    v(&StreamlineProxyParams::integration,
      {.key = "integration", .description = "integrator parameters (lengths in cells)"});
  }
};

}  // namespace fluidviz::paraview
