#pragma once
// Particle sets <-> vtkPolyData point clouds (the .vtp files SPH codes and ParaView write).
// The VTK side of resampling: the core (filters/resample) sees only particles::ParticleSet.
//   vtkPolyData -> ParticleSet: every numeric point-data array with 1 component becomes a
//     scalar, with 2 or 3 a vector (2 -> z = 0); other arrays (strings, 4+ components, unnamed)
//     are left out and listed in `skipped` with the reason. Cells are ignored: only points count.
//   ParticleSet -> vtkPolyData: points, one vertex cell per particle, double arrays.
#include <filesystem>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "fieldviz/vtk/ImageDataAdapter.h"
#include "fieldviz/particles/ParticleSet.h"

class vtkPolyData;

namespace fluidviz::resample {

/// `source` ("file X") prefixes error messages. dimension is 2 if every point has the same z,
/// else 3. Throws DataArrayError if an array's tuple count differs from the point count.
particles::ParticleSet particleSetFromPolyData(vtkPolyData* poly, const std::string& source,
                                         std::vector<SkippedArray>* skipped = nullptr);

/// readVtp + particleSetFromPolyData; FileError names the file (missing, corrupt, no points).
particles::ParticleSet readParticleVtp(const std::filesystem::path& path,
                                 std::vector<SkippedArray>* skipped = nullptr);

/// Points with one vertex per particle and the set's arrays (double; vectors 3 components).
vtkSmartPointer<vtkPolyData> toPolyData(const particles::ParticleSet& particles);

}  // namespace fluidviz::resample
