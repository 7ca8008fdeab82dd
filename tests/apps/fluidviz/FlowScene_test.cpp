// Scene outputs output.lic and output.streamlines: a roller turning in a closed box. Its
// streamlines must be closed loops around it (reason closed_loop, winding once, anticlockwise
// like the roller), the .vtp must carry the documented arrays, and the LIC picture must show the
// blend rule on the fluid, the mask colour on the roller and the lines where they were traced.
#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "apps/fluidviz/Commands.h"
#include "fieldviz/core/Sampling.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/render/LicPicture.h"
#include "filters/lic/LineIntegralConvolution.h"
#include "filters/streamlines/Streamline.h"
#include "filters/streamlines/vtk/StreamlinePolyData.h"
#include "tests/support/PngFiles.h"

namespace fs = std::filesystem;

namespace fluidviz {
namespace {

// Signed number of turns of a closed polyline around c (anticlockwise positive).
double windingNumber(const std::vector<Vec3>& loop, const Vec3& c) {
  double angle = 0;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Vec3 a = loop[k] - c, b = loop[(k + 1) % loop.size()] - c;
    angle += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
  }
  return angle / (2 * M_PI);
}

// A roller of radius 0.2 m at the centre of a 1 m box, 40 x 40 nodes, Re 10: 320 steps.
constexpr const char* kScene = R"({
  "name": "roller",
  "lbm": {"domain_size": [1, 1], "resolution": 40, "reynolds": 10, "lattice_velocity": 0.1,
          "rollers": [{"center": [0.5, 0.5], "radius": 0.2, "angular_velocity": 1.0}],
          "end_time": 4.0},
  "output": {
    "snapshots": 1, "images": [],
    "lic": [{"width": 160, "length": 10, "color_by": "speed", "lic_weight": 0.6,
             "mask_color": [0.0, 1.0, 1.0]}],
    "streamlines": [{"seeding": {"strategy": "line", "line_start": [0.75, 0.5, 0],
                                 "line_end": [0.82, 0.5, 0], "line_count": 3},
                     "integration": {"step": 0.2}, "line_color": [1, 0, 0],
                     "arrows": false, "draw_on": "lic"}]
  }})";

class FlowScene : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // ctest runs each test in its own process, possibly at the same time: one folder each.
    dir_ = fs::temp_directory_path() / ("fluidviz_flow_scene_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "roller.json") << kScene;
    std::ostringstream out, err;
    code_ = app::dispatch({"run", (dir_ / "roller.json").string(), "-o", (dir_ / "out").string()},
                          out, err, false);
    log_ = err.str();
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static inline fs::path dir_;
  static inline int code_ = -1;
  static inline std::string log_;
};

TEST_F(FlowScene, StreamlinesAreClosedAnticlockwiseLoopsAroundTheRoller) {
  ASSERT_EQ(code_, 0) << log_;
  vtkSmartPointer<vtkPolyData> poly = readVtp(dir_ / "out" / "roller_streamlines.vtp");
  ASSERT_EQ(poly->GetNumberOfLines(), 3);
  for (const char* name : {"speed", "integration_time"})
    EXPECT_NE(poly->GetPointData()->GetArray(name), nullptr) << name;
  const auto loops = streamlines::polylinePoints(poly);
  for (vtkIdType c = 0; c < 3; ++c) {
    EXPECT_EQ(poly->GetCellData()->GetArray("reason")->GetTuple1(c),
              static_cast<int>(streamlines::TerminationReason::closed_loop));
    // One turn round the roller's centre, in its sense of rotation; the loop stays in the fluid
    // between the roller (r = 0.2) and the walls.
    EXPECT_NEAR(windingNumber(loops[c], Vec3(0.5, 0.5, 0)), 1.0, 1e-9) << "line " << c;
    for (const Vec3& p : loops[c]) {
      EXPECT_GT((p - Vec3(0.5, 0.5, 0)).norm(), 0.2);
      EXPECT_LT(std::max(std::abs(p.x() - 0.5), std::abs(p.y() - 0.5)), 0.5);
    }
    // Closed: the end is within closing_distance (0.1 cell = 0.0025 m) plus a step of the start.
    EXPECT_LT((loops[c].back() - loops[c].front()).norm(), 0.0025 + 0.2 * 0.025) << "line " << c;
  }
}

