#pragma once
// Conversion between fluidviz's field model (FieldSet on a Grid) and vtkImageData point data.
// The only place where a FieldSet meets VTK: writers, readers, renderer and the thin VTK filter
// wrappers all go through here, so array layout rules live in one file:
//   FieldSet -> image: vectors first, then scalars (FieldSet::arrayNames order); all arrays are
//                      double; vectors always have 3 components (2D fields carry z = 0).
//   image -> FieldSet: numeric point-data arrays of any type become doubles; 1 component ->
//                      ScalarField, 3 -> VectorField, 2 -> VectorField with z = 0; other
//                      component counts are skipped (with the reason) unless asked for by name.
#include <stdexcept>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "fieldviz/core/Field.h"
#include "fieldviz/core/PointMask.h"
#include "fieldviz/core/RestingWalls.h"

class vtkDataObject;
class vtkImageData;
class vtkInformation;

namespace fluidviz {

/// A point-data array that is missing, has the wrong shape or does not fit the grid.
/// what() is the full message, prefixed with the data's source ("file X: ...").
class DataArrayError : public std::invalid_argument {
 public:
  DataArrayError(const std::string& message, std::string arrayName)
      : std::invalid_argument(message), arrayName_(std::move(arrayName)) {}
  const std::string& arrayName() const { return arrayName_; }

 private:
  std::string arrayName_;
};

/// A point-data array left out of a FieldSet, and why.
struct SkippedArray {
  std::string name;
  int components = 0;
  std::string reason;
};

struct ImageDataFields {
  FieldSet fields;
  std::vector<SkippedArray> skipped;
};

/// Image with the set's grid (dims, origin, spacing exact) and one double point-data array per
/// field. Throws std::invalid_argument if the grid is invalid or a field's size does not match it.
vtkSmartPointer<vtkImageData> toImageData(const FieldSet& set);

/// Grid of an image; `source` ("file X") prefixes the message. Throws std::invalid_argument if the
/// image is rotated (direction matrix not identity) or Grid::validate rejects it.
Grid gridOf(vtkImageData* image, const std::string& source = "image data");

/// All usable point-data arrays of the image, in the image's order; the others in `skipped`.
/// Throws DataArrayError if an array's tuple count differs from the image's point count.
ImageDataFields fromImageData(vtkImageData* image, const std::string& source = "image data");

/// One named point-data array as a vector field (2 or 3 components, z = 0 for 2).
/// Throws DataArrayError: "<source>: no point-data array 'foo'; arrays present: velocity(3),
/// density(1)" or "<source>: array 'density' has 1 component; a vector field needs 2 or 3".
VectorField vectorFieldFrom(vtkImageData* image, const std::string& arrayName,
                            const std::string& source = "image data");

/// One named 1-component point-data array as a scalar field; errors as vectorFieldFrom.
ScalarField scalarFieldFrom(vtkImageData* image, const std::string& arrayName,
                            const std::string& source = "image data");

/// The nodes the fluidviz CLI masks by default in a 2D `velocity` read from `image` (flowMask):
/// where the image's vtkValidPointMask, if it has one, is 0, NaN/inf nodes and no-slip solids, so
/// that a VTK or ParaView filter masks the same nodes as `fluidviz lic` and `fluidviz topology`.
/// Empty when no node is masked, and for a 3D field (solids are found layer by layer).
PointMask defaultFlowMask(vtkImageData* image, const VectorField& velocity,
                          const std::string& source = "image data");

/// Adds the point array vtkValidPointMask (unsigned char, 1 = valid) of `masked` (1 = masked;
/// empty: every node valid) to `image`, as fluidviz writes its masks (writeVti).
void addValidPointMask(vtkImageData* image, const PointMask& masked);

/// "velocity(3), density(1)", or "none": what an error message offers instead of a missing array.
std::string describePointArrays(vtkImageData* image);

/// The first value of the field-data string array `name` (e.g. "length_unit", docs/units.md), or
/// an empty string when the data has no such array or it is not a non-empty string array.
std::string fieldDataString(vtkDataObject* data, const std::string& name);

/// The no-slip walls at rest of a 2D `velocity` read from `image`: the masked nodes (`mask`,
/// e.g. defaultFlowMask) whose velocity is zero (restingSolidNodes), and the sides the file's
/// field data kRestingSidesFieldData names (fluidviz's LBM snapshots write it). Throws
/// DataArrayError naming `source` for a field-data value that names no side.
RestingWalls restingWallsOf(vtkImageData* image, const VectorField& velocity,
                            const PointMask& mask, const std::string& source = "image data");

/// Asks the upstream pipeline for the whole input, `in` being the input's information in a
/// filter's RequestUpdateExtent: the whole extent, as piece 0 of 1. For filters whose every
/// output value may depend on any input node (streamlines, LIC, index loops): in a parallel
/// ParaView each rank then reads all of it, instead of the piece its own output was asked for.
void requestWholeInput(vtkInformation* in);

/// The vector array a VTK filter works on: the one chosen with SetInputArrayToProcess (`chosen`,
/// the filter's GetInputArrayInformation(0)) if its name is not empty, else the image's active
/// vectors. Throws std::invalid_argument naming `filter` and the arrays present without either.
std::string chosenVectorArrayName(vtkInformation* chosen, vtkImageData* image,
                                  const std::string& filter);

}  // namespace fluidviz
