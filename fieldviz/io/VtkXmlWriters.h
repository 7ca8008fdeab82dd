#pragma once
// VTK XML writers for ParaView: .vti (image data) and .vtp (poly data). Binary appended data,
// zlib-compressed, 64-bit headers, written atomically (a temporary file renamed into place).
// Every failure (folder missing or not writable, disk full) throws FileError naming the target
// and the reason, and leaves no file behind.
#include <filesystem>

#include "fieldviz/core/Field.h"
#include "fieldviz/core/PointMask.h"

class vtkPolyData;

namespace fluidviz {

/// Writes the set's fields as point data of a .vti (layout: vtk/ImageDataAdapter.h).
/// Throws std::invalid_argument for an inconsistent set, FileError for write failures.
void writeVti(const FieldSet& fields, const std::filesystem::path& path);
/// The same with the nodes of `masked` (solids) flagged by an unsigned char point array
/// vtkValidPointMask (kValidPointMaskArray: 1 = fluid, 0 = masked), as VTK and ParaView do.
void writeVti(const FieldSet& fields, const PointMask& masked, const std::filesystem::path& path);

/// Writes poly data (streamlines, particles, critical points) as .vtp.
void writeVtp(vtkPolyData* polyData, const std::filesystem::path& path);

}  // namespace fluidviz
