// fluidviz sketch: a strokes CSV becomes a .vti field (and a LIC picture), and a user's bad file
// or option is refused with exit code 2, naming the problem, with nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include <unistd.h>

#include "apps/fluidviz/Commands.h"
#include "fieldviz/core/Sampling.h"
#include "fieldviz/io/VtkXmlReaders.h"

namespace fluidviz {
namespace {

namespace fs = std::filesystem;

class SketchCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fluidviz_sketch_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    std::ostringstream circle;
    circle << "# a circle of radius 0.3 about (0.5, 0.5), counter-clockwise\nstroke,x,y,speed\n";
    for (int k = 0; k <= 72; ++k) {
      const double a = 2 * std::numbers::pi * k / 72;
      circle << "7," << 0.5 + 0.3 * std::cos(a) << "," << 0.5 + 0.3 * std::sin(a) << ",0.05\n";
    }
    write("circle.csv", circle.str());
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
  int run(std::vector<std::string> args) {
    out_.str("");
    err_.str("");
    return app::dispatch(args, out_, err_, false);
  }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
  std::ostringstream out_, err_;
};

// The circle's field: the drawn speed on the stroke, a centre within one cell of (0.5, 0.5).
TEST_F(SketchCommand, WritesTheFieldAndItsPictureAndListsTheCentre) {
  ASSERT_EQ(run({"sketch", file("circle.csv"), "--nodes", "41,41", "-o", file("f.vti"), "--png",
                 file("f.png")}), 0) << err_.str();
  const FieldSet set = readVti(dir_ / "f.vti");
  const VectorField* v = set.findVector("velocity");
  ASSERT_NE(v, nullptr);
  ASSERT_NE(set.findVector("projected_velocity"), nullptr);
  ASSERT_NE(set.findScalar("gvf_weight"), nullptr);
  // Top of the circle (0.5, 0.8): leftwards at the drawn speed.
  const Vec3 top = *sample(*v, Vec3(0.5, 0.8, 0));
  EXPECT_NEAR(top[0], -0.05, 0.003);
  EXPECT_NEAR(top[1], 0.0, 0.003);
  EXPECT_TRUE(fs::exists(dir_ / "f.png"));
  const std::string text = out_.str();
  const auto at = text.find("critical point: centre at (");
  ASSERT_NE(at, std::string::npos) << text;
  double x = 0, y = 0;
  std::istringstream(text.substr(at + 27)) >> x;
  std::istringstream(text.substr(text.find(", ", at) + 2)) >> y;
  const double cell = set.grid.spacing[0];
  EXPECT_LE(std::abs(x - 0.5), cell) << text;
  EXPECT_LE(std::abs(y - 0.5), cell) << text;
}

// The spiral drawn as a .vtp polyline (examples/sketch/spiral.vtp) gives the field of its CSV.
TEST_F(SketchCommand, VtpPolylinesGiveTheFieldOfTheSameCsv) {
  const fs::path examples = fs::path(FLUIDVIZ_SOURCE_DIR) / "examples/sketch";
  for (const char* in : {"spiral.csv", "spiral.vtp"})
    ASSERT_EQ(run({"sketch", (examples / in).string(), "--domain", "0,1,0,1", "--nodes", "33,33",
                   "-o", file(std::string(in) + ".vti")}),
              0)
        << err_.str();
  const FieldSet csv = readVti(dir_ / "spiral.csv.vti"), vtp = readVti(dir_ / "spiral.vtp.vti");
  const auto &a = csv.findVector("velocity")->values, &b = vtp.findVector("velocity")->values;
  ASSERT_EQ(a.size(), b.size());
  double worst = 0;
  for (std::size_t n = 0; n < a.size(); ++n) worst = std::max(worst, (a[n] - b[n]).norm());
  EXPECT_LT(worst, 1e-12);
}

TEST_F(SketchCommand, BadStrokesOrOptionsAreRefusedAndNothingIsWritten) {
  write("nocol.csv", "stroke,x,y\n1,0,0\n1,1,1\n");
  write("nan.csv", "stroke,x,y,speed\n1,0,0,1\n1,nan,1,1\n");
  write("back.csv", "stroke,x,y,speed\n1,0,0,1\n1,1,0,1\n2,0,1,1\n2,1,1,1\n1,0,2,1\n");
  write("speed.csv", "stroke,x,y,speed\n1,0,0,1\n1,1,0,2\n");
  write("point.csv", "stroke,x,y,speed\n1,0,0,1\n1,1,0,1\n2,0.5,0.5,1\n");
  write("half.csv", "stroke,x,y,speed\n1.5,0,0,1\n1.5,1,0,1\n");
  write("garbage.vtp", "<VTKFile type=\"PolyData\"> not closed");
  write("strokes.txt", "stroke,x,y,speed\n1,0,0,1\n1,1,0,1\n");
  const struct {
    std::vector<std::string> args;
    std::string message;
  } cases[] = {
      {{"sketch", file("nocol.csv")}, "has no column 'speed'"},
      {{"sketch", file("nan.csv")}, "data row 2: x is nan; expected a finite number"},
      {{"sketch", file("back.csv")}, "data row 5: stroke 1 comes back after another stroke"},
      {{"sketch", file("speed.csv")}, "data row 2: speed 2 differs from the stroke's 1"},
      {{"sketch", file("point.csv")}, "stroke 2: a stroke needs two distinct points"},
      {{"sketch", file("half.csv")}, "data row 1: stroke is 1.5; expected a whole number"},
      {{"sketch", file("garbage.vtp")}, "garbage.vtp"},
      {{"sketch", file("strokes.txt")}, "is not a stroke file: expected .csv"},
      {{"sketch", file("circle.csv"), "--nodes", "2,40"}, "--nodes 2,40: each must be"},
      {{"sketch", file("circle.csv"), "--sigma", "-1"}, "--sigma"},
      {{"sketch", file("circle.csv"), "--solver", "explicit", "--time-step", "5"},
       "--time-step is 5, above the explicit GVF stability limit"},
      {{"sketch", file("circle.csv"), "--solver", "explicit", "--max-iterations", "10"},
       "--max-iterations is 10: explicit GVF stopped there at residual"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = c.args;
    for (const char* a : {"-o", "out.vti", "--png", "out.png"}) args.push_back(a);
    args[args.size() - 3] = file("out.vti");
    args.back() = file("out.png");
    EXPECT_EQ(run(args), 2) << c.message << "\n" << err_.str();
    EXPECT_NE(err_.str().find(c.message), std::string::npos) << err_.str();
    EXPECT_NE(err_.str().find("fluidviz sketch: error:"), std::string::npos) << err_.str();
    if (c.args.size() == 2)  // a bad file: named
      EXPECT_NE(err_.str().find(c.args[1]), std::string::npos) << err_.str();
    EXPECT_FALSE(fs::exists(dir_ / "out.vti")) << c.message;
    EXPECT_FALSE(fs::exists(dir_ / "out.png")) << c.message;
  }
}

}  // namespace
}  // namespace fluidviz
