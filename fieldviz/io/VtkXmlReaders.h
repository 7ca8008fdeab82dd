#pragma once
// Readers for the VTK XML files users bring: .vti from ParaView, VTK or fluidviz (float or double,
// any integer type, compressed or not, appended/binary/ascii) and .vtp particle or line sets.
// VTK's own complaints are caught, never printed; every problem throws FileError whose message
// names the file and, where it applies, the array and what was expected:
//   missing file, not a VTK XML file of that kind, corrupt or truncated data, missing array
//   (listing the arrays present), wrong component count, array size not matching the grid, and
//   invalid grids (Grid::validate).
#include <filesystem>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "fieldviz/core/Field.h"
#include "fieldviz/io/ImageSampling.h"
#include "fieldviz/vtk/ImageDataAdapter.h"

class vtkImageData;
class vtkPolyData;

namespace fluidviz {

/// The image as VTK reads it (for callers that keep working in VTK, e.g. the renderer). A legacy
/// .vtk file of any dataset type is read too (VtkLegacyReader.h) and, unless it holds structured
/// points, resampled onto an image (ImageSampling.h).
vtkSmartPointer<vtkImageData> readImageData(const std::filesystem::path& path,
                                            const ImageSampling& sampling = {});

/// Every usable point-data array; arrays that cannot be fields (4+ components, strings, unnamed)
/// are left out and, if `skipped` is given, listed there with the reason.
FieldSet readVti(const std::filesystem::path& path, std::vector<SkippedArray>* skipped = nullptr);

/// One named array with 2 or 3 components (2 -> z = 0).
VectorField readVectorField(const std::filesystem::path& path, const std::string& arrayName);

/// One named array with 1 component.
ScalarField readScalarField(const std::filesystem::path& path, const std::string& arrayName);

/// Poly data of a .vtp file (points, lines, vertices and their arrays).
vtkSmartPointer<vtkPolyData> readVtp(const std::filesystem::path& path);

}  // namespace fluidviz
