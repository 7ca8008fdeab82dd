// Writes small .pvd time series for the pvbatch integration tests (tests/CMakeLists.txt):
//   OUT/good/series.pvd     3 snapshots of a 16x12 grid: velocity(3), density(1), speed(1)
//   OUT/nan/series.pvd      the same, with one NaN in step 1's density
//   OUT/missing/series.pvd  the same, with step 2's .vti deleted after it was listed
// Usage: write_sample_series OUT
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <numbers>

#include "fieldviz/io/PvdSeries.h"
#include "fieldviz/io/VtkXmlWriters.h"

using namespace fluidviz;

namespace {

constexpr int kSteps = 3;

// A decaying Taylor-Green vortex: smooth, known, and different at every step.
FieldSet taylorGreenSnapshot(double time) {
  FieldSet set;
  set.grid.dims = {16, 12, 1};
  set.grid.spacing = {1.0 / 15.0, 1.0 / 11.0, 1.0};
  VectorField velocity{"velocity", set.grid, {}};
  ScalarField density{"density", set.grid, {}};
  const double decay = std::exp(-2.0 * time);
  const double k = 2.0 * std::numbers::pi;
  for (int j = 0; j < set.grid.dims[1]; ++j)
    for (int i = 0; i < set.grid.dims[0]; ++i) {
      const Vec3 p = set.grid.position(i, j);
      velocity.values.push_back(
          decay * Vec3(std::sin(k * p.x()) * std::cos(k * p.y()), -std::cos(k * p.x()) * std::sin(k * p.y()), 0.0));
      density.values.push_back(1.0 + 0.01 * decay * decay * std::cos(2 * k * p.x()));
    }
  set.add(magnitude(velocity, "speed"));
  set.add(velocity);
  set.add(density);
  return set;
}

enum class Defect { None, NanInStep1, MissingStep2 };

void writeSeries(const std::filesystem::path& folder, Defect defect) {
  std::filesystem::remove_all(folder);  // each run starts from nothing: no stale snapshots
  std::filesystem::create_directories(folder);
  PvdSeries series(folder / "series.pvd");
  for (int step = 0; step < kSteps; ++step) {
    const double time = 0.25 * step;
    FieldSet set = taylorGreenSnapshot(time);
    if (defect == Defect::NanInStep1 && step == 1)
      set.scalars[1].values[7] = std::numeric_limits<double>::quiet_NaN();
    const std::string file = "snapshot_" + std::to_string(step) + ".vti";
    writeVti(set, folder / file);
    series.add(time, file);
  }
  if (defect == Defect::MissingStep2) std::filesystem::remove(folder / "snapshot_2.vti");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: write_sample_series OUT\n";
    return 2;
  }
  try {
    const std::filesystem::path out = argv[1];
    writeSeries(out / "good", Defect::None);
    writeSeries(out / "nan", Defect::NanInStep1);
    writeSeries(out / "missing", Defect::MissingStep2);
  } catch (const std::exception& e) {
    std::cerr << "write_sample_series: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
