#pragma once
// The z layers of the public real flows (tests/data/vtkdata/README.md) that the validation tests
// of issue 15 use, read as `fluidviz ... --slice z=K` reads them: readImageData (the office and
// kitchen structured grids resampled onto images by vtkResampleToImage, the carotid's structured
// points as they are), then the layer's in-plane part, named "velocity" as the peers want it.
#include <ostream>
#include <string>
#include <vector>

#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "pipeline/FlowFields.h"

namespace fluidviz::testing {

struct RealLayer {
  const char* file;
  const char* array;
  int layer;
};
inline void PrintTo(const RealLayer& d, std::ostream* os) { *os << d.file << " layer " << d.layer; }

inline const std::vector<RealLayer>& realLayers() {
  static const std::vector<RealLayer> layers = {{"office.binary.vtk", "vectors", 5},
                                                {"kitchen_velocity.vtk", "velocity", 8},
                                                {"carotid_bifurcation.vtk", "vectors", 12}};
  return layers;
}

inline VectorField readRealLayer(const RealLayer& d) {
  const std::string path = std::string(FLUIDVIZ_TEST_DATA_DIR) + "/vtkdata/" + d.file;
  VectorField layer =
      inPlaneVelocity(sliceZ(vectorFieldFrom(readImageData(path), d.array, path), d.layer));
  layer.name = "velocity";
  return layer;
}

/// gtest's name of a parameter: "office", "kitchen", "carotid".
inline std::string realLayerName(const RealLayer& d) {
  const std::string name = d.file;
  return name.substr(0, name.find_first_of("._"));
}

}  // namespace fluidviz::testing
