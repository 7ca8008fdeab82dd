#include "paraview/properties/FluidvizProxies.h"

#include "filters/lic/LicParams.h"
#include "filters/topology/TopologyParams.h"

namespace fluidviz::paraview {

std::vector<ProxyDescription> fluidvizProxies() {
  return {
      {.name = "FluidvizLIC",
       .label = "Fluidviz LIC",
       .vtkClass = "fvPvLic",
       .help = "Line Integral Convolution of a vector point array of image data (2D, or the xy "
               "slice of 3D data at Slice Height): an image whose point array `lic` in [0, 1] "
               "is the texture and `lic_mask` marks masked pixels. Reference (Cabral & Leedom "
               "1993) or fast (Stalling & Hege 1995) method; the same result as `fluidviz lic`. "
               "In parallel every rank reads the whole input (streamlines cross partitions) and "
               "writes the texture of its own piece.",
       .sceneSection = "output.lic[]",
       .input = {.dataType = "vtkImageData", .arrayAttribute = "Vectors"},
       .params = scene::paramTable<lic::LicParams>()},
      {.name = "FluidvizCriticalPoints",
       .label = "Fluidviz Critical Points",
       .vtkClass = "fvPvTopology",
       .help = "Critical points of a vector point array of image data (a 2D field or the layer "
               "Slice Index of 3D data) with Morse and non-Morse classification (Poincare "
               "index, sectors), and their separatrices; the same result as `fluidviz topology`. "
               "In parallel every rank analyses the whole input and keeps the points (and their "
               "separatrices) inside its own piece, so that each is found once.",
       .sceneSection = "topology",
       .input = {.dataType = "vtkImageData", .arrayAttribute = "Vectors"},
       .outputPorts = {"Critical Points", "Separatrices"},
       .params = scene::paramTable<topology::TopologyParams>()},
  };
}

}  // namespace fluidviz::paraview
