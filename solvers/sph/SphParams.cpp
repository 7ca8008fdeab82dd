#include "solvers/sph/SphParams.h"

#include "fieldviz/core/ParamRanges.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>

namespace fluidviz::sph {

namespace {

const char* axisName(int a) { return a == 0 ? "x" : (a == 1 ? "y" : "z"); }

std::array<const SphSide*, 2> sides(const SphWallsParams& w, int axis) {
  if (axis == 0) return {&w.x_min, &w.x_max};
  if (axis == 1) return {&w.y_min, &w.y_max};
  return {&w.z_min, &w.z_max};
}

void checkDomainAndWalls(const SphParams& p) {
  const double twoH = 2.0 * p.smoothing_length_ratio * p.particle_spacing;
  for (int a = 0; a < p.dimension; ++a) {
    const double length = p.domain_upper[a] - p.domain_lower[a];
    if (!(length > 0))
      throw ParamError(std::string("domain_upper[") + std::to_string(a) + "]",
                       "is " + formatNumber(p.domain_upper[a]) + " m, not above domain_lower[" +
                           std::to_string(a) + "] = " + formatNumber(p.domain_lower[a]) + " m");
    const auto [lo, hi] = sides(p.walls, a);
    const std::string loKey = std::string(axisName(a)) + "_min",
                      hiKey = std::string(axisName(a)) + "_max";
    if ((*lo == SphSide::periodic) != (*hi == SphSide::periodic))
      throw ParamError("walls." + (*lo == SphSide::periodic ? hiKey : loKey),
                       "is not periodic but walls." + (*lo == SphSide::periodic ? loKey : hiKey) +
                           " is; periodic sides come in pairs: make both periodic or neither");
    if (*lo != SphSide::periodic) continue;
    const double cells = length / p.particle_spacing;
    if (std::abs(cells - std::round(cells)) > 1e-6 * cells)
      throw ParamError(std::string("domain_upper[") + std::to_string(a) + "]",
                       "gives a periodic length " + formatNumber(length) +
                           " m that is not a whole number of particle spacings (" + formatNumber(cells) +
                           "); adjust the domain or particle_spacing");
    if (length < 3.0 * twoH)
      throw ParamError(std::string("domain_upper[") + std::to_string(a) + "]",
                       "gives a periodic length " + formatNumber(length) +
                           " m shorter than 3 kernel supports (" + formatNumber(3.0 * twoH) +
                           " m); lengthen the domain along " + axisName(a));
  }
}

void checkBox(const SphParams& p, const SphBoxParams& b, const std::string& key, bool inside) {
  for (int a = 0; a < p.dimension; ++a) {
    if (!(b.upper[a] > b.lower[a]))
      throw ParamError(key + ".upper", std::string("is not above ") + key + ".lower along " +
                                           axisName(a) + " (" + formatNumber(b.upper[a]) + " <= " +
                                           formatNumber(b.lower[a]) + " m)");
    const double tol = 1e-9 * (p.domain_upper[a] - p.domain_lower[a]);
    if (inside && (b.lower[a] < p.domain_lower[a] - tol || b.upper[a] > p.domain_upper[a] + tol))
      throw ParamError(key, std::string("reaches outside the domain along ") + axisName(a) +
                                " ([" + formatNumber(b.lower[a]) + ", " + formatNumber(b.upper[a]) +
                                "] m, domain [" + formatNumber(p.domain_lower[a]) + ", " +
                                formatNumber(p.domain_upper[a]) + "] m); move or shrink it");
  }
}

void checkBlocks(const SphParams& p) {
  if (p.fluid_blocks.empty())
    throw ParamError("fluid_blocks", "is empty; give at least one box of fluid");
  for (std::size_t i = 0; i < p.fluid_blocks.size(); ++i) {
    const std::string key = "fluid_blocks[" + std::to_string(i) + "]";
    const SphBoxParams& b = p.fluid_blocks[i];
    checkBox(p, b, key, true);
    for (int a = 0; a < p.dimension; ++a)
      if (b.upper[a] - b.lower[a] < p.particle_spacing)
        throw ParamError(key, std::string("is thinner than one particle spacing along ") +
                                  axisName(a) + "; enlarge it or reduce particle_spacing");
  }
  for (std::size_t i = 0; i < p.obstacles.size(); ++i)
    checkBox(p, p.obstacles[i], "obstacles[" + std::to_string(i) + "]", false);
}

void checkRollers(const SphParams& p) {
  for (std::size_t i = 0; i < p.rollers.size(); ++i) {
    const SphRollerParams& r = p.rollers[i];
    const std::string key = "rollers[" + std::to_string(i) + "]";
    if (r.radius < 2.0 * p.particle_spacing)
      throw ParamError(key + ".radius", "is " + formatNumber(r.radius) +
                                            " m, below 2 particle spacings (" +
                                            formatNumber(2.0 * p.particle_spacing) + " m)");
    for (int a = 0; a < 2; ++a)
      if (r.center[a] - r.radius < p.domain_lower[a] || r.center[a] + r.radius > p.domain_upper[a])
        throw ParamError(key, "does not lie inside the domain along " + std::string(axisName(a)) +
                                  "; move its centre or reduce its radius");
    for (std::size_t k = 0; k < i; ++k) {
      const SphRollerParams& o = p.rollers[k];
      if (std::hypot(r.center[0] - o.center[0], r.center[1] - o.center[1]) < r.radius + o.radius)
        throw ParamError(key, "overlaps rollers[" + std::to_string(k) +
                                  "]; move the centres apart or reduce the radii");
    }
  }
}

void checkModelTerms(const SphParams& p) {
  auto onlyFor = [&](double value, const char* key, SphModel model) {
    if (value != 0.0)
      throw ParamError(key, "is " + formatNumber(value) + " but applies to model " + choiceName(model) +
                                " only; set it to 0 or choose model " + choiceName(model));
  };
  if (p.model == SphModel::muller2003) {
    onlyFor(p.alpha, "alpha", SphModel::weakly_compressible);
    onlyFor(p.beta, "beta", SphModel::weakly_compressible);
    onlyFor(p.xsph_epsilon, "xsph_epsilon", SphModel::weakly_compressible);
    onlyFor(p.cohesion, "cohesion", SphModel::weakly_compressible);
  } else {
    onlyFor(p.surface_tension, "surface_tension", SphModel::muller2003);
  }
  if (!(p.boundary_exponents[0] > p.boundary_exponents[1]))
    throw ParamError("boundary_exponents", "must have n1 > n2 (repulsive at short range); got [" +
                                               formatNumber(p.boundary_exponents[0]) + ", " +
                                               formatNumber(p.boundary_exponents[1]) + "]");
}

}  // namespace

void validateSphParams(const SphParams& p) {
  params::checkRanges(p);
  checkDomainAndWalls(p);
  checkBlocks(p);
  checkRollers(p);
  checkModelTerms(p);
}

double boundaryStrength(const SphParams& p) {
  return p.boundary_strength > 0.0 ? p.boundary_strength
                                   : p.speed_of_sound * p.speed_of_sound / 40.0;
}

double boundaryRange(const SphParams& p) {
  const bool wallPressure = p.model == SphModel::muller2003 || p.wall_pressure == WallPressure::adami2012;
  const double ratio = p.boundary_range > 0.0 ? p.boundary_range : (wallPressure ? 0.7 : 1.0);
  return ratio * p.particle_spacing;
}

}  // namespace fluidviz::sph