// The picture against the rule, recomputed from the final snapshot: the same LIC texture (same
// parameters, deterministic), the same speed, the same roller mask.
TEST_F(FlowScene, LicPictureShowsBlendRuleMaskAndLines) {
  ASSERT_EQ(code_, 0) << log_;
  const RgbaImage png = fluidviz::testing::readPngImage(dir_ / "out" / "roller_lic_speed.png");
  const VectorField velocity = readVectorField(dir_ / "out/roller/roller_0001.vti", "velocity");
  lic::LicParams params;
  params.width = 160;
  params.length = 10;
  const lic::LicImage texture = lic::computeLic(velocity, params);
  const ScalarField speed = magnitude(velocity);
  // The scene's picture has the size renderLicPicture fits around a 160 px texture; find where
  // the texture sits from the same fitting.
  FieldImageParams picture;
  // The default title template and legend (pipeline/PictureText.h) at the end time, 4 s.
  picture.title = "roller: LIC coloured by speed (m/s), t = 4 s";
  picture.scalar_bar_title = "speed (m/s)";
  LicBlendParams blend;
  const LicPicture reference = renderLicPicture(texture.texture, {}, speed, picture, blend);
  ASSERT_EQ(png.width, reference.image.width);
  ASSERT_EQ(png.height, reference.image.height);
  const int left = static_cast<int>(reference.texture.left);
  const int top = static_cast<int>(reference.texture.top);
  // The texture covers the nodes' extent: cell centres 0.0125 ... 0.9875 m, 160 px.
  const Grid& px = texture.texture.grid;
  const auto pictureOf = [&](double x, double y) {  // world -> picture pixel of its texel
    const int i = static_cast<int>((x - velocity.grid.origin[0]) / px.spacing[0]);
    const int j = static_cast<int>((y - velocity.grid.origin[1]) / px.spacing[1]);
    return std::array<int, 4>{left + i, top + 159 - j, i, j};
  };
  const ColorMap& viridis = ColorMap::byName("viridis");
  const auto range = reference.range;
  // Fluid between the outer loop and the wall, away from the lines: the blend rule.
  int checked = 0;
  for (const auto& [x, y] : std::vector<std::array<double, 2>>{{0.93, 0.5}, {0.5, 0.07}, {0.1, 0.9}}) {
    const auto [px, py, i, j] = pictureOf(x, y);
    const Vec3 centre = texture.texture.grid.position(i, j);
    const double s = *sample(speed, centre);
    const ColorMap::Color expected = blendLicColor(
        viridis.map((s - range[0]) / (range[1] - range[0])),
        texture.texture.values[static_cast<std::size_t>(j) * 160 + i], 0.6);
    const auto p = png.pixel(px, py);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(p[k], 255.0 * std::clamp(expected[k], 0.0, 1.0), 1.0) << x << ", " << y;
    ++checked;
  }
  EXPECT_EQ(checked, 3);
  // The roller is masked: cyan.
  const auto [cx, cy, ci, cj] = pictureOf(0.5, 0.5);
  EXPECT_EQ(png.pixel(cx, cy), (std::array<std::uint8_t, 4>{0, 255, 255, 255}));
  // The lines pass through their seeds (0.75, 0.785, 0.82; y = 0.5): red there.
  for (double x : {0.75, 0.785, 0.82}) {
    const auto [px, py, i, j] = pictureOf(x, 0.5);
    const auto p = png.pixel(px, py);
    EXPECT_GE(p[0], 250) << "seed x = " << x;
    EXPECT_LE(p[1], 5) << "seed x = " << x;
  }
}

}  // namespace
}  // namespace fluidviz
