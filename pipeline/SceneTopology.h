#pragma once
// output.topology (SceneParams.h TopologyOutput): the topology of a grid solver's final
// velocity. The analysis runs on the image the final snapshot file holds (snapshotImage: solids
// masked by vtkValidPointMask, the resting walls in its field data), through the same VTK
// wrappers as `fluidviz topology` and the ParaView plugin (computeTopology, computeTopology3D),
// so that the scene, the command on the written snapshot and ParaView find the same points.
#include <filesystem>
#include <string>
#include <vector>

#include "pipeline/SceneParams.h"

class vtkImageData;

namespace fluidviz {

/// <file> of output.topology[i] (the stem of its files), or <name>_topology (_2, _3, ...).
std::string topologyFileStem(const SceneParams& scene, std::size_t i);

/// File names, ranges, solver (lbm or fhp) and title of every output.topology entry; adds the
/// files to `taken`. Throws ParamError naming "output.topology[i].<key>".
void validateSceneTopology(const SceneParams& scene, std::vector<std::string>& taken);

/// Analyses `snapshot`'s velocity for every output.topology entry and writes its files into
/// `dir` (appending them to `written`); `time` fills the picture titles.
void writeSceneTopology(const SceneParams& scene, vtkImageData* snapshot, double time,
                        const std::filesystem::path& dir,
                        std::vector<std::filesystem::path>& written);

}  // namespace fluidviz
