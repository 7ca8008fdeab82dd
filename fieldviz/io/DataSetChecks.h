#pragma once
// Checks of a dataset a VTK reader made, before any filter touches it. VTK's readers (legacy and
// XML) trust the file's geometry: a cell naming a point that does not exist, offsets that run
// past the connectivity or arrays shorter than the points are read as they are, and every filter
// after the reader then reads outside its arrays (fuzzing: the legacy reader, issue 15, and a
// .vtu cell naming point 2^40 that crashed vtkCellDataToPointData's threads).
#include <filesystem>

class vtkDataSet;

namespace fluidviz {

/// Throws FileError naming the file (and the array): point and cell arrays that do not match the
/// points or cells, structured points or coordinates fewer than the dimensions, cells naming
/// points outside the dataset, cells of a non-linear or unknown type or with the wrong number of
/// points for their type, offsets that are not 0 then non-decreasing up to the connectivity's end.
void requireConsistentDataSet(vtkDataSet* data, const std::filesystem::path& path);

}  // namespace fluidviz
