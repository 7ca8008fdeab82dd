#pragma once
// What a grid that is not an image becomes: fluidviz's filters work on regular grids, so a
// structured, rectilinear or unstructured grid, or poly data, is resampled onto an image with
// VTK's own vtkResampleToImage (probe of each node in the input's cells: linear inside a cell,
// cell data as the value of the cell that holds the node), with the same spacing on every axis,
// from the input's lower bounds on (the image ends less than a spacing short of the upper bounds). Nodes outside every cell get 0 and
// vtkValidPointMask = 0 (the array VTK adds, kept so that masks can use it).
#include <string>

#include <vtkSmartPointer.h>

#include "fieldviz/core/Params.h"

class vtkDataObject;
class vtkImageData;

namespace fluidviz {

struct ImageSampling {
  /// Node spacing of the image (world units); 0: automatic, about as many nodes as the input
  /// has points over its bounding box, at most kMaxAutomaticNodes.
  double spacing = 0.0;
  static constexpr double kMaxAutomaticNodes = 4.0e6;
  /// An explicit spacing may not give more nodes than this (a typo such as 1e-6 m).
  static constexpr double kMaxNodes = 2.0e8;
  /// Cell points each image node may be tested against on average (ImageSampling.cpp,
  /// probeWork): cells that tile a domain need a few; overlapping cells are refused above this.
  static constexpr double kMaxProbeWorkPerNode = 512.0;

  /// Drives --spacing of the grid commands, its help and its row in docs/input_formats.md. When
  /// not given the spacing stays 0 (automatic); given, it must be > 0.
  template <class V>
  static void describe(V& v) {
    v(&ImageSampling::spacing,
      {.key = "spacing",
       .description = "node spacing of the image that a grid which is not an image (.vtr .vts "
                      ".vtu .vtp .pvtu .vtm, legacy .vtk grids) is resampled onto, in the "
                      "file's length unit, the same on every axis; when not given: about as "
                      "many nodes as the file has points; images (.vti .pvti, legacy "
                      "structured points) keep their own grid and ignore it",
       .min = 0,
       .minExclusive = true});
  }
};

/// `data` itself when it is an image; otherwise its resampling (see above). `source` names the
/// input in errors (std::invalid_argument: empty data, no points, too many nodes,
/// overlapping cells).
vtkSmartPointer<vtkImageData> resampleToImage(vtkDataObject* data, const ImageSampling& sampling,
                                              const std::string& source);

}  // namespace fluidviz
