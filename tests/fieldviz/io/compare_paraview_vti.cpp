// Reads a .vti that ParaView wrote (paraview_resave.py) and compares it with the fluidviz original:
// the grid and the double arrays ParaView passed through must be bit-identical, and the Float32
// array twice_density must equal 2 * density within float precision (relative 1.2e-7).
// Usage: compare_paraview_vti ORIGINAL.vti PARAVIEW_WRITTEN.vti     exit 0 = same, 1 = differs
#include <cmath>
#include <iostream>

#include "fieldviz/io/VtkXmlReaders.h"

using namespace fluidviz;

namespace {

int failures = 0;

void expect(bool ok, const std::string& what) {
  if (ok) return;
  std::cout << "compare_paraview_vti: FAIL: " << what << "\n";
  ++failures;
}

void compareGrids(const Grid& a, const Grid& b) {
  expect(a.dims == b.dims, "dims differ");
  expect(a.origin == b.origin, "origin differs");
  expect(a.spacing == b.spacing, "spacing differs");
}

void comparePassedThrough(const FieldSet& original, const FieldSet& paraview) {
  for (const VectorField& v : original.vectors) {
    const VectorField* p = paraview.findVector(v.name);
    expect(p && p->values == v.values, "vector array '" + v.name + "' missing or changed");
  }
  for (const ScalarField& s : original.scalars) {
    const ScalarField* p = paraview.findScalar(s.name);
    expect(p && p->values == s.values, "scalar array '" + s.name + "' missing or changed");
  }
}

void compareFloatResult(const FieldSet& original, const FieldSet& paraview) {
  const ScalarField* density = original.findScalar("density");
  const ScalarField* twice = paraview.findScalar("twice_density");
  expect(density && twice, "density or twice_density missing");
  if (!density || !twice) return;
  double worst = 0.0;
  for (std::size_t n = 0; n < density->values.size(); ++n)
    worst = std::max(worst, std::abs(twice->values[n] - 2.0 * density->values[n]) / (2.0 * std::abs(density->values[n])));
  std::cout << "twice_density: worst relative deviation from 2*density " << worst << "\n";
  expect(worst <= 1.2e-7, "twice_density deviates from 2*density by more than float precision");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: compare_paraview_vti ORIGINAL.vti PARAVIEW_WRITTEN.vti\n";
    return 2;
  }
  try {
    const FieldSet original = readVti(argv[1]);
    const FieldSet paraview = readVti(argv[2]);
    compareGrids(original.grid, paraview.grid);
    comparePassedThrough(original, paraview);
    compareFloatResult(original, paraview);
  } catch (const std::exception& e) {
    std::cout << "compare_paraview_vti: FAIL: " << e.what() << "\n";
    return 1;
  }
  if (failures == 0) std::cout << "compare_paraview_vti: OK: " << argv[2] << " matches " << argv[1] << "\n";
  return failures == 0 ? 0 : 1;
}
