#pragma once
// Where the resampling grid goes and how fine it is, decided before any field is allocated.
#include <string>
#include <vector>

#include "fieldviz/core/Grid.h"
#include "filters/resample/ResampleParams.h"

namespace fluidviz::resample {

/// Axis-aligned box, m.
struct Bounds {
  Vec3 lower = Vec3::Zero();
  Vec3 upper = Vec3::Zero();
};

/// Bounding box of the positions. Throws std::invalid_argument naming the first particle with a
/// non-finite coordinate, or if there are no positions.
Bounds boundsOf(const std::vector<Vec3>& positions);

/// params.dimension when set; otherwise 2 if every particle has the same z, else 3.
int chooseDimension(const ParticleResampleParams& params, const Bounds& bounds);

/// Median distance from a particle to its nearest neighbour (over up to 4096 evenly strided
/// particles), m. Exact for lattices; for jittered lattices smaller than the lattice spacing.
/// Throws std::invalid_argument (saying to give particle_spacing) for fewer than 2 particles or
/// when most sampled particles coincide with another.
double medianNearestNeighbourDistance(const std::vector<Vec3>& positions, int dimension,
                                      const Bounds& bounds);

/// The grid: nodes `spacing` apart (params.spacing, else the longest padded extent over
/// params.dims - 1, else `particleSpacing`), covering `bounds` grown by `padding` on every side
/// of the first `dimension` axes, centred on the bounds. 2D grids have one node in z, at the
/// particles' z. `bytesPerNode` is the memory the output arrays take per node; a grid needing
/// more than params.max_memory_mb throws ParamError (key "spacing" or "dims") that states the
/// grid size and the memory it would need, before anything is allocated.
Grid planGrid(const Bounds& bounds, int dimension, double padding, double particleSpacing,
              const ParticleResampleParams& params, double bytesPerNode);

}  // namespace fluidviz::resample
