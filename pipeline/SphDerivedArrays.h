#pragma once
// Particle arrays derived from the SPH solver's state for outputs: what the particle files,
// pictures and the resampled grids show besides velocity, density and pressure.
#include "fieldviz/particles/ParticleSet.h"

namespace fluidviz {

/// The set with "speed" = |velocity| added when it has "velocity", and with `components` also
/// "velocity_x" and "velocity_y" (what a picture may colour by).
particles::ParticleSet withDerived(particles::ParticleSet s, bool components = false);

/// What a snapshot file holds (withDerived, and what `fluidviz resample` needs to interpolate
/// without guessing, docs/scenes.md): "mass" (kg; kg/m in 2D, per unit depth) and
/// "smoothing_length" h (m) of every particle, the solver's constants.
particles::ParticleSet withSnapshotArrays(particles::ParticleSet s, double mass, double h);

}  // namespace fluidviz
