#pragma once
// Seeds of `fluidviz streamlines --seeds file:PATH`: the points of a .csv (x,y,z per row, an
// optional header row) or of a .vtp (its points, read by fieldviz's readVtp).
#include <filesystem>
#include <vector>

#include "fieldviz/core/Field.h"

namespace fluidviz::app {

/// The points of `file`. Throws FileError naming the file (and the line of a bad .csv row), and
/// UsageError for another extension.
std::vector<Vec3> readSeedFile(const std::filesystem::path& file);

}  // namespace fluidviz::app
