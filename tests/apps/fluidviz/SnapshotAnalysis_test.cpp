// The analysis commands on a run's own snapshots, with default settings (issue 16):
//   - six-roll mill (examples/six_roll_mill.json at 96 nodes across, 3 s): `topology` finds no
//     critical point inside a roller (before: a fake centre at each of the 6 roller axes, the
//     rigid rotation the roller nodes carry; the snapshot's vtkValidPointMask masks them now),
//     and `lic` draws every pixel within 0.8 R of a roller axis in the mask colour (before:
//     noise swirling with the roller); --ignore-file-arrays brings the 6 fake centres back;
//   - hydrostatic tank (examples/hydrostatic_tank.json, 0.02 s): its pressure picture is
//     written; `resample` takes h = 2.0 x 0.025 m = 0.05 m from the snapshot's smoothing_length
//     and the volumes m / rho from mass and density (before: h = 1.3 s guessed), so that the
//     colour field inside the water is 1 to 2% (Shepard sums of a Wendland kernel at 2 dx);
//   - a resampled grid whose unsupported nodes hold a made-up velocity (--empty-value 1): `lic`
//     masks them by the grid's own support flags, vtkValidPointMask (before: it convolved the
//     made-up velocity).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include "fieldviz/io/VtkXmlReaders.h"
#include "tests/apps/fluidviz/CliTestSupport.h"
#include "tests/support/PngFiles.h"

namespace fs = std::filesystem;

namespace {

using fluidviz::test::Result;
using fluidviz::test::run;

const std::string kExamples = std::string(FLUIDVIZ_SOURCE_DIR) + "/examples/";

// The six rollers of examples/six_roll_mill.json: radius 0.075 m on a circle of radius 0.2 m
// around (1, 1), at angles 0, 60, ... 300 degrees.
constexpr double kRollerRadius = 0.075;
std::vector<std::array<double, 2>> rollerCentres() {
  std::vector<std::array<double, 2>> c;
  for (int k = 0; k < 6; ++k)
    c.push_back({1.0 + 0.2 * std::cos(k * M_PI / 3), 1.0 + 0.2 * std::sin(k * M_PI / 3)});
  return c;
}

// Where `fluidviz lic` put its texture: "texture W x H px at picture pixels x [l, r), y [t, b)".
struct TextureRect {
  int left = 0, right = 0, top = 0, bottom = 0;
};
TextureRect textureRect(const std::string& out) {
  std::smatch m;
  const std::regex re(R"(picture pixels x \[(\d+), (\d+)\), y \[(\d+), (\d+)\))");
  if (!std::regex_search(out, m, re)) return {};
  return {std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3]), std::stoi(m[4])};
}

// (x, y) of every critical point of a `fluidviz topology --csv` file.
std::vector<std::array<double, 2>> csvPoints(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::array<double, 2>> points;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    double x = 0, y = 0;
    char comma = 0;
    s >> x >> comma >> y;
    points.push_back({x, y});
  }
  return points;
}

int pointsInRollers(const std::vector<std::array<double, 2>>& points) {
  int inside = 0;
  for (const auto& p : points)
    for (const auto& c : rollerCentres())
      inside += std::hypot(p[0] - c[0], p[1] - c[1]) < kRollerRadius;
  return inside;
}

class SnapshotAnalysisTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("fluidviz_snapshot_analysis_" + std::string(info->name()) +
                                        "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }
  // The last snapshot of examples/<name>.json run into dir_/<name> with `settings`.
  fs::path runExample(const std::string& name, const std::string& extension,
                      const std::vector<std::string>& settings) {
    std::vector<std::string> args = {"run", kExamples + name + ".json", "-o",
                                     (dir_ / name).string(), "--threads", "2"};
    for (const std::string& s : settings) args.insert(args.end(), {"--set", s});
    const Result r = run(args);
    EXPECT_EQ(r.code, 0) << r.err << r.out;
    return dir_ / name / name / (name + "_0001" + extension);
  }
  fs::path sixRollMillSnapshot() {
    return runExample("six_roll_mill", ".vti",
                      {"lbm.resolution=96", "lbm.end_time=3", "output.images=[]"});
  }
  // `pictures`: the example's own (density, speed, pressure), else none.
  fs::path tankSnapshot(bool pictures = false) {
    std::vector<std::string> settings = {"sph.end_time=0.02", "output.snapshots=1"};
    if (!pictures) settings.push_back("output.images=[]");
    return runExample("hydrostatic_tank", ".vtp", settings);
  }
  fs::path dir_;
};

