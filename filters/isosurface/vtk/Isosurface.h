#pragma once
// Thin VTK wrapper: isolines of 2D grids (vtkFlyingEdges2D) and isosurfaces of 3D grids
// (vtkFlyingEdges3D), with normals and optional windowed-sinc smoothing, plus the surface's size
// (vtkMassProperties for area and enclosed volume, summed segment lengths for isolines).
#include <string>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "fieldviz/core/Field.h"
#include "filters/isosurface/IsosurfaceParams.h"

class vtkImageData;

namespace fluidviz::isosurface {

/// The params.value level set of params.array: line segments for a 2D image (one node in z),
/// triangles for a 3D one. With params.interpolate_arrays every other point array of the image
/// is interpolated onto it linearly along the grid edge each point lies on (as Flying Edges
/// places the points; where one end of the edge is NaN - a resampled node without particle
/// support - the other end's value is taken). 3D surfaces carry "Normals" when params.normals. `source` ("file
/// X") prefixes messages. Throws ParamError for bad params or a value outside the array's finite
/// range, DataArrayError (fieldviz/vtk/ImageDataAdapter.h) if the array is missing, has more than
/// one component or holds NaN (e.g. resampled nodes without particle support: contour "color").
vtkSmartPointer<vtkPolyData> extractIsosurface(vtkImageData* image, const IsosurfaceParams& params,
                                               const std::string& source = "image data");

/// The same for a FieldSet (converted with toImageData).
vtkSmartPointer<vtkPolyData> extractIsosurface(const FieldSet& fields,
                                               const IsosurfaceParams& params);

struct SurfaceMeasures {
  double area = 0.0;    ///< 3D: total triangle area (m^2)
  double volume = 0.0;  ///< 3D: enclosed volume (m^3), meaningful for closed surfaces
  double length = 0.0;  ///< 2D: total isoline length (m)
  long long points = 0, cells = 0;
};

/// Size of a surface from extractIsosurface: triangles -> area and volume (vtkMassProperties),
/// lines -> length.
SurfaceMeasures measureSurface(vtkPolyData* surface);

}  // namespace fluidviz::isosurface
