#pragma once
// Hostile-input checks of a legacy VTK file (.vtk, "# vtk DataFile Version ...") before VTK's
// vtkDataSetReader reads it (docs/reliability.md). The legacy reader allocates whatever a header
// line declares ("POINTS 100000000000 float") before it finds the data missing, so every count a
// line declares is held against the bytes the file has: each value takes at least sizeof(type)
// bytes in a BINARY file and 2 bytes ("0 ") in an ASCII one. Checked lines, wherever they stand
// (the check does not follow the file's structure; a binary block that happens to hold such a
// line is refused only if its count could not fit either):
//   DIMENSIONS nx ny nz, POINTS n type, X/Y/Z_COORDINATES n type, CELLS n size, CELL_TYPES n,
//   VERTICES/LINES/POLYGONS/TRIANGLE_STRIPS n size, OFFSETS/CONNECTIVITY type (5.1 files),
//   POINT_DATA n, CELL_DATA n, FIELD name n and each of its arrays "name components tuples type"
//   (the block is followed through its data), LOOKUP_TABLE name size, SCALARS name type
//   components (1..4, VTK's limit); and every type name (POINTS, COORDINATES, SCALARS, VECTORS,
//   NORMALS, TENSORS, TEXTURE_COORDINATES, OFFSETS, CONNECTIVITY, field arrays) must be one VTK
//   reads: VTK 9.1 dereferences the null array it makes of an unknown one.
// Throws FileError naming the file, the line number and the keyword (or field array).
#include <filesystem>

namespace fluidviz {

void checkLegacyVtkSizes(const std::filesystem::path& path);

}  // namespace fluidviz
