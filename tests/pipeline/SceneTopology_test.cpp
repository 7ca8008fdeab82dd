// output.topology (pipeline/SceneTopology.h):
// 1. A 2D lid-driven cavity at Re 100 (48 x 48 nodes, 15 s): the primary vortex is a centre at
//    Ghia, Ghia & Shin 1982's (0.6172, 0.7344) within 0.01 m, and the scene's CSV is exactly what
//    the topology wrapper (the path of `fluidviz topology` and the ParaView plugin) finds in the
//    final snapshot read back from its file: the scene analyses the image the file holds.
// 2. A 3D cubic cavity at Re 100 (16^3 nodes, 6 s): the primary vortex core crosses the
//    symmetry plane z = 0.5 at a spiral 2-saddle, the core (its stable separatrix) and the
//    outward spiralling unstable surface in that plane (within 0.01 m); the same file check.
// 3. Bad entries are refused naming their key.
#include <gtest/gtest.h>

#include <vtkImageData.h>
#include <vtkPolyData.h>

#include <cmath>
#include <filesystem>
#include <regex>

#include "fieldviz/io/VtkXmlReaders.h"
#include "filters/topology/vtk/TopologyPolyData.h"
#include "pipeline/SceneValidation.h"
#include "pipeline/TopologyOutputs.h"
#include "tests/pipeline/PipelineTestSupport.h"

namespace fs = std::filesystem;

namespace fluidviz::test {
namespace {

class SceneTopologyTest : public TempDirTest {};

std::string cavityScene(const std::string& lattice, int resolution, double endTime,
                        const std::string& topology) {
  const bool is3D = lattice == "D3Q19";
  return R"({"name": "cavity", "solver": "lbm", "lbm": {"lattice": ")" + lattice +
         R"(", "collision": "trt", "domain_size": [1.0, 1.0], )" +
         (is3D ? R"("domain_depth": 1.0, )" : "") + R"("resolution": )" +
         std::to_string(resolution) +
         R"(, "reynolds": 100, "lattice_velocity": 0.1,
       "walls": {"y_max": {"type": "moving_wall", "velocity": [1.0, 0.0]}}, "end_time": )" +
         std::to_string(endTime) + R"(},
       "output": {"snapshots": 1, "images": [], "topology": [)" + topology + "]}}";
}

/// The final snapshot of a run into `dir` (the last .vti of its series).
fs::path finalSnapshot(const fs::path& dir) {
  fs::path last;
  for (const auto& e : fs::directory_iterator(dir / "cavity"))
    if (e.path().extension() == ".vti" && e.path() > last) last = e.path();
  return last;
}

}  // namespace

TEST_F(SceneTopologyTest, PlanarCavityCentreIsGhiasAndTheFileGivesTheSamePoints) {
  runInto(sceneFromText(cavityScene("D2Q9", 48, 15.0, R"({"planar": {"underlay": "speed"}})")),
          "run");
  const fs::path out = dir_ / "run";
  for (const char* f : {"cavity_topology.vtp", "cavity_topology.csv",
                        "cavity_topology_separatrices.vtp", "cavity_topology.png"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  EXPECT_FALSE(fs::exists(out / "cavity_topology_surfaces.vtp"));  // planar: no surfaces

  const std::string csv = readText(out / "cavity_topology.csv");
  const std::regex centre(R"(\n([0-9.]+),([0-9.]+),0,centre,1,1,)");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(csv, m, centre)) << csv;
  EXPECT_NEAR(std::stod(m[1]), 0.6172, 0.01);  // Ghia et al. 1982, Table V, Re 100
  EXPECT_NEAR(std::stod(m[2]), 0.7344, 0.01);

  vtkSmartPointer<vtkImageData> image = readImageData(finalSnapshot(out));
  const topology::TopologyResult again =
      topology::computeTopology(image, "velocity", topology::TopologyParams{}, true);
  EXPECT_EQ(criticalPointsCsv(again.points), csv);
}

TEST_F(SceneTopologyTest, CubicCavityCoreIsASpiralSaddleInTheSymmetryPlane) {
  runInto(sceneFromText(cavityScene("D3Q19", 16, 6.0, R"({"view": {"width": 320, "height": 240}})")),
          "run");
  const fs::path out = dir_ / "run";
  const std::string csv = readText(out / "cavity_topology.csv");
  const std::regex saddle(R"(\n([0-9.]+),([0-9.]+),([0-9.]+),spiral_saddle_2,-1,1,)");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(csv, m, saddle)) << csv;
  const double z0 = std::stod(m[3]);
  EXPECT_NEAR(z0, 0.5, 0.01);  // the mid-plane is a symmetry plane of the cubic cavity

  vtkSmartPointer<vtkPolyData> surfaces = readVtp(out / "cavity_topology_surfaces.vtp");
  ASSERT_GT(surfaces->GetNumberOfPolys(), 100);
  double bounds[6];
  surfaces->GetBounds(bounds);
  EXPECT_NEAR(bounds[4], z0, 0.01);
  EXPECT_NEAR(bounds[5], z0, 0.01);
  EXPECT_GT(bounds[1] - bounds[0], 0.1);  // spirals out across the plane

  vtkSmartPointer<vtkImageData> image = readImageData(finalSnapshot(out));
  const topology::Topology3DResult again =
      topology::computeTopology3D(image, "velocity", topology::TopologyParams{}, false);
  EXPECT_EQ(criticalPoints3DCsv(again.points), csv);
  EXPECT_TRUE(fs::exists(out / "cavity_topology.png"));
}

TEST(SceneTopology, BadEntriesAreRefusedNamingTheKey) {
  EXPECT_NE(sceneErrorOf(cavityScene("D2Q9", 32, 1.0, R"({}, {"file": "cavity_topology"})"))
                .find("output.topology[1].file"),
            std::string::npos);
  EXPECT_NE(sceneErrorOf(cavityScene("D2Q9", 32, 1.0, R"({"cluster_radius": 50})"))
                .find("output.topology[0].cluster_radius"),
            std::string::npos);
  EXPECT_NE(sceneErrorOf(cavityScene("D3Q19", 16, 1.0, R"({"view": {"turntable_frames": 4}})"))
                .find("output.topology[0].view.turntable_frames"),
            std::string::npos);
  EXPECT_NE(sceneErrorOf(cavityScene("D2Q9", 32, 1.0, R"({"title": "{nonsense} t = {time}"})"))
                .find("output.topology[0].title"),
            std::string::npos);
  EXPECT_EQ(sceneErrorOf(cavityScene("D2Q9", 32, 1.0, R"({})")), "");
}

}  // namespace fluidviz::test
