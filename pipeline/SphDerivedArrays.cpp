#include "pipeline/SphDerivedArrays.h"

#include <utility>

#include "filters/resample/ParticleResampler.h"

namespace fluidviz {

particles::ParticleSet withDerived(particles::ParticleSet s, bool components) {
  const particles::ParticleVectors* v = s.findVector("velocity");
  if (!v) return s;
  particles::ParticleScalars speed{"speed", {}}, vx{"velocity_x", {}}, vy{"velocity_y", {}};
  for (const Vec3& u : v->values) {
    speed.values.push_back(u.norm());
    if (components) {
      vx.values.push_back(u[0]);
      vy.values.push_back(u[1]);
    }
  }
  s.scalars.push_back(std::move(speed));
  if (components) {
    s.scalars.push_back(std::move(vx));
    s.scalars.push_back(std::move(vy));
  }
  return s;
}

particles::ParticleSet withSnapshotArrays(particles::ParticleSet s, double mass, double h) {
  s = withDerived(std::move(s));
  s.scalars.push_back({resample::ParticleResampleParams{}.mass_array,
                       std::vector<double>(s.size(), mass)});
  s.scalars.push_back({resample::kSmoothingLengthArray, std::vector<double>(s.size(), h)});
  return s;
}

}  // namespace fluidviz
