#pragma once
// A set of particles with named per-particle arrays: what the SPH solver hands out (the fieldviz
// writers turn it into .vtp). Plain data, no VTK.
#include <string>
#include <vector>

#include "fieldviz/core/Grid.h"

namespace fluidviz::particles {

struct ParticleScalars {
  std::string name;
  std::vector<double> values;  ///< one per particle
};

struct ParticleVectors {
  std::string name;
  std::vector<Vec3> values;  ///< one per particle; 2D sets keep z = 0
};

struct ParticleSet {
  int dimension = 2;              ///< 2 or 3
  std::vector<Vec3> positions;    ///< m
  std::vector<ParticleScalars> scalars;
  std::vector<ParticleVectors> vectors;

  std::size_t size() const { return positions.size(); }
  const ParticleScalars* findScalar(const std::string& name) const {
    for (const auto& s : scalars)
      if (s.name == name) return &s;
    return nullptr;
  }
  const ParticleVectors* findVector(const std::string& name) const {
    for (const auto& v : vectors)
      if (v.name == name) return &v;
    return nullptr;
  }
};

}  // namespace fluidviz::particles