TEST_F(SnapshotAnalysisTest, TopologyOfTheSixRollMillFindsNoPointInsideARoller) {
  const fs::path vti = sixRollMillSnapshot();
  const fs::path csv = dir_ / "points.csv";
  const auto topology = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"topology", vti.string(), "-a", "velocity", "-o",
                                     (dir_ / "p.vtp").string(), "--csv", csv.string(),
                                     "--no-separatrices"};
    args.insert(args.end(), extra.begin(), extra.end());
    const Result r = run(args);
    EXPECT_EQ(r.code, 0) << r.err << r.out;
    return csvPoints(csv);
  };
  const auto points = topology({});
  EXPECT_GT(points.size(), 6u);  // the saddles between the rollers and the outer vortices
  EXPECT_EQ(pointsInRollers(points), 0);
  // Without the file's mask the roller nodes' rigid rotation is a centre at each axis.
  EXPECT_EQ(pointsInRollers(topology({"--ignore-file-arrays"})), 6);
}

TEST_F(SnapshotAnalysisTest, LicOfTheSixRollMillDrawsTheRollersInTheMaskColour) {
  const fs::path vti = sixRollMillSnapshot();
  const fs::path png = dir_ / "lic.png";
  const Result r = run({"lic", vti.string(), "-a", "velocity", "-o", png.string(),
                        "--resolution", "400"});
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  const TextureRect t = textureRect(r.out);
  ASSERT_GT(t.right, t.left) << r.out;
  const fluidviz::RgbaImage image = fluidviz::testing::readPngImage(png);
  // The texture spans the grid's nodes: x in [dx/2, 2 - dx/2], y likewise (row 0 at the top).
  const double dx = 2.0 / 96, lo = dx / 2, hi = 2.0 - dx / 2;
  const int width = t.right - t.left, height = t.bottom - t.top;
  int checked = 0, off = 0;
  for (int py = t.top; py < t.bottom; ++py)
    for (int px = t.left; px < t.right; ++px) {
      const double x = lo + (px - t.left + 0.5) * (hi - lo) / width;
      const double y = hi - (py - t.top + 0.5) * (hi - lo) / height;
      for (const auto& c : rollerCentres())
        if (std::hypot(x - c[0], y - c[1]) < 0.8 * kRollerRadius) {
          ++checked;
          const auto p = image.pixel(px, py);
          // mask_color 0.75 grey: 191 in 8 bits, 1 level of rounding.
          for (int k = 0; k < 3; ++k) off += std::abs(int(p[k]) - 191) > 1;
        }
    }
  EXPECT_GT(checked, 6 * 300);  // pi (0.8 x 0.075 m x 200 px/m)^2 = 450 px per roller
  EXPECT_EQ(off, 0);
}

// Pixels of the masked grey (kMaskedGrey, 0.75: 191 in 8 bits, 1 level of rounding).
int maskedGreyPixels(const fluidviz::RgbaImage& image) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto p = image.pixel(x, y);
      n += std::abs(int(p[0]) - 191) <= 1 && std::abs(int(p[1]) - 191) <= 1 &&
           std::abs(int(p[2]) - 191) <= 1;
    }
  return n;
}

// A field picture draws a triangle holding a masked node in the masked grey: the six discs of
// radius r in grey, grown by up to one cell diagonal (dx sqrt 2). Before, the speed picture
// showed the rollers' rigid rotation and no grey at all.
void expectSixGreyRollers(const fluidviz::RgbaImage& image, double pxPerMetre) {
  const double dx = 2.0 / 96, r = kRollerRadius * pxPerMetre;
  const double grow = std::sqrt(2.0) * dx * pxPerMetre;
  const int grey = maskedGreyPixels(image);
  EXPECT_GE(grey, 6 * M_PI * r * r * 0.95);
  EXPECT_LE(grey, 6 * M_PI * (r + grow) * (r + grow));
}

