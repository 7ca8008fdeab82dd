// taylor_green_core: the decaying Taylor-Green vortex (Taylor & Green 1937) run with fluidviz's
// LBM solver and analysed with its topology filter, through the installed package's VTK-free
// targets only. Checks, and exits 1 if one fails:
//   - max |u| over the nodes at t = 0.5 s against the exact solution's at the same nodes,
//     U0 exp(-2 nu k^2 t) |(sin kx cos ky, -cos kx sin ky)|, k = 2 pi / L, within 1%;
//   - the critical points of the final velocity: the four vortex centres at (0.25 | 0.75,
//     0.25 | 0.75) m and the saddle at (0.5, 0.5) m, each within a tenth of a cell.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "fieldviz/core/BuildInfo.h"
#include "fieldviz/scene/ParamVisitors.h"
#include "filters/topology/VectorFieldTopology.h"
#include "solvers/lbm/LbmSolver.h"

namespace {

// The scene's lbm section, read through the same parameter declarations as a scene file.
fluidviz::lbm::LbmParams taylorGreen() {
  const auto j = fluidviz::scene::json::parse(R"({
    "collision": "trt", "domain_size": [1.0, 1.0], "resolution": 32, "reynolds": 100,
    "lattice_velocity": 0.05, "initial_flow": "taylor_green", "initial_speed": 1.0,
    "end_time": 0.5,
    "walls": {"x_min": {"type": "periodic"}, "x_max": {"type": "periodic"},
              "y_min": {"type": "periodic"}, "y_max": {"type": "periodic"}}})");
  fluidviz::lbm::LbmParams p;
  fluidviz::scene::readParams(j, p, "lbm");
  return p;
}

double maxSpeed(const fluidviz::VectorField& v) {
  double m = 0;
  for (const auto& u : v.values) m = std::max(m, u.norm());
  return m;
}

// max over the grid's nodes of |(sin kx cos ky, -cos kx sin ky)|: the nodes miss the peaks.
double maxShapeAtNodes(const fluidviz::Grid& g, double k) {
  double m = 0;
  for (int j = 0; j < g.dims[1]; ++j)
    for (int i = 0; i < g.dims[0]; ++i) {
      const double x = g.origin[0] + i * g.spacing[0], y = g.origin[1] + j * g.spacing[1];
      m = std::max(m, std::hypot(std::sin(k * x) * std::cos(k * y),
                                 std::cos(k * x) * std::sin(k * y)));
    }
  return m;
}

}  // namespace

int main() {
  using namespace fluidviz;
  std::printf("fluidviz %s\n", buildInfo().describe().c_str());
  const lbm::LbmParams params = taylorGreen();
  std::unique_ptr<lbm::LbmSolver> solver = lbm::createLbmSolver(params);
  std::vector<double> density;
  std::vector<Vec3> velocity;
  lbm::initialFlowFields(params, solver->units(), solver->grid(), density, velocity);
  solver->initialise(density, velocity);
  solver->run();
  const FieldSet fields = solver->fields();
  const VectorField& u = *fields.findVector("velocity");

  int failures = 0;
  const double nu = solver->units().viscosity;  // U0 L / Re
  const double k = 2 * std::numbers::pi / params.domain_size[0];
  const double exact = params.initial_speed * std::exp(-2 * nu * k * k * solver->time()) *
                       maxShapeAtNodes(u.grid, k);
  const double measured = maxSpeed(u);
  const double error = std::abs(measured / exact - 1);
  std::printf("t = %.4f s: max |u| = %.5f m/s, exact %.5f m/s (error %.2f%%, allowed 1%%)\n",
              solver->time(), measured, exact, 100 * error);
  failures += error > 0.01;

  const std::vector<topology::CriticalPoint> points =
      topology::findCriticalPoints(u, topology::TopologyParams{});
  const double cell = u.grid.spacing[0];
  const auto found = [&](double x, double y, topology::CriticalPointType type) {
    for (const auto& p : points)
      if (p.type == type && std::hypot(p.position.x() - x, p.position.y() - y) < 0.1 * cell)
        return true;
    std::printf("missing: %s at (%.2f, %.2f)\n", topology::toString(type).c_str(), x, y);
    return false;
  };
  for (double x : {0.25, 0.75})
    for (double y : {0.25, 0.75}) failures += !found(x, y, topology::CriticalPointType::Centre);
  failures += !found(0.5, 0.5, topology::CriticalPointType::Saddle);
  std::printf("%zu critical points (expected 5: 4 centres, 1 saddle)\n", points.size());
  failures += points.size() != 5;
  std::printf(failures == 0 ? "all checks passed\n" : "%d checks failed\n", failures);
  return failures == 0 ? 0 : 1;
}
