// `fluidviz streamlines` on a 3D field without --slice (issue 15): traced in 3D, the 3D --seeds
// forms (line, plane, box, points, file:.csv|.vtp), seeds outside the grid counted, bad seeds
// files naming file and line, the .vtp arrays, and the 3D picture's size.
#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkCellData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <filesystem>
#include <fstream>

#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "filters/streamlines/vtk/StreamlinePolyData.h"
#include "tests/apps/fluidviz/CliTestSupport.h"
#include "tests/support/PngFiles.h"

namespace fs = std::filesystem;

namespace fluidviz {
namespace {

using fluidviz::test::Result;
using fluidviz::test::run;

// 9 x 9 x 5 nodes over [0, 2] x [0, 2] x [0, 1] flowing along +x at 1 m/s, with a 1-component
// `density` = z (for --context isosurface and --color-by).
FieldSet uniformFlow3D() {
  FieldSet set;
  set.grid.dims = {9, 9, 5};
  set.grid.spacing = {0.25, 0.25, 0.25};
  set.add(VectorField{"velocity", set.grid, std::vector<Vec3>(set.grid.nodeCount(), Vec3(1, 0, 0))});
  ScalarField density{"density", set.grid, {}};
  for (int k = 0; k < 5; ++k)
    for (int n = 0; n < 81; ++n) density.values.push_back(0.25 * k);
  set.add(density);
  return set;
}

class Streamlines3D : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fluidviz_lines3d_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "out");
    field_ = (dir_ / "flow.vti").string();
    writeVti(uniformFlow3D(), field_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string out(const std::string& name) const { return (dir_ / "out" / name).string(); }
  std::string file(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  Result lines(const std::string& seeds, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"streamlines", field_, "-a", "velocity", "-o", out("s.vtp"),
                                     "--seeds", seeds};
    args.insert(args.end(), extra.begin(), extra.end());
    return run(args);
  }
  std::vector<std::vector<Vec3>> written() { return streamlines::polylinePoints(readVtp(out("s.vtp"))); }

  fs::path dir_;
  std::string field_;
};

// Along +x from a seed at (x, y, z): the line runs across the domain from x = 0 to x = 2 at the
// seed's y and z (traced both ways).
void expectStraightAcross(const std::vector<Vec3>& line, double y, double z) {
  ASSERT_GE(line.size(), 2u);
  EXPECT_NEAR(line.front().x(), 0.0, 1e-9);
  EXPECT_NEAR(line.back().x(), 2.0, 1e-9);
  EXPECT_NEAR(line.back().y(), y, 1e-12);
  EXPECT_NEAR(line.back().z(), z, 1e-12);
}

TEST_F(Streamlines3D, LineSeedsTraceIn3DAndWriteTheArraysOf2D) {
  const Result r = lines("line:1,0.5,0.25,1,1.5,0.75,3");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("traced 3 lines in 3D"), std::string::npos) << r.out;
  const auto l = written();
  ASSERT_EQ(l.size(), 3u);
  expectStraightAcross(l[0], 0.5, 0.25);
  expectStraightAcross(l[1], 1.0, 0.5);
  expectStraightAcross(l[2], 1.5, 0.75);
  vtkSmartPointer<vtkPolyData> vtp = readVtp(out("s.vtp"));
  for (const char* a : {"speed", "integration_time"})
    EXPECT_NE(vtp->GetPointData()->GetArray(a), nullptr) << a;
  for (const char* a : {"reason", "reason_backward", "seed_id"})
    EXPECT_NE(vtp->GetCellData()->GetArray(a), nullptr) << a;
  EXPECT_NEAR(vtp->GetPointData()->GetArray("speed")->GetRange()[1], 1.0, 1e-12);
}

TEST_F(Streamlines3D, PlaneBoxAndPointSeedsGiveTheirCountsAndOutsideSeedsAreCounted) {
  Result r = lines("plane:1,0,0,0,2,0,0,0,1,3,2");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(written().size(), 6u);
  expectStraightAcross(written()[5], 2.0, 1.0);  // corner + u + v
  r = lines("box:0.5,0.5,0.25,1.5,1.5,0.75,2,3,2");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(written().size(), 12u);
  r = lines("points:1,1,0.5;1,1,7;5,1,0.5");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("2 of 3 seeds lie outside the grid (no line)"), std::string::npos) << r.out;
  EXPECT_EQ(written().size(), 1u);
}

TEST_F(Streamlines3D, SeedsFromCsvWithHeaderAndFromVtpPoints) {
  Result r = lines("file:" + file("seeds.csv", "x,y,z\n1,0.5,0.25\n\n1, 1.5 ,0.75\n"));
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(written().size(), 2u);
  expectStraightAcross(written()[1], 1.5, 0.75);
  // The lines just written, as a seeds .vtp: their points are seeds on the same two lines.
  fs::copy_file(out("s.vtp"), dir_ / "seeds.vtp");
  r = lines("file:" + (dir_ / "seeds.vtp").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_GT(written().size(), 2u);
}

TEST_F(Streamlines3D, BadSeedsFilesExitWithCodeTwoNamingFileAndLine) {
  const std::string bad = file("bad.csv", "x,y,z\n1,1,0.5\n1,1\n");
  Result r = lines("file:" + bad);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(bad + ", line 3: expected x,y,z (three finite numbers), got '1,1'"),
            std::string::npos) << r.err;
  r = lines("file:" + file("nan.csv", "1,nan,0.5\n"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("line 1: expected x,y,z"), std::string::npos) << r.err;
  r = lines("file:" + (dir_ / "missing.csv").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("missing.csv"), std::string::npos) << r.err;
  r = lines("file:" + file("seeds.txt", "1,1,1\n"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("must be a .csv (x,y,z rows) or a .vtp"), std::string::npos) << r.err;
  r = lines("plane:1,0,0,0,2,0,0,0,1,3");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--seeds plane"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out("s.vtp")));
}

TEST_F(Streamlines3D, PictureHasTheAskedSizeWithTubesAndContext) {
  for (const std::string& context : {"slice:z=2", "isosurface:density=0.5"}) {
    const Result r = lines("box:0.5,0.5,0.25,1.5,1.5,0.75,2,2,2",
                           {"--png", out("s.png"), "--size", "320x240", "--tubes", "0.2",
                            "--context", context, "--color-by", "density"});
    ASSERT_EQ(r.code, 0) << r.err;
    const RgbaImage image = testing::readPngImage(out("s.png"));
    EXPECT_EQ(image.width, 320);
    EXPECT_EQ(image.height, 240);
  }
  Result r = lines("box:0.5,0.5,0.25,1.5,1.5,0.75,2,2,2",
                   {"--png", out("t.png"), "--context", "slice:z=5"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--context slice:z=5 is outside [0, 4]"), std::string::npos) << r.err;
  r = lines("box:0.5,0.5,0.25,1.5,1.5,0.75,2,2,2", {"--png", out("t.png"), "--underlay", "lic"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--underlay is for the 2D picture"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out("t.png")));
}

}  // namespace
}  // namespace fluidviz
