#pragma once
// Scene-facing parameters of the surface flow solver (issue 24; no scene uses them yet): the
// surface (a built-in icosphere or torus), the fluid (viscosity and its operator on a curved
// surface, the frame's rotation), the time stepping, and an initial vorticity of one spherical
// harmonic. Units are the scene's: lengths in m, times in s.
#include <array>

#include "fieldviz/core/Params.h"
#include "solvers/surface/VorticityStream.h"
#include "solvers/surface/mesh/TriangleMesh.h"

namespace fluidviz::surface {

enum class SurfaceShape { icosphere, torus };
constexpr std::array<Choice<SurfaceShape>, 2> paramChoices(SurfaceShape) {
  return {{{SurfaceShape::icosphere, "icosphere"}, {SurfaceShape::torus, "torus"}}};
}

// Units, ranges and meanings of the members: their describe() declarations below.
struct SurfaceParams {
  SurfaceShape shape = SurfaceShape::icosphere;
  double radius = 1.0;
  int subdivision_level = 4;
  double torus_major_radius = 1.0;
  double torus_minor_radius = 0.4;
  int torus_segments = 64;
  int torus_tube_segments = 32;
  double viscosity = 0.0;
  ViscousOperator viscous_operator = ViscousOperator::deformation;
  double rotation_rate = 0.0;
  MassLumping mass_lumping = MassLumping::mixed_voronoi;
  double time_step = 0.01;
  double end_time = 1.0;
  int harmonic_degree = 3;
  int harmonic_order = 2;
  double amplitude = 1.0;

  template <class V>
  static void describe(V& v) {
    v(&SurfaceParams::shape,
      {.key = "shape", .description = "built-in surface: icosphere (a subdivided icosahedron "
                                      "projected onto the sphere) or torus (about the z axis)"});
    v(&SurfaceParams::radius, {.key = "radius", .unit = "m", .description = "icosphere radius R",
                               .min = 0, .minExclusive = true});
    v(&SurfaceParams::subdivision_level,
      {.key = "subdivision_level",
       .description = "icosphere subdivisions L: 10 * 4^L + 2 vertices (4: 2562, 5: 10242)",
       .min = 0, .max = 7});
    v(&SurfaceParams::torus_major_radius,
      {.key = "torus_major_radius", .unit = "m",
       .description = "distance R from the z axis to the tube's centre line (above "
                      "torus_minor_radius)", .min = 0, .minExclusive = true});
    v(&SurfaceParams::torus_minor_radius,
      {.key = "torus_minor_radius", .unit = "m", .description = "tube radius r",
       .min = 0, .minExclusive = true});
    v(&SurfaceParams::torus_segments,
      {.key = "torus_segments", .description = "vertices around the z axis", .min = 3,
       .max = 4096});
    v(&SurfaceParams::torus_tube_segments,
      {.key = "torus_tube_segments", .description = "vertices around the tube", .min = 3,
       .max = 4096});
    v(&SurfaceParams::viscosity,
      {.key = "viscosity", .unit = "m^2/s", .description = "kinematic viscosity nu (0: Euler)",
       .min = 0});
    v(&SurfaceParams::viscous_operator,
      {.key = "viscous_operator",
       .description = "viscous term on the curved surface: deformation (nu (Delta_H u + 2 K u), "
                      "the Navier-Stokes stress; rigid rotation does not decay) or laplacian "
                      "(nu Delta omega, the Hodge Laplacian alone)"});
    v(&SurfaceParams::rotation_rate,
      {.key = "rotation_rate", .unit = "1/s",
       .description = "angular speed Omega of the frame about +z (Coriolis parameter 2 Omega "
                      "n.z; 0: inertial frame)"});
    v(&SurfaceParams::mass_lumping,
      {.key = "mass_lumping",
       .description = "vertex areas: barycentric (a third of each face) or mixed_voronoi "
                      "(Meyer et al. 2003)"});
    v(&SurfaceParams::time_step,
      {.key = "time_step", .unit = "s",
       .description = "time step; the implicit midpoint iteration needs about dt < edge "
                      "length / speed", .min = 0, .minExclusive = true});
    v(&SurfaceParams::end_time, {.key = "end_time", .unit = "s", .description = "simulated time",
                                 .min = 0, .minExclusive = true});
    v(&SurfaceParams::harmonic_degree,
      {.key = "harmonic_degree",
       .description = "degree l of the initial vorticity Y_l^m (icosphere)", .min = 1, .max = 32});
    v(&SurfaceParams::harmonic_order,
      {.key = "harmonic_order",
       .description = "order m of the initial vorticity Y_l^m, |m| <= l (m < 0: sin(|m| phi))",
       .min = -32, .max = 32});
    v(&SurfaceParams::amplitude,
      {.key = "amplitude", .unit = "1/s", .description = "largest initial vorticity"});
  }
};

/// Checks the ranges and the combinations (torus_major_radius above torus_minor_radius,
/// |harmonic_order| <= harmonic_degree). Throws ParamError naming the key.
void validateSurfaceParams(const SurfaceParams& p);

/// The built-in mesh the parameters describe (validated first).
TriangleMesh makeSurfaceMesh(const SurfaceParams& p);

/// The Gaussian curvature of the smooth built-in surface at the mesh's vertices: 1 / R^2 on the
/// sphere, cos v / (r (R + r cos v)) on the torus (v the angle around the tube).
Eigen::VectorXd builtInCurvature(const SurfaceParams& p, const TriangleMesh& mesh);

/// The solver settings of valid parameters, with the built-in surface's curvature.
VorticityStreamSettings vorticityStreamSettings(const SurfaceParams& p, const TriangleMesh& mesh);

}  // namespace fluidviz::surface
