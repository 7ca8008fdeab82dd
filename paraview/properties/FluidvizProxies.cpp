#include "paraview/properties/FluidvizProxies.h"

#include "paraview/properties/LicProxyParams.h"
#include "filters/resample/ResampleParams.h"
#include "filters/topology/TopologyParams.h"
#include "paraview/properties/StreamlineProxyParams.h"

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
               "writes the texture of its own piece. With Color By (speed, or a point scalar array) the "
               "point array `lic_color` (RGB, 0-255) is the texture blended with that scalar's "
               "colour map as in `fluidviz lic` pictures: colour + Lic Weight * (lic - 1/2) per "
               "channel, masked pixels in Mask Color.",
       .sceneSection = "output.lic[]",
       .input = {.dataType = "vtkImageData", .arrayAttribute = "Vectors"},
       .params = scene::paramTable<LicProxyParams>()},
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
      {.name = "FluidvizStreamlines",
       .label = "Fluidviz Streamlines",
       .vtkClass = "fvPvStreamlines",
       .help = "Streamlines of a vector point array of image data (2D, or 3D traced in 3D): "
               "polylines with point arrays speed and integration_time and cell arrays reason, "
               "reason_backward and seed_id (legend: field data reason_names). Seeds on a grid, "
               "a line, a plane, a box or evenly spaced (Jobard & Lefer 1997); RK2, RK4 or "
               "RK45. Masks what `fluidviz streamlines` masks (vtkValidPointMask, NaN, no-slip "
               "solids: lines end there); the same lines as `fluidviz streamlines` with the "
               "same keys (in 3D the default Seeding Grid Counts 10 x 10 x 1 seed the middle "
               "layer; the CLI's default there, without --seeds, is grid:5,5,5). In parallel "
               "every rank reads the whole input and traces every line (a line crosses any "
               "partition, evenly spaced lines depend on each other) and keeps those whose "
               "seed lies in a cell of its own piece, so that each line is produced once, "
               "whole.",
       .sceneSection = "output.streamlines[]",
       .input = {.dataType = "vtkImageData", .arrayAttribute = "Vectors"},
       .params = scene::paramTable<StreamlineProxyParams>()},
      {.name = "FluidvizResample",
       .label = "Fluidviz Resample",
       .vtkClass = "fvPvResample",
       .help = "SPH interpolation of particles (the points of poly data, e.g. an SPH snapshot "
               ".vtp) onto a regular grid, Shepard-normalised or (Order linear) first order, "
               "as `fluidviz resample`: image data with each resampled point array, color "
               "(sum of V_j W), mask and vtkValidPointMask (1 = particle support), "
               "summation_density with masses, resample_order with Order linear (1 = first "
               "order, 0 = Shepard fallback). "
               "Without Smoothing Length, h is the median of the particles' array "
               "smoothing_length when they have one. In parallel every rank reads every "
               "particle and writes its own piece of the grid.",
       .sceneSection = "",
       .input = {.dataType = "vtkPolyData", .arrayAttribute = ""},
       .params = scene::paramTable<resample::ParticleResampleParams>()},
  };
}

}  // namespace fluidviz::paraview
