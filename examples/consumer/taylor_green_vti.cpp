// taylor_green_vti OUT.vti: the Taylor-Green vortex's initial state from fluidviz's LBM solver,
// written with fluidviz's VTK writer (COMPONENTS vtk of the installed package) and read back:
// exits 1 unless the file holds the same arrays with the same values (bit-equal doubles).
#include <cstdio>
#include <vector>

#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "fieldviz/scene/ParamVisitors.h"
#include "solvers/lbm/LbmSolver.h"

int main(int argc, char** argv) {
  using namespace fluidviz;
  if (argc != 2) {
    std::fprintf(stderr, "usage: taylor_green_vti OUT.vti\n");
    return 2;
  }
  lbm::LbmParams params;
  scene::readParams(scene::json::parse(R"({
    "domain_size": [1.0, 1.0], "resolution": 16, "reynolds": 100, "lattice_velocity": 0.05,
    "initial_flow": "taylor_green", "initial_speed": 1.0, "end_time": 0.1,
    "walls": {"x_min": {"type": "periodic"}, "x_max": {"type": "periodic"},
              "y_min": {"type": "periodic"}, "y_max": {"type": "periodic"}}})"),
                    params, "lbm");
  auto solver = lbm::createLbmSolver(params);
  std::vector<double> density;
  std::vector<Vec3> velocity;
  lbm::initialFlowFields(params, solver->units(), solver->grid(), density, velocity);
  solver->initialise(density, velocity);
  const FieldSet written = solver->fields();
  writeVti(written, argv[1]);
  const FieldSet read = readVti(argv[1]);
  int failures = 0;
  for (const VectorField& v : written.vectors) {
    const VectorField* back = read.findVector(v.name);
    failures += back == nullptr || back->values != v.values;
  }
  for (const ScalarField& s : written.scalars) {
    const ScalarField* back = read.findScalar(s.name);
    failures += back == nullptr || back->values != s.values;
  }
  std::printf("wrote and read %s: %zu arrays, %d differ\n", argv[1],
              written.vectors.size() + written.scalars.size(), failures);
  return failures == 0 ? 0 : 1;
}
