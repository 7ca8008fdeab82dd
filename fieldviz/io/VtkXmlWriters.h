#pragma once
// VTK XML writers for ParaView: .vti (image data) and .vtp (poly data). Binary appended data,
// zlib-compressed, 64-bit headers, written atomically (a temporary file renamed into place).
// Every failure (folder missing or not writable, disk full) throws FileError naming the target
// and the reason, and leaves no file behind.
#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/core/PointMask.h"

#include <vtkSmartPointer.h>

class vtkImageData;
class vtkPolyData;

namespace fluidviz {

/// What a file says about itself besides its arrays, as VTK field data: strings (provenance:
/// fluidviz version and commit, the scene, the solver's units; one-tuple vtkStringArrays) and
/// the time, as ParaView's TimeValue (a one-tuple double array), which ParaView shows for a file
/// opened on its own.
struct FileInfo {
  std::vector<std::pair<std::string, std::string>> strings;
  double time = std::numeric_limits<double>::quiet_NaN();  ///< s; NaN: none written
};

/// Writes the set's fields as point data of a .vti (layout: vtk/ImageDataAdapter.h).
/// Throws std::invalid_argument for an inconsistent set, FileError for write failures.
void writeVti(const FieldSet& fields, const std::filesystem::path& path);
/// The same with the nodes of `masked` (solids) flagged by an unsigned char point array
/// vtkValidPointMask (kValidPointMaskArray: 1 = fluid, 0 = masked), as VTK and ParaView do.
void writeVti(const FieldSet& fields, const PointMask& masked, const std::filesystem::path& path,
              const FileInfo& info = {});

/// The image writeVti(fields, masked, path, info) writes: for filters that must see a snapshot
/// exactly as its file holds it (solids masked, field data) without reading it back.
vtkSmartPointer<vtkImageData> snapshotImage(const FieldSet& fields, const PointMask& masked,
                                            const FileInfo& info = {});

/// Writes poly data (streamlines, particles, critical points) as .vtp.
void writeVtp(vtkPolyData* polyData, const std::filesystem::path& path, const FileInfo& info = {});

}  // namespace fluidviz
