#pragma once
// Legacy VTK files (.vtk: "# vtk DataFile Version 2.0 ... 5.1", ASCII or BINARY) of every
// dataset type — structured points, structured and rectilinear grids, unstructured grids, poly
// data — read by VTK's own vtkDataSetReader, every SCALARS/VECTORS/NORMALS/FIELD array included.
// Hostile input is refused first (VtkLegacySizeCheck.h) and VTK's complaints are collected, not
// printed; every problem throws FileError naming the file (and the array where it applies):
// missing or unreadable file, not a legacy VTK file, declared sizes the file cannot hold,
// corrupt or truncated data, arrays whose length does not match the points or cells.
#include <filesystem>

#include <vtkSmartPointer.h>

class vtkDataSet;

namespace fluidviz {

vtkSmartPointer<vtkDataSet> readLegacyVtk(const std::filesystem::path& path);

}  // namespace fluidviz
