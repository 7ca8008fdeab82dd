#pragma once
// output.probes (pipeline/ProbeParams.h) of a grid solver's final state (filters/probe):
//   <name>_<probe>.csv  header comments (scene, line, field, and the deviation from the
//                       reference: max and RMS over the reference points inside the grid), then
//                       distance (m), x (m), y (m), z (m), <field> (<unit>) per sample
//   <name>_<probe>.png  the profile against the distance, the reference drawn as markers
// The deviation is also printed. Reference files are named relative to the scene file's folder.
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "fieldviz/core/Field.h"
#include "filters/probe/LineProbe.h"
#include "pipeline/SceneParams.h"

namespace fluidviz {

/// The rules of output.probes: solver lbm, names, a line of non-zero length, and a reference
/// that can be read and has the named columns. Throws ParamError (key "output.probes[i].<key>").
void validateProbes(const SceneParams& scene, const std::string& sceneFile);

/// A probe's reference profile: the distance and the scaled value columns of its CSV.
std::vector<probe::ReferencePoint> readProbeReference(const ProbeOutput& probe,
                                                      const std::filesystem::path& sceneFile);

/// Writes every probe of `scene` from `fields` (arrays "velocity" and "density", the state at
/// `time`, s, which a title's {time} shows) into `dir`,
/// prints each deviation to `log` and appends the files to `written`.
void writeProbes(const SceneParams& scene, const FieldSet& fields, double time,
                 const std::filesystem::path& sceneFile, const std::filesystem::path& dir,
                 std::ostream& log, std::vector<std::filesystem::path>& written);

}  // namespace fluidviz
