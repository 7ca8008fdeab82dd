// Lid-driven square cavity at Re = 100 against Ghia, Ghia & Shin 1982 (J. Comput. Phys.
// 48:387), Tables I and II: u on the vertical centreline x = 0.5 and v on the horizontal
// centreline y = 0.5, normalised by the lid speed (solvers/lbm/validation/CavityGhia1982.h: bilinear
// samples at the table's positions, the rows on the walls left out).
// Resolution 64 x 64, lattice lid speed 0.1 (tau = 0.692), run to steady state (measured RMS
// errors: 0.0034 / 0.0021 at 64^2, 0.0027 / 0.0032 at 128^2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "tests/support/LbmScenes.h"
#include "solvers/lbm/LbmSolverD2Q9.h"
#include "solvers/lbm/validation/CavityGhia1982.h"

namespace fluidviz::lbm {
namespace {

TEST(LidDrivenCavity, Re100MatchesGhia1982) {
  LbmParams p = test::lidDrivenCavity(64, 100, 0.1);
  p.end_time = 100.0;  // 100 lid transit times at most
  p.steady_tolerance = 1e-6;
  p.check_interval = 1000;
  LbmSolverD2Q9 solver(p);
  EXPECT_EQ(solver.run(), StopReason::Steady);
  const FieldSet f = solver.fields();
  const std::string data = FLUIDVIZ_EXAMPLE_DATA_DIR;
  const std::vector<GhiaPoint> uTable = readGhiaCentreline(data + "/ghia1982_u_vertical_centerline.csv");
  const std::vector<GhiaPoint> vTable = readGhiaCentreline(data + "/ghia1982_v_horizontal_centerline.csv");
  ASSERT_EQ(uTable.size(), 15u);  // 17 rows, the two on the walls left out
  ASSERT_EQ(vTable.size(), 15u);
  const GhiaComparison c = compareWithGhia(*f.findVector("velocity"), 1.0, uTable, vTable);
  const double uRms = c.uRms, vRms = c.vRms;
  std::printf("Cavity Re 100, 64^2, t = %.1f s (%lld steps): RMS error u %.4f (max %.4f), "
              "v %.4f (max %.4f); tolerance %.2f RMS\n",
              solver.time(), solver.stepCount(), uRms, c.uMax, vRms, c.vMax, kGhiaRmsTolerance);
  EXPECT_LT(uRms, kGhiaRmsTolerance);
  EXPECT_LT(vRms, kGhiaRmsTolerance);
}

}  // namespace
}  // namespace fluidviz::lbm
