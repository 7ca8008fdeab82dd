#include "pipeline/SceneTopology.h"

#include <vtkImageData.h>
#include <vtkPolyData.h>

#include "fieldviz/core/PointMask.h"
#include "fieldviz/io/OutputPath.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "fieldviz/render/RgbaImage.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/topology/vtk/TopologyPolyData.h"
#include "pipeline/FlowFields.h"
#include "pipeline/PictureText.h"
#include "pipeline/SceneValidation.h"
#include "pipeline/TopologyOutputs.h"
#include "pipeline/TopologyPicture3D.h"

namespace fluidviz {

namespace fs = std::filesystem;
namespace topo = topology;

namespace {

constexpr const char* kSource = "final snapshot";

std::string keyOf(std::size_t i) { return "output.topology[" + std::to_string(i) + "]."; }

/// The files an entry writes, by suffix of its stem.
std::vector<std::string> suffixes(const TopologyOutput& o) {
  std::vector<std::string> s{".vtp", ".csv"};
  if (o.separatrices) s.insert(s.end(), {"_separatrices.vtp", "_surfaces.vtp"});
  if (o.picture) s.push_back(".png");
  return s;
}

struct Written {
  const fs::path& dir;
  std::vector<fs::path>& files;
  void vtp(vtkPolyData* data, const std::string& name) {
    writeVtp(data, dir / name);
    files.push_back(dir / name);
  }
  void text(const std::string& content, const std::string& name) {
    writeTextOutput(dir / name, content);
    files.push_back(dir / name);
  }
  void png(const RgbaImage& image, const std::string& name) {
    writePicture(image, dir / name);
    files.push_back(dir / name);
  }
};

void writePlanar(const TopologyOutput& o, vtkImageData* image, const std::string& title,
                 const std::string& stem, Written& out) {
  const topo::TopologyResult r =
      topo::computeTopology(image, "velocity", o, o.separatrices, kSource);
  RgbaImage picture;  // rendered before the files: its errors stop everything
  if (o.picture) {
    const PointMask mask = defaultFlowMask(image, r.field, kSource);
    TopologyPictureParams p = o.planar;
    p.separatrices = p.separatrices && o.separatrices;
    p.picture.title = title;
    if (p.picture.scalar_bar_title.empty()) p.picture.scalar_bar_title = legendTitleOf(p.blend.color_by);
    picture = renderTopologyPicture(inPlaneVelocity(withMaskedValue(r.field, mask, Vec3::Zero())),
                                    r.points, r.separatrices, p, maskedCells(r.field.grid, mask));
  }
  out.vtp(r.pointsPolyData, stem + ".vtp");
  out.text(criticalPointsCsv(r.points), stem + ".csv");
  if (o.separatrices) out.vtp(r.separatricesPolyData, stem + "_separatrices.vtp");
  if (o.picture) out.png(picture, stem + ".png");
}

void writeVolume(const TopologyOutput& o, vtkImageData* image, const std::string& title,
                 const std::string& stem, Written& out) {
  const topo::Topology3DResult r =
      topo::computeTopology3D(image, "velocity", o, o.separatrices, kSource, o.separatrices);
  RgbaImage picture;
  if (o.picture) {
    Topology3DPictureParams p;
    p.view = o.view;
    p.title = title;
    p.glyph_size = o.planar.glyph_size;
    picture = renderTopology3DPicture(r.field.grid, r.points, r.separatrices, r.surfaces, p);
  }
  out.vtp(r.pointsPolyData, stem + ".vtp");
  out.text(criticalPoints3DCsv(r.points), stem + ".csv");
  if (o.separatrices) {
    out.vtp(r.separatricesPolyData, stem + "_separatrices.vtp");
    out.vtp(r.surfacesPolyData, stem + "_surfaces.vtp");
  }
  if (o.picture) out.png(picture, stem + ".png");
}

}  // namespace

std::string topologyFileStem(const SceneParams& scene, std::size_t i) {
  const TopologyOutput& o = scene.output.topology[i];
  if (!o.file.empty()) return o.file;
  return scene.name + "_topology" + (i == 0 ? "" : "_" + std::to_string(i + 1));
}

void validateSceneTopology(const SceneParams& scene, std::vector<std::string>& taken) {
  for (std::size_t i = 0; i < scene.output.topology.size(); ++i) {
    const TopologyOutput& o = scene.output.topology[i];
    const std::string key = keyOf(i);
    if (scene.solver == SolverKind::sph)
      throw ParamError(key.substr(0, key.size() - 1),
                       "is for grid solvers (lbm, fhp); for SPH resample the particles with "
                       "output.grids and run `fluidviz topology` on the grid");
    for (const std::string& suffix : suffixes(o))
      requireOutputFileName(key + "file", topologyFileStem(scene, i) + suffix,
                            suffix.substr(suffix.rfind('.')), taken);
    withKeyPrefix(key, [&] { topo::validateTopologyParams(o); });
    withKeyPrefix(key + "planar.", [&] { validateTopologyPictureParams(o.planar); });
    withKeyPrefix(key + "view.", [&] {
      validateView3DParams(o.view);
      if (o.view.turntable_frames > 0)
        throw ParamError("turntable_frames", "is " + std::to_string(o.view.turntable_frames) +
                                                 "; the topology picture is one view (its legend "
                                                 "is drawn below it), allowed: 0");
    });
    pictureTitle(scene, key + "title", o.title, {"velocity", 0.0});
  }
}

void writeSceneTopology(const SceneParams& scene, vtkImageData* snapshot, double time,
                        const fs::path& dir, std::vector<fs::path>& written) {
  Written out{dir, written};
  const bool volume = snapshot->GetDimensions()[2] > 1;
  for (std::size_t i = 0; i < scene.output.topology.size(); ++i) {
    const TopologyOutput& o = scene.output.topology[i];
    const std::string title = pictureTitle(scene, keyOf(i) + "title", o.title, {"velocity", time});
    const std::string stem = topologyFileStem(scene, i);
    if (volume)
      writeVolume(o, snapshot, title, stem, out);
    else
      writePlanar(o, snapshot, title, stem, out);
  }
}

}  // namespace fluidviz
