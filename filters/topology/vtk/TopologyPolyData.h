#pragma once
// Critical points and separatrices <-> vtkPolyData: the layout of every fluidviz topology .vtp.
//
// Critical points: one vertex cell per point, in the order of findCriticalPoints; point arrays
//   type            string, the type's name ("saddle", "monkey_saddle", ...: toString)
//   type_code       int, CriticalPointType value (for colouring in ParaView; names in type_names)
//   index           int, Poincare index
//   morse           int, 1 = Morse (non-degenerate, one zero), 0 = non-Morse
//   det, trace      double, of the world-space Jacobian (1/s^2, 1/s)
//   normalized_det  double, det / G^2 (the degeneracy measure, TopologyParams::det_threshold)
//   hyperbolic, elliptic, parabolic   int, sector counts on the index loop
//   index_measured  int, 0 = no loop fitted (point on or next to the boundary)
//   cluster_size    int, zeros of the interpolant merged into the point
// field data type_names (string): type_names[code] is the name of type_code `code`.
//
// Critical points of a 3D field (VolumeTopology.h): one vertex cell per point, point arrays
//   type, type_code (CriticalPointType3D; names in field data type_names), index (degree on the
//   sphere), morse, det, trace, normalized_det (det / G^3), index_measured, cluster_size as above;
//   eigenvalues_real, eigenvalues_imag  3 components each, larger real part first (1/s)
//   jacobian        9 components, row-major d v_i / d x_j (1/s), as VTK's "gradient"
//   sphere_radius   radius of the index sphere (cells; 0 = not measured)
//
// Separatrices: one polyline cell per separatrix with at least 2 points, points from the critical
// point outwards; cell arrays
//   origin          int, index of the critical point it starts at
//   outgoing        int, 1 = leaves the point (traced forward), 0 = enters it (traced backward)
//   end             int, SeparatrixEnd value; names in field data end_names
//   end_point       int, critical point reached (end = critical_point), else -1
//
// Separating surfaces of 3D saddles (SeparatingSurfaces.h): triangles, all surfaces in one poly
// data; cell arrays
//   surface         int, index of the surface (one per Morse saddle)
//   origin          int, index of the critical point it starts at
//   outgoing        int, 1 = unstable manifold (2-saddles, traced forward), 0 = stable
// field data surface_end (int, one per surface: SurfaceEnd value; names in surface_end_names).
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "fieldviz/core/Field.h"
#include "filters/topology/CriticalPoint.h"
#include "filters/topology/CriticalPoint3D.h"
#include "filters/topology/Separatrices.h"
#include "filters/topology/SeparatingSurfaces.h"
#include "filters/topology/Separatrices3D.h"
#include "filters/topology/TopologyParams.h"

class vtkImageData;
class vtkPolyData;

namespace fluidviz::topology {

vtkSmartPointer<vtkPolyData> criticalPointsToPolyData(const std::vector<CriticalPoint>& points);
vtkSmartPointer<vtkPolyData> criticalPoints3DToPolyData(const std::vector<CriticalPoint3D>& points);
vtkSmartPointer<vtkPolyData> separatricesToPolyData(const std::vector<Separatrix>& separatrices);
/// 1D separatrices of 3D saddles, with the same cell arrays as the planar ones.
vtkSmartPointer<vtkPolyData> separatrices3DToPolyData(
    const std::vector<Separatrix3D>& separatrices);
/// Separating surfaces of 3D saddles as triangles.
vtkSmartPointer<vtkPolyData> separatingSurfacesToPolyData(
    const std::vector<SeparatingSurface>& surfaces);

/// Throws DataArrayError naming `source`, the array and the first offending node when a value of
/// the analysed slice is NaN or infinite: a zero of the field cannot be located next to them.
void requireFiniteSlice(const VectorField& field, int slice, const std::string& source);

/// The topology of one array of an image, in the core's types and as poly data.
struct TopologyResult {
  VectorField field;                       ///< the analysed array as read from the image
  std::vector<CriticalPoint> points;
  std::vector<Separatrix> separatrices;    ///< empty unless asked for
  vtkSmartPointer<vtkPolyData> pointsPolyData;
  vtkSmartPointer<vtkPolyData> separatricesPolyData;
};

/// Reads `arrayName` (2 or 3 components) of `image`, checks slice params.slice_index for
/// non-finite values and runs the core. Throws DataArrayError (array missing, scalar, NaN; the
/// message starts with `source`), ParamError (bad params, slice outside the grid).
TopologyResult computeTopology(vtkImageData* image, const std::string& arrayName,
                               const TopologyParams& params, bool withSeparatrices,
                               const std::string& source = "image data");

/// The topology of one array of a 3D image: critical points and the 1D separatrices of saddles.
struct Topology3DResult {
  VectorField field;                        ///< the analysed array as read from the image
  std::vector<CriticalPoint3D> points;
  std::vector<Separatrix3D> separatrices;   ///< empty unless asked for
  std::vector<SeparatingSurface> surfaces;  ///< empty unless asked for
  vtkSmartPointer<vtkPolyData> pointsPolyData;
  vtkSmartPointer<vtkPolyData> separatricesPolyData;
  vtkSmartPointer<vtkPolyData> surfacesPolyData;
};

/// Reads `arrayName` (3 components) of a 3D `image` and runs the volume core
/// (findCriticalPoints3D, computeSeparatrices3D). Nodes where the image's vtkValidPointMask is 0
/// are NaN for the core (no zero in their tetrahedra, lines end there), as are non-finite ones.
/// Throws DataArrayError (array missing or scalar; the message starts with `source`),
/// std::invalid_argument (an axis with fewer than 2 nodes), ParamError (bad params).
/// withSurfaces: also the separating surfaces of the saddles (computeSeparatingSurfaces).
Topology3DResult computeTopology3D(vtkImageData* image, const std::string& arrayName,
                                   const TopologyParams& params, bool withSeparatrices,
                                   const std::string& source = "image data",
                                   bool withSurfaces = false);

}  // namespace fluidviz::topology
