#include "solvers/surface/SurfaceParams.h"

#include <cmath>
#include <cstdlib>
#include <string>

#include "fieldviz/core/ParamRanges.h"

namespace fluidviz::surface {

void validateSurfaceParams(const SurfaceParams& p) {
  params::checkRanges(p);
  if (p.shape == SurfaceShape::torus && !(p.torus_major_radius > p.torus_minor_radius))
    throw ParamError("torus_major_radius",
                     "is " + formatNumber(p.torus_major_radius) + " m, not above torus_minor_radius " +
                         formatNumber(p.torus_minor_radius) +
                         " m: the tube would cross the z axis (a self-intersecting surface)");
  if (std::abs(p.harmonic_order) > p.harmonic_degree)
    throw ParamError("harmonic_order", "is " + std::to_string(p.harmonic_order) +
                                           "; allowed |m| <= harmonic_degree (" +
                                           std::to_string(p.harmonic_degree) + ")");
}

TriangleMesh makeSurfaceMesh(const SurfaceParams& p) {
  validateSurfaceParams(p);
  return p.shape == SurfaceShape::icosphere
             ? makeIcosphere(p.radius, p.subdivision_level)
             : makeTorus(p.torus_major_radius, p.torus_minor_radius, p.torus_segments,
                         p.torus_tube_segments);
}

Eigen::VectorXd builtInCurvature(const SurfaceParams& p, const TriangleMesh& mesh) {
  Eigen::VectorXd k(mesh.vertexCount());
  for (int i = 0; i < mesh.vertexCount(); ++i) {
    const Eigen::Vector3d& x = mesh.vertices[i];
    if (p.shape == SurfaceShape::icosphere) {
      k[i] = 1.0 / (p.radius * p.radius);
    } else {
      // Distance from the z axis rho = R + r cos v.
      const double rho = std::hypot(x.x(), x.y());
      const double cosV = (rho - p.torus_major_radius) / p.torus_minor_radius;
      k[i] = cosV / (p.torus_minor_radius * rho);
    }
  }
  return k;
}

VorticityStreamSettings vorticityStreamSettings(const SurfaceParams& p, const TriangleMesh& mesh) {
  VorticityStreamSettings s;
  s.gaussianCurvature = builtInCurvature(p, mesh);
  s.viscosity = p.viscosity;
  s.timeStep = p.time_step;
  s.rotationRate = p.rotation_rate;
  s.viscousOperator = p.viscous_operator;
  s.lumping = p.mass_lumping;
  return s;
}

}  // namespace fluidviz::surface
