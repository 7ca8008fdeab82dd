// readParticleVtp (ParticleSetVtk.h), apart from the conversions: it reads files with
// fieldviz/io, which the ParaView plugin, reading through ParaView's readers, does not build.
#include <vtkPolyData.h>

#include "fieldviz/io/FileError.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "filters/resample/vtk/ParticleSetVtk.h"

namespace fluidviz::resample {

particles::ParticleSet readParticleVtp(const std::filesystem::path& path,
                                 std::vector<SkippedArray>* skipped) {
  vtkSmartPointer<vtkPolyData> poly = readVtp(path);
  if (poly->GetNumberOfPoints() == 0)
    throw FileError(path, "file " + path.string() + ": has no points (particles) to resample");
  try {
    return particleSetFromPolyData(poly, "file " + path.string(), skipped);
  } catch (const DataArrayError& e) {
    throw FileError(path, e.what(), e.arrayName());
  }
}

}  // namespace fluidviz::resample
