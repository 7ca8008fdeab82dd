#pragma once
// Particle arrays derived from the SPH solver's state for outputs: what the particle files,
// pictures and the resampled grids show besides velocity, density and pressure.
#include "fieldviz/particles/ParticleSet.h"

namespace fluidviz {

/// The set with "speed" = |velocity| added when it has "velocity", and with `components` also
/// "velocity_x" and "velocity_y" (what a picture may colour by).
particles::ParticleSet withDerived(particles::ParticleSet s, bool components = false);

}  // namespace fluidviz
