// FastLIC (Stalling & Hege 1995) against reference LIC (Cabral & Leedom 1993), measured in the
// same run on the same field, noise and kernel: 1024 x 1024 px, L = 30 px, box kernel.
// Prints both wall times, the speed-up (target >= 5) and how far the fast image is from the
// reference. Usage: flow_bench [size=1024] [length=30]
#include <omp.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <string>

#include "filters/lic/LineIntegralConvolution.h"

using namespace fluidviz;

namespace {

// Four Lamb-Oseen vortices of alternating sign in a weak uniform stream on [0, 1]^2: circles,
// saddles between the vortices and nearly straight flow, like a mixing flow.
VectorField vortexStreet(int nodes) {
  VectorField v{"velocity", {}, {}};
  v.grid.dims = {nodes, nodes, 1};
  v.grid.spacing = {1.0 / (nodes - 1), 1.0 / (nodes - 1), 1.0};
  const double cx[4] = {0.25, 0.75, 0.25, 0.75}, cy[4] = {0.25, 0.25, 0.75, 0.75};
  const double gamma[4] = {1.0, -1.0, -1.0, 1.0}, core = 0.08;
  for (int j = 0; j < nodes; ++j)
    for (int i = 0; i < nodes; ++i) {
      const Vec3 p = v.grid.position(i, j);
      Vec3 u(0.3, 0.1, 0.0);
      for (int k = 0; k < 4; ++k) {
        const double dx = p.x() - cx[k], dy = p.y() - cy[k], r2 = dx * dx + dy * dy + 1e-12;
        const double s = gamma[k] / (2 * M_PI * r2) * (1 - std::exp(-r2 / (core * core)));
        u += Vec3(-dy * s, dx * s, 0.0);
      }
      v.values.push_back(u);
    }
  return v;
}

struct Seconds {
  double wall, cpu;  // cpu: all threads of the process, robust when other jobs share the cores
};
Seconds secondsOf(const auto& f) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  f();
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
          double(std::clock() - c0) / CLOCKS_PER_SEC};
}

}  // namespace

int main(int argc, char** argv) {
  const int size = argc > 1 ? std::stoi(argv[1]) : 1024;
  const double length = argc > 2 ? std::stod(argv[2]) : 30.0;
  const VectorField field = vortexStreet(257);
  lic::LicParams p;
  p.width = p.height = size;
  p.length = length;
  p.contrast = false;

  lic::LicImage ref, fast;
  p.method = "reference";
  const Seconds tRef = secondsOf([&] { ref = lic::computeLic(field, p); });
  p.method = "fast";
  const Seconds tFast = secondsOf([&] { fast = lic::computeLic(field, p); });

  double meanAbs = 0;
  for (std::size_t i = 0; i < ref.texture.values.size(); ++i)
    meanAbs += std::abs(ref.texture.values[i] - fast.texture.values[i]);
  meanAbs /= ref.texture.values.size();

  std::printf("LIC %d x %d px, L = %.0f px, step %.2f px, box kernel, %d threads\n", size, size,
              length, p.step, omp_get_max_threads());
  std::printf("                                      wall s     cpu s\n");
  std::printf("  reference (Cabral & Leedom 1993): %8.3f  %8.3f\n", tRef.wall, tRef.cpu);
  std::printf("  fast      (Stalling & Hege 1995): %8.3f  %8.3f  (fast_min_hits %d, line %.0f L)\n",
              tFast.wall, tFast.cpu, p.fast_min_hits, p.fast_line_factor);
  std::printf("  speed-up fast / reference:        %8.2f  %8.2f  (target >= 5)\n",
              tRef.wall / tFast.wall, tRef.cpu / tFast.cpu);
  std::printf("  mean |fast - reference|:          %8.4f            (raw values in [0, 1])\n",
              meanAbs);
  return 0;
}