TEST_F(SnapshotAnalysisTest, StreamlinesOverTheSpeedDrawTheRollersInTheMaskColour) {
  const fs::path vti = sixRollMillSnapshot();
  const fs::path png = dir_ / "lines.png";
  const Result r = run({"streamlines", vti.string(), "-a", "velocity", "-o",
                        (dir_ / "lines.vtp").string(), "--seeds", "grid:8,8", "--png", png.string(),
                        "--width", "400"});
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  expectSixGreyRollers(fluidviz::testing::readPngImage(png), 400 / 2.0);
  // Lines that reach a roller end there as expected: counted, not warned about as NaN data.
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(\d+ lines end at masked nodes)"))) << r.out;
}

TEST_F(SnapshotAnalysisTest, TheRunsSpeedPictureDrawsTheRollersInTheMaskColour) {
  runExample("six_roll_mill", ".vti",
             {"lbm.resolution=96", "lbm.end_time=3", "output.images[0].width=400",
              "output.images[0].height=400", "output.images[0].title=", "output.images[0].padding=0",
              "output.images[0].scalar_bar=false"});
  const fluidviz::RgbaImage image =
      fluidviz::testing::readPngImage(dir_ / "six_roll_mill" / "six_roll_mill_speed.png");
  expectSixGreyRollers(image, image.width / 2.0);  // the field fills the picture: 2 m wide
}

TEST_F(SnapshotAnalysisTest, TankWritesItsPressurePictureAndResamplesWithItsOwnH) {
  const fs::path vtp = tankSnapshot(true);
  EXPECT_TRUE(fs::exists(dir_ / "hydrostatic_tank" / "hydrostatic_tank_pressure.png"));
  const fs::path grid = dir_ / "grid.vti";
  const Result r = run({"resample", vtp.string(), "-o", grid.string(), "--threads", "2"});
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("h = 0.05 m"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("m/rho from arrays 'mass' and 'density'"), std::string::npos) << r.out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(particle spacing s = ([0-9.e-]+) m)")));
  EXPECT_NEAR(std::stod(m[1]), 0.025, 0.025 * 0.01);  // (m / rho)^(1/2), rho within 1% of rho0

  // The colour field inside the water (more than 2h = 0.1 m from the walls and the surface).
  vtkSmartPointer<vtkImageData> image = fluidviz::readImageData(grid);
  vtkDataArray* color = image->GetPointData()->GetArray("color");
  ASSERT_NE(color, nullptr);
  double lowest = 1e9, highest = 0;
  for (vtkIdType n = 0; n < image->GetNumberOfPoints(); ++n) {
    const double* x = image->GetPoint(n);
    if (x[0] < 0.1 || x[0] > 0.9 || x[1] < 0.1 || x[1] > 0.4) continue;
    lowest = std::min(lowest, color->GetComponent(n, 0));
    highest = std::max(highest, color->GetComponent(n, 0));
  }
  EXPECT_GT(lowest, 0.98);
  EXPECT_LT(highest, 1.02);
}

TEST_F(SnapshotAnalysisTest, LicMasksTheNodesAResampledGridHasNoParticlesFor) {
  const fs::path vtp = tankSnapshot();
  const fs::path grid = dir_ / "grid.vti", png = dir_ / "lic.png";
  Result r = run({"resample", vtp.string(), "-o", grid.string(), "--empty-value", "1",
                  "--padding", "0.3", "--threads", "2"});
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  r = run({"lic", grid.string(), "-a", "velocity", "-o", png.string(), "--resolution", "300"});
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  const TextureRect t = textureRect(r.out);
  ASSERT_GT(t.right, t.left) << r.out;
  const fluidviz::RgbaImage image = fluidviz::testing::readPngImage(png);
  // The grid reaches 0.3 m above the top particles (y = 0.49 m), the kernel 2h = 0.1 m: its top
  // 10% (0.11 m) has no particle support.
  int checked = 0, off = 0;
  const int rows = static_cast<int>(0.1 * (t.bottom - t.top));
  for (int py = t.top; py < t.top + rows; ++py)
    for (int px = t.left; px < t.right; ++px, ++checked) {
      const auto p = image.pixel(px, py);
      for (int k = 0; k < 3; ++k) off += std::abs(int(p[k]) - 191) > 1;
    }
  EXPECT_GT(checked, 1000);
  EXPECT_EQ(off, 0);
}

}  // namespace
