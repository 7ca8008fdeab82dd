#pragma once
// Where streamlines start: explicit points, n points on a line segment, an nu x nv lattice on a
// parallelogram (a plane in 3D), an nx x ny x nz lattice filling a box, an nx x ny (x nz) lattice
// over the domain, or evenly spaced lines in 2D (Jobard & Lefer 1997, EvenlySpacedStreamlines.h).
#include <array>
#include <string>
#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/core/Params.h"
#include "filters/streamlines/EvenlySpacedStreamlines.h"
#include "filters/streamlines/Streamline.h"

namespace fluidviz::streamlines {

enum class SeedStrategy { points, line, plane, box, grid, evenly_spaced };
constexpr std::array<Choice<SeedStrategy>, 6> paramChoices(SeedStrategy) {
  return {{{SeedStrategy::points, "points"},
           {SeedStrategy::line, "line"},
           {SeedStrategy::plane, "plane"},
           {SeedStrategy::box, "box"},
           {SeedStrategy::grid, "grid"},
           {SeedStrategy::evenly_spaced, "evenly_spaced"}}};
}

struct SeedPoint {
  std::array<double, 3> position{0.0, 0.0, 0.0};  ///< m, world coordinates (z ignored in 2D)

  template <class V>
  static void describe(V& v) {
    v(&SeedPoint::position,
      {.key = "position", .unit = "m", .description = "seed position [x, y, z]", .required = true});
  }
};

struct SeedingParams {
  /// points: the listed `points`; line: `line_count` seeds from line_start to line_end;
  /// grid: grid_counts seeds at the cell centres of a lattice over the domain;
  /// evenly_spaced: 2D evenly spaced lines (`evenly_spaced`).
  SeedStrategy strategy = SeedStrategy::grid;
  std::vector<SeedPoint> points;                    ///< strategy points: the seeds, >= 1
  std::array<double, 3> line_start{0.0, 0.0, 0.0};  ///< m, strategy line: first seed
  std::array<double, 3> line_end{0.0, 0.0, 0.0};    ///< m, strategy line: last seed
  int line_count = 10;                              ///< strategy line: seeds, [1, 1e6]
  std::array<double, 3> plane_origin{0.0, 0.0, 0.0};  ///< m, strategy plane: corner seed
  std::array<double, 3> plane_u{1.0, 0.0, 0.0};       ///< m, strategy plane: first edge
  std::array<double, 3> plane_v{0.0, 1.0, 0.0};       ///< m, strategy plane: second edge
  std::array<double, 2> plane_counts{10, 10};         ///< strategy plane: seeds along u, v
  std::array<double, 3> box_min{0.0, 0.0, 0.0};       ///< m, strategy box: lower corner
  std::array<double, 3> box_max{1.0, 1.0, 1.0};       ///< m, strategy box: upper corner
  std::array<double, 3> box_counts{5, 5, 5};          ///< strategy box: seeds along x, y, z
  std::array<double, 3> grid_counts{10, 10, 1};     ///< strategy grid: seeds along x, y, z, each
                                                    ///< a whole number in [1, 1e4]
  EvenlySpacedParams evenly_spaced;                 ///< strategy evenly_spaced

  template <class V>
  static void describe(V& v) {
    v(&SeedingParams::strategy,
      {.key = "strategy",
       .description = "points: listed seeds; line: seeds on a segment; plane: lattice on a "
                      "parallelogram; box: lattice filling a box; grid: lattice over the "
                      "domain; evenly_spaced: 2D lines at even spacing (Jobard & Lefer 1997)"});
    v(&SeedingParams::points, {.key = "points", .description = "seeds of strategy points"});
    v(&SeedingParams::line_start,
      {.key = "line_start", .unit = "m", .description = "strategy line: first seed [x, y, z]"});
    v(&SeedingParams::line_end,
      {.key = "line_end", .unit = "m", .description = "strategy line: last seed [x, y, z]"});
    v(&SeedingParams::line_count, {.key = "line_count",
                                   .description = "strategy line: number of seeds (evenly spaced, "
                                                  "ends included; 1 = the midpoint)",
                                   .min = 1,
                                   .max = 1e6});
    v(&SeedingParams::plane_origin,
      {.key = "plane_origin", .unit = "m", .description = "strategy plane: corner seed [x, y, z]"});
    v(&SeedingParams::plane_u, {.key = "plane_u",
                                .unit = "m",
                                .description = "strategy plane: edge from the corner to the "
                                               "last seed along u [x, y, z]"});
    v(&SeedingParams::plane_v, {.key = "plane_v",
                                .unit = "m",
                                .description = "strategy plane: edge from the corner to the "
                                               "last seed along v [x, y, z]"});
    v(&SeedingParams::plane_counts,
      {.key = "plane_counts",
       .description = "strategy plane: seeds along u and v, whole numbers (edges included; "
                      "1 = the edge's midpoint)",
       .min = 1,
       .max = 1e4});
    v(&SeedingParams::box_min,
      {.key = "box_min", .unit = "m", .description = "strategy box: lower corner [x, y, z]"});
    v(&SeedingParams::box_max,
      {.key = "box_max", .unit = "m", .description = "strategy box: upper corner [x, y, z]"});
    v(&SeedingParams::box_counts,
      {.key = "box_counts",
       .description = "strategy box: seeds along x, y, z, whole numbers (faces included; "
                      "1 = the midpoint)",
       .min = 1,
       .max = 1e4});
    v(&SeedingParams::grid_counts,
      {.key = "grid_counts",
       .description = "strategy grid: seeds along x, y, z at the cell centres of a lattice over "
                      "the domain (z count must be 1 for a 2D field)",
       .min = 1,
       .max = 1e4});
    v(&SeedingParams::evenly_spaced,
      {.key = "evenly_spaced", .description = "strategy evenly_spaced: line spacing"});
  }
};

/// n seeds from a to b inclusive (n == 1: the midpoint). Throws std::invalid_argument if n < 1.
std::vector<Vec3> seedLine(const Vec3& a, const Vec3& b, int n);

/// nu * nv seeds origin + u i/(nu-1) + v j/(nv-1) (edges included; a count of 1 puts the seeds
/// at the middle of that edge), i fastest. Throws std::invalid_argument if a count < 1.
std::vector<Vec3> seedPlane(const Vec3& origin, const Vec3& u, const Vec3& v, int nu, int nv);

/// nx * ny * nz seeds at the centres of an nx x ny x nz partition of the grid's bounding box,
/// x fastest. For a 2D grid nz must be 1 and seeds lie in its plane. Throws std::invalid_argument.
std::vector<Vec3> seedGrid(const Grid& grid, int nx, int ny, int nz = 1);

/// The seeds of strategy points, line, plane, box or grid (ParamError for evenly_spaced, bad counts or an
/// empty list of points).
std::vector<Vec3> generateSeeds(const Grid& grid, const SeedingParams& seeding);

/// Lines for any strategy: evenly_spaced runs Jobard & Lefer, the others trace every seed
/// (traceStreamlines, in parallel). Seeds outside the grid give empty lines (domain_exit).
std::vector<Streamline> traceSeeded(const VectorField& field, const SeedingParams& seeding,
                                    const StreamlineParams& integration);

}  // namespace fluidviz::streamlines
