// Issue 16: the critical points of fluidviz's own LBM snapshots next to no-slip walls at rest,
// end to end: example scene -> runScene -> final snapshot (solid mask, fluidviz_resting_walls)
// -> computeTopology, the function behind `fluidviz topology`, the ParaView plugin and `sweep`.
//
// Before walls at rest were told apart, the search took the zeros that line such a wall for
// flow features: the cylinder wake at 160 nodes gave 9 points of which 7 lay in the cylinder's
// wall layer (two "spiral sources" with det J = 3.4 and 4.3 1/s^2 and tr J = 0.9, 0.75 1/s, which
// an incompressible flow cannot have), the four-roll mill "unknown" points next to the box's
// corners and "degenerate" ones on its left and right walls. Now a wall's points are its
// attachment and separation points (sign changes of the wall shear), and the flow's own points
// lie outside the wall layer.
#include <gtest/gtest.h>
#include <vtkImageData.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include <unistd.h>

#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/scene/SceneFile.h"
#include "filters/topology/vtk/TopologyPolyData.h"
#include "pipeline/RunScene.h"
#include "pipeline/SceneReading.h"
#include "pipeline/Sweep.h"

namespace fs = std::filesystem;
using namespace fluidviz;
using namespace fluidviz::topology;

namespace {

// The example with its pictures off, at a coarse lattice: the topology of the final snapshot.
std::vector<CriticalPoint> finalTopology(const std::string& example,
                                         const std::vector<std::string>& overrides) {
  const std::string file = std::string(FLUIDVIZ_SOURCE_DIR) + "/examples/" + example + ".json";
  scene::json j = scene::readSceneFile(file);
  for (const std::string& o : overrides) scene::applyOverride(j, o, file);
  for (const char* o : {"output.images=[]", "output.lic=[]", "output.streamlines=[]",
                        "output.snapshots=1"})
    scene::applyOverride(j, o, file);
  const fs::path dir =
      fs::temp_directory_path() / ("fluidviz_wall_topology_" + example + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  std::ostringstream log;
  RunOptions options;
  options.outputDir = dir;
  options.log = &log;
  const fs::path snapshot = finalSnapshot(runScene(readSceneParams(j, file), options).files);
  std::vector<CriticalPoint> points =
      computeTopology(readImageData(snapshot), "velocity", TopologyParams{}, false, example).points;
  fs::remove_all(dir);
  return points;
}

std::string listed(const std::vector<CriticalPoint>& points) {
  std::string s;
  for (const CriticalPoint& p : points)
    s += "\n  " + p.typeName() + " (" + std::to_string(p.position.x()) + ", " +
         std::to_string(p.position.y()) + ")";
  return s;
}

// The points of `type` within `radius` of `at`.
int countNear(const std::vector<CriticalPoint>& points, CriticalPointType type, const Vec3& at,
              double radius) {
  return static_cast<int>(std::count_if(points.begin(), points.end(), [&](const CriticalPoint& p) {
    return p.type == type && (p.position - at).norm() <= radius;
  }));
}

}  // namespace

// Four rollers turning in alternation in a box with four walls at rest (examples/
// four_roll_mill.json at 80 nodes, dx = 0.0125 m, t = 3 s): the flow comes in between each pair
// of rollers along y and leaves along x, so a saddle at the centre, and on the walls: fluid
// meeting the left and right walls at their middles (attachment), leaving the bottom and top
// walls at theirs (separation), all on the box's mirror lines. Nothing else: the corners'
// unresolved eddies give no point.
TEST(WallTopology, FourRollMillHasItsSaddleAndOneWallPointPerWall) {
  const std::vector<CriticalPoint> points =
      finalTopology("four_roll_mill", {"lbm.resolution=80", "lbm.end_time=3"});
  const double dx = 0.0125, tolerance = 0.5 * dx;
  EXPECT_EQ(countNear(points, CriticalPointType::Saddle, Vec3(0.5, 0.5, 0), tolerance), 1);
  EXPECT_EQ(countNear(points, CriticalPointType::Attachment, Vec3(0.0, 0.5, 0), tolerance), 1);
  EXPECT_EQ(countNear(points, CriticalPointType::Attachment, Vec3(1.0, 0.5, 0), tolerance), 1);
  EXPECT_EQ(countNear(points, CriticalPointType::Separation, Vec3(0.5, 0.0, 0), tolerance), 1);
  EXPECT_EQ(countNear(points, CriticalPointType::Separation, Vec3(0.5, 1.0, 0), tolerance), 1);
  EXPECT_EQ(points.size(), 5u) << listed(points);
}

// Flow past a cylinder at rest (examples/cylinder_wake.json at 160 x 60 nodes, dx = 0.01 m,
// R = 5 cells, t = 2 s, before shedding starts): the steady wake's topology (as in Taneda's 1956
// photographs): the front stagnation point (attachment), a separation point either side, the
// rear stagnation point where the recirculating flow meets the cylinder (attachment), the two
// eddies of the recirculation bubble and the saddle that closes it on the axis. The flow is
// still mirror-symmetric about the axis y = 0.31 m: the pairs are mirror images.
TEST(WallTopology, CylinderWakeHasTheRecirculationBubblesTopology) {
  const std::vector<CriticalPoint> points =
      finalTopology("cylinder_wake", {"lbm.resolution=160", "lbm.end_time=2"});
  const double dx = 0.01, R = 0.05;
  const Vec3 centre(0.3, 0.31, 0);
  ASSERT_EQ(points.size(), 7u) << listed(points);
  EXPECT_EQ(countNear(points, CriticalPointType::Attachment, centre - Vec3(R, 0, 0), dx), 1)
      << listed(points);
  EXPECT_EQ(countNear(points, CriticalPointType::Attachment, centre + Vec3(R, 0, 0), dx), 1)
      << listed(points);
  std::vector<Vec3> separations, eddies;
  for (const CriticalPoint& p : points) {
    const Vec3 r = p.position - centre;
    if (p.type == CriticalPointType::Separation) {
      separations.push_back(p.position);
      EXPECT_NEAR(r.norm(), R, dx) << "on the wall";
      // On the rear half: between 20 and 70 degrees from the rear stagnation point.
      const double fromRear = std::abs(std::atan2(r.y(), r.x())) * 180 / M_PI;
      EXPECT_GT(fromRear, 20.0);
      EXPECT_LT(fromRear, 70.0);
    } else if (p.index == 1) {
      eddies.push_back(p.position);
      EXPECT_GT(r.x(), 0.0) << "behind the cylinder";
      EXPECT_GT(r.norm() - R, 1.5 * dx) << "outside the wall layer";
    } else if (p.type == CriticalPointType::Saddle) {
      EXPECT_NEAR(p.position.y(), centre.y(), 0.5 * dx) << "on the axis";
      EXPECT_GT(r.x(), R + dx) << "behind the bubble's eddies";
    }
    EXPECT_FALSE((p.type == CriticalPointType::SpiralSource || p.type == CriticalPointType::Source))
        << "a source in an incompressible flow at " << p.position.transpose();
  }
  ASSERT_EQ(separations.size(), 2u) << listed(points);
  ASSERT_EQ(eddies.size(), 2u) << listed(points);
  EXPECT_NEAR(separations[0].x(), separations[1].x(), 0.5 * dx) << "mirror images";
  EXPECT_NEAR(separations[0].y() + separations[1].y(), 2 * centre.y(), 0.5 * dx);
  EXPECT_NEAR(eddies[0].y() + eddies[1].y(), 2 * centre.y(), 0.5 * dx);
}
