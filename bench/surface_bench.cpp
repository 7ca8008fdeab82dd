// Surface flow solver (solvers/surface): the cost of one VorticityStream step (implicit midpoint
// with its fixed-point iterations: each a Poisson back-solve, a Galerkin Jacobian and a
// Crank-Nicolson back-solve) and of its parts, as ratios to a plain sparse matrix-vector product
// S x of the same size (the cotangent stiffness, about 7 entries per row), measured in the same
// run. A Rossby-Haurwitz wave on a turning sphere, dt = 0.02, viscous (nu = 1e-4) and inviscid
// (the Crank-Nicolson back-solve is then a division by M).
// Usage: surface_bench [levels...]   (default: 4 5 6)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "solvers/surface/VorticityStream.h"
#include "solvers/surface/validation/SphericalHarmonics.h"

using namespace fluidviz::surface;

namespace {

/// Best of `repeats` wall times of f, in seconds.
template <class F>
double bestSeconds(int repeats, F&& f) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

void benchLevel(int level, double viscosity) {
  const TriangleMesh mesh = makeIcosphere(1.0, level);
  VorticityStreamSettings settings;
  settings.timeStep = 0.02;
  settings.rotationRate = 1.0;
  settings.viscosity = viscosity;
  const auto t0 = std::chrono::steady_clock::now();
  VorticityStream flow(mesh, settings);
  const double setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  flow.setVorticity(0.2 * sampleSphericalHarmonic(mesh, 3, 2));

  const SparseMatrix s = cotanStiffness(mesh);
  Eigen::VectorXd x = flow.vorticity(), y(x.size());
  const int products = 200;
  const double spmv = bestSeconds(5, [&] {
                        for (int i = 0; i < products; ++i) {
                          y.noalias() = s * x;
                          x[i % x.size()] += 1e-300 * y[0];  // keep the products alive
                        }
                      }) / products;
  const double poisson = bestSeconds(20, [&] { y = flow.streamFunctionOf(flow.vorticity()); });
  const double jacobian =
      bestSeconds(20, [&] { y = flow.galerkinJacobian(flow.streamFunction(), flow.vorticity()); });
  const int steps = 10;
  const double step = bestSeconds(3, [&] {
                        for (int i = 0; i < steps; ++i) flow.step();
                      }) / steps;
  std::printf("level %d, %d vertices, %lld nonzeros, nu = %g: setup (2 factorisations) %.2f ms\n",
              level, mesh.vertexCount(), static_cast<long long>(s.nonZeros()), viscosity, 1e3 * setup);
  std::printf("  S x %.3f ms | Poisson solve %.3f ms = %.1f S x | Galerkin Jacobian %.3f ms = "
              "%.1f S x | step (%d iterations) %.3f ms = %.1f S x\n",
              1e3 * spmv, 1e3 * poisson, poisson / spmv, 1e3 * jacobian, jacobian / spmv,
              flow.lastIterations(), 1e3 * step, step / spmv);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> levels;
  for (int i = 1; i < argc; ++i) levels.push_back(std::atoi(argv[i]));
  if (levels.empty()) levels = {4, 5, 6};
  for (int level : levels)
    for (double viscosity : {1e-4, 0.0}) benchLevel(level, viscosity);
  return 0;
}
