// Issue 15, defects 6-8 and --units: the messages and labels of the fluidviz commands.
// 6: isosurface of a 2D grid prints nothing through VTK, and sizes carry the length unit in force.
// 7: a slice of a 3D field is coloured by its in-plane speed |v_xy| = sqrt(vx^2 + vy^2), the
//    speed LIC and streamlines integrate, and the legend says so.
// 8: every error reads "fluidviz <command>: error: ..."; the LIC NaN error names --mask-speed on
//    the command line and mask_speed in a scene.
// --units: the option, else the file's field-data string "length_unit", else m.
#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkXMLImageDataWriter.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <regex>
#include <string>
#include <vector>

#include "apps/fluidviz/FlowCommandSupport.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/lic/LineIntegralConvolution.h"
#include "tests/apps/fluidviz/CliTestSupport.h"
#include "tests/fieldviz/io/IoTestSupport.h"
#include "tests/support/PngFiles.h"

namespace fs = std::filesystem;

namespace fluidviz {
namespace {

using test::Result;
using test::run;

// n x n x nz nodes, spacing h = 2 / (n - 1), over [-1, 1]^2 x [0, (nz - 1) h] with velocity f(p),
// a scalar density = 1 and r2 = x^2 + y^2 (+ (z - zc)^2 in 3D, zc the middle height).
FieldSet field(int n, int nz, const std::function<Vec3(const Vec3&)>& f) {
  FieldSet set;
  set.grid.dims = {n, n, nz};
  set.grid.origin = {-1, -1, 0};
  const double h = 2.0 / (n - 1), zc = (nz - 1) * h / 2;
  set.grid.spacing = {h, h, h};
  VectorField v{"velocity", set.grid, {}};
  ScalarField r2{"r2", set.grid, {}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3 p = set.grid.position(i, j, k);
        v.values.push_back(f(p));
        r2.values.push_back(p.x() * p.x() + p.y() * p.y() + (p.z() - zc) * (p.z() - zc));
      }
  set.add(v);
  set.add(ScalarField{"density", set.grid, std::vector<double>(set.grid.nodeCount(), 1.0)});
  set.add(r2);
  return set;
}

// Rotation about z plus a strong uniform vz = 5: |v| >= 5 everywhere, |v_xy| = r.
Vec3 swirl(const Vec3& p) { return {-p.y(), p.x(), 5.0}; }
Vec3 rigidRotation(const Vec3& p) { return {-p.y(), p.x(), 0.0}; }

// The numbers of `pattern`'s groups in `text`.
std::vector<double> numbers(const std::string& text, const std::string& pattern) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(pattern))) {
    ADD_FAILURE() << "no '" << pattern << "' in: " << text;
    return {};
  }
  std::vector<double> v;
  for (std::size_t g = 1; g < m.size(); ++g) v.push_back(std::stod(m[g]));
  return v;
}

class CliMessages : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fluidviz_msg_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The set as a .vti without active scalars (as ParaView and other writers leave many files:
  // defect 6 shows only then), with the field-data string array length_unit = `unit` unless
  // empty.
  std::string input(const std::string& name, const FieldSet& set, const std::string& unit = "") {
    const fs::path p = dir_ / name;
    vtkSmartPointer<vtkImageData> image = toImageData(set);
    image->GetPointData()->SetActiveAttribute(-1, vtkDataSetAttributes::SCALARS);
    if (!unit.empty()) {
      vtkNew<vtkStringArray> units;
      units->SetName("length_unit");
      units->InsertNextValue(unit);
      image->GetFieldData()->AddArray(units);
    }
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(image);
    writer->SetFileName(p.c_str());
    EXPECT_EQ(writer->Write(), 1);
    return p.string();
  }
  std::string out(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

// ---- 6: isosurface ----------------------------------------------------------------------------

// r2 = 0.25 on a 41 x 41 grid over [-1, 1]^2 is the circle of radius 0.5: length pi less the
// chord error of the inscribed isoline polygon (h = 0.05: measured 3.5e-3; tolerance 6e-3).
TEST_F(CliMessages, IsolinesOfA2DGridPrintNoVtkMessageAndTheirLengthInMetres) {
  const std::string f = input("r2.vti", field(41, 1, rigidRotation));
  testing::VtkOutputCounter vtkOutput;
  const Result r = run({"isosurface", f, "-a", "r2", "--value", "0.25", "-o", out("c.vtp"),
                        "--png", out("c.png")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(vtkOutput.count(), 0) << "VTK printed: " << vtkOutput.last();
  EXPECT_EQ(r.err, "");
  const auto length =
      numbers(r.out, R"(isolines: \d+ segments, \d+ points, length ([0-9.e+-]+) m\n)");
  ASSERT_EQ(length.size(), 1u);
  EXPECT_NEAR(length[0], std::numbers::pi, 6e-3);
}

TEST_F(CliMessages, IsosurfaceSizesUseTheUnitOfTheFileOrOfUnits) {
  const std::string cells = input("cells.vti", field(41, 1, rigidRotation), "cells");
  Result r = run({"isosurface", cells, "-a", "r2", "--value", "0.25", "-o", out("c.vtp")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find(" cells\n"), std::string::npos) << r.out;
  r = run({"isosurface", cells, "-a", "r2", "--value", "0.25", "-o", out("c.vtp"), "--units",
           "mm"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find(" mm\n"), std::string::npos) << "the option overrides the file: " << r.out;
  // 3D: the sphere r = 0.5 (10 h); area 4 pi r^2 = pi, volume 4/3 pi r^3 = pi / 6. The
  // triangulation cuts inside the sphere: measured 0.4 % and 0.75 % low; tolerances 1 % and 1.5 %.
  const std::string ball = input("ball.vti", field(41, 41, rigidRotation), "deg");
  r = run({"isosurface", ball, "-a", "r2", "--value", "0.25", "-o", out("s.vtp")});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto m =
      numbers(r.out, R"(area ([0-9.e+-]+) deg\^2, enclosed volume ([0-9.e+-]+) deg\^3\n)");
  ASSERT_EQ(m.size(), 2u);
  EXPECT_NEAR(m[0], std::numbers::pi, 0.01 * std::numbers::pi);
  EXPECT_NEAR(m[1], std::numbers::pi / 6, 0.015 * std::numbers::pi / 6);
}

// ---- --units -----------------------------------------------------------------------------------

TEST_F(CliMessages, UnitsOutsideTheAllowedNamesAreRefusedNamingTheOption) {
  const std::string f = input("r2.vti", field(21, 1, rigidRotation));
  for (const std::string bad : {"", "a b", "0123456789abcdefghij"}) {
    const Result r = run({"isosurface", f, "-a", "r2", "--value", "0.25", "-o", out("c.vtp"),
                          "--units", bad});
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("fluidviz isosurface: error: --units is '" + bad + "'"),
              std::string::npos)
        << r.err;
  }
  const std::vector<std::vector<std::string>> others = {
      {"lic", f, "-a", "velocity", "-o", out("l.png")},
      {"streamlines", f, "-a", "velocity", "-o", out("s.vtp")},
      {"topology", f, "-a", "velocity", "-o", out("t.vtp")}};
  for (std::vector<std::string> args : others) {
    args.insert(args.end(), {"--units", "a b"});
    const Result r = run(args);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("fluidviz " + args[0] + ": error: --units is 'a b'; allowed: 1 to 16 "
                          "letters, digits or _^/-.", 0),
              0u)
        << r.err;
  }
  for (const char* written : {"c.vtp", "l.png", "s.vtp", "t.vtp"})
    EXPECT_FALSE(fs::exists(dir_ / written)) << "bad input must not write " << written;
  const std::string odd = input("odd.vti", field(21, 1, rigidRotation), "a b");
  const Result r = run({"lic", odd, "-a", "velocity", "-o", out("l.png")});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("length_unit"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(odd), std::string::npos) << r.err;
}

// ---- 7: in-plane speed of slices ---------------------------------------------------------------

TEST_F(CliMessages, SpeedOfASliceIsTheInPlaneMagnitudeAndItsLegendSaysSo) {
  const std::string f = input("swirl.vti", field(21, 3, swirl));
  const app::FlowInput in = app::readFlowInput({f, "velocity", "z=1", std::nullopt, {}});
  const app::ColourScalar speed = app::colourScalar(in, "speed");
  EXPECT_EQ(speed.legendTitle, "in-plane speed |v_xy| (m/s)");
  ASSERT_EQ(speed.field.values.size(), 21u * 21u);
  for (std::size_t n = 0; n < speed.field.values.size(); ++n) {
    const Vec3 p = speed.field.grid.position(static_cast<int>(n % 21), static_cast<int>(n / 21));
    EXPECT_NEAR(speed.field.values[n], std::hypot(p.x(), p.y()), 1e-12) << "node " << n;
  }
  // A 2D field: the full |v|.
  const std::string flat = input("flat.vti", field(21, 1, rigidRotation), "mm");
  const app::FlowInput in2 = app::readFlowInput({flat, "velocity", "", std::nullopt, {}});
  EXPECT_EQ(app::colourScalar(in2, "speed").legendTitle, "speed |v| (mm/s)");
  EXPECT_EQ(app::colourScalar(in2, "speed", "px").legendTitle, "speed |v| (px/s)");
}

// Issue 15: slices normal to x and y, at a coordinate, on a plane; their speed is in-plane too.
// swirl = (-y, x, 5) on x, y in [-1, 1], z in [0, 0.2], spacing 0.1: each slice is known exactly.
TEST_F(CliMessages, SlicesOnEveryAxisAndPlaneHaveTheirInPlaneComponents) {
  const std::string f = input("swirl.vti", field(21, 3, swirl));
  const auto read = [&](const std::string& slice, const std::string& crop = "") {
    return app::readFlowInput({f, "velocity", slice, std::nullopt, {}, "", crop});
  };
  const app::FlowInput x = read("x=20");  // x = 1: axes (y, z), components (vy, vz) = (1, 5)
  ASSERT_EQ(x.velocity.grid.dims, (std::array<int, 3>{21, 3, 1}));
  EXPECT_NEAR((x.velocity.values[5] - Vec3(1.0, 5.0, x.velocity.grid.position(5, 0).x() * -1)).norm(),
              0, 1e-12);
  EXPECT_EQ(app::colourScalar(x, "speed").legendTitle, "in-plane speed |v_xy| (m/s)");
  EXPECT_NEAR(app::colourScalar(x, "speed").field.values[7], std::hypot(1.0, 5.0), 1e-12);
  const app::FlowInput y = read("y@0.05");  // between two layers: (vx, vz) = (-0.05, 5)
  EXPECT_NEAR((y.velocity.values[3] - Vec3(-0.05, 5.0, y.velocity.grid.position(3, 0).x())).norm(),
              0, 1e-12);
  const app::FlowInput p = read("plane:0,0,0.1,0,0,1");  // the z layer 1: e1 = x, e2 = y
  EXPECT_TRUE(p.mask.empty());
  for (std::size_t n = 0; n < p.velocity.values.size(); n += 37) {
    const Vec3 q = p.velocity.grid.position(static_cast<int>(n % p.velocity.grid.dims[0]),
                                            static_cast<int>(n / p.velocity.grid.dims[0]));
    EXPECT_NEAR((p.velocity.values[n] - Vec3(-q.y(), q.x(), 5.0)).norm(), 0, 1e-12) << n;
  }
  const app::FlowInput c = read("z=1", "-0.5,0.5,0,1");
  EXPECT_EQ(c.velocity.grid.dims, (std::array<int, 3>{11, 11, 1}));
  EXPECT_DOUBLE_EQ(c.velocity.grid.origin[0], -0.5);
  const auto message = [&](const std::string& slice, const std::string& crop = "") {
    try {
      read(slice, crop);
    } catch (const app::UsageError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("q=1").find("expected x=I, y=J or z=K (node index), x@X, y@Y or z@Z"),
            std::string::npos);
  EXPECT_NE(message("x=21").find("--slice is x=21, outside [0, 20]"), std::string::npos);
  EXPECT_NE(message("z@0.5").find("outside z in [0.000000, 0.200000]"), std::string::npos);
  EXPECT_NE(message("z=1", "0.5,2,0,1").find("reaches outside the grid's [-1.000000, 1.000000]"),
            std::string::npos);
}

// The colour range the commands report is that of |v_xy| over [-1, 1]^2: [0, sqrt 2] (|v| would
// give [5, sqrt 27]).
TEST_F(CliMessages, LicAndStreamlinesOfASliceColourByInPlaneSpeed) {
  const std::string f = input("swirl.vti", field(21, 3, swirl));
  Result r = run({"lic", f, "-a", "velocity", "--slice", "z=1", "--resolution", "64", "-o",
                  out("l.png")});
  ASSERT_EQ(r.code, 0) << r.err;
  auto range = numbers(r.out, R"(colour range \[([0-9.e+-]+), ([0-9.e+-]+)\])");
  ASSERT_EQ(range.size(), 2u);
  EXPECT_NEAR(range[0], 0.0, 1e-9);
  EXPECT_NEAR(range[1], std::sqrt(2.0), 1e-5);
  for (const std::string background : {"speed", "lic"}) {
    r = run({"streamlines", f, "-a", "velocity", "--slice", "z=1", "-o", out("s.vtp"), "--png",
             out("s.png"), "--width", "64", "--underlay", background});
    ASSERT_EQ(r.code, 0) << r.err;
    range = numbers(r.out, R"(colour range \[([0-9.e+-]+), ([0-9.e+-]+)\])");
    ASSERT_EQ(range.size(), 2u);
    EXPECT_NEAR(range[0], 0.0, 1e-9) << background;
    EXPECT_NEAR(range[1], std::sqrt(2.0), 1e-5) << background;
  }
}

// ---- 8: one message form -----------------------------------------------------------------------

TEST_F(CliMessages, EveryErrorReadsFluidvizCommandErrorOnOneLine) {
  const std::string f = input("rot.vti", field(21, 1, rigidRotation));
  const std::string d3 = input("d3.vti", field(9, 3, swirl));
  const std::string none = out("none.vti");
  const std::vector<std::vector<std::string>> bad = {
      {"lic", f, "-o", out("a.png")},
      {"lic", f, "-a", "velocity"},
      {"lic", none, "-a", "velocity", "-o", out("a.png")},
      {"lic", f, "-a", "r2", "-o", out("a.png")},
      {"lic", d3, "-a", "velocity", "-o", out("a.png")},
      {"lic", d3, "-a", "velocity", "-o", out("a.png"), "--slice", "z=9"},
      {"lic", f, "-a", "velocity", "-o", out("a.png"), "--length", "0"},
      {"lic", f, "-a", "velocity", "-o", out("a.png"), "--bogus"},
      {"lic", f, f, "-a", "velocity", "-o", out("a.png")},
      {"streamlines", f, "-a", "velocity"},
      {"streamlines", f, "-o", out("a.vtp")},
      {"streamlines", f, "-a", "velocity", "-o", out("a.vtp"), "--seeds", "ring:3"},
      {"streamlines", f, "-a", "velocity", "-o", out("a.vtp"), "--step", "0"},
      {"streamlines", d3, "-a", "velocity", "-o", out("a.vtp"), "--slice", "z"},
      {"streamlines", f, "-a", "velocity", "-o", out("a.vtp"), "--width", "2"},
      {"topology", f, "-a", "velocity"},
      {"topology", f, "-a", "velocity", "-o", out("a.csv")},
      {"topology", none, "-a", "velocity", "-o", out("a.vtp")},
      {"topology", f, "-a", "velocity", "-o", out("a.vtp"), "--set", "cluster_radius=-1"},
      {"isosurface", f, "-a", "r2", "-o", out("a.vtp")},
      {"isosurface", f, "-a", "r2", "--value", "9", "-o", out("a.vtp")},
      {"isosurface", f, "-a", "velocity", "--value", "0", "-o", out("a.vtp")},
      {"isosurface", f, "--value", "0", "-o", out("a.vtp")},
      {"resample", out("none.vtp"), "-o", out("g.vti")},
      {"run"},
      {"run", out("none.json")},
      {"check", out("none.json")},
      {"sweep", out("none.json")},
  };
  const std::regex form(
      R"(fluidviz (lic|streamlines|topology|isosurface|resample|run|check|sweep): error: [^\n]+\n)");
  for (const auto& args : bad) {
    const Result r = run(args);
    std::string line;
    for (const auto& a : args) line += a + " ";
    EXPECT_EQ(r.code, 2) << line << "\n" << r.err;
    std::smatch m;
    EXPECT_TRUE(std::regex_match(r.err, m, form)) << line << "\nprinted: " << r.err;
    if (!r.err.empty() && m.size() > 1) {
      EXPECT_EQ(m[1], args[0]) << r.err;
    }
    EXPECT_EQ(r.err.find("error: fluidviz " + args[0]), std::string::npos)
        << "the command is named once: " << r.err;
  }
  const Result unknown = run({"frobnicate"});
  EXPECT_EQ(unknown.code, 2);
  EXPECT_EQ(unknown.err, "fluidviz: error: unknown command 'frobnicate' (see fluidviz --help)\n");
}

TEST_F(CliMessages, LicNaNErrorNamesTheOptionOnTheCommandLineAndTheKeyInAScene) {
  const FieldSet set = field(21, 1, [](const Vec3& p) {
    return p.x() > 0.5 ? Vec3::Constant(std::numeric_limits<double>::quiet_NaN()) : rigidRotation(p);
  });
  const std::string f = input("nan.vti", set);
  // Issue 15: the command line masks NaN nodes (they are drawn in the mask colour).
  const Result r = run({"lic", f, "-a", "velocity", "-o", out("n.png")});
  EXPECT_EQ(r.code, 0) << r.err;
  // The scene's LIC outputs call computeLic directly: its message names the scene key.
  try {
    lic::computeLic(set.vectors[0], lic::LicParams{});
    ADD_FAILURE() << "a NaN field must be refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("use mask_speed to mask them"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fluidviz

// ---- issue 16, defect 10: one meaning per option name, the format of -o, docs KEY -------------

namespace fluidviz {
namespace {

// --background is the backdrop (white|dark) in every command, as in lic; the picture under the
// lines or glyphs is --underlay. Old command lines are told the new name, and write nothing.
TEST_F(CliMessages, BackgroundIsTheBackdropEverywhereAndTheUnderlayIsUnderlay) {
  const std::string f = input("swirl.vti", field(21, 3, swirl));
  Result r = run({"streamlines", f, "-a", "velocity", "--slice", "z=1", "-o", out("s.vtp"),
                  "--png", out("s.png"), "--width", "64", "--background", "lic"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("the picture under the lines is --underlay lic"), std::string::npos) << r.err;
  r = run({"streamlines", f, "-a", "velocity", "--slice", "z=1", "-o", out("s.vtp"), "--png",
           out("s.png"), "--width", "64", "--background-color", "dark"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--background-color is now --background white|dark"), std::string::npos)
      << r.err;
  r = run({"topology", f, "-a", "velocity", "--slice", "z=1", "-o", out("t.vtp"), "--png",
           out("t.png"), "--background", "speed"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--underlay speed"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out("s.vtp")) || fs::exists(out("s.png")) || fs::exists(out("t.vtp")));
  // The new names work; a dark backdrop has a dark corner.
  r = run({"streamlines", f, "-a", "velocity", "--slice", "z=1", "-o", out("s.vtp"), "--png",
           out("s.png"), "--width", "64", "--underlay", "lic", "--background", "dark"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_LT(testing::readPngImage(out("s.png")).pixel(1, 1)[0], 80);
}

TEST_F(CliMessages, OutputExtensionChoosesPngOrJpegAndOthersAreRefused) {
  const std::string f = input("swirl.vti", field(21, 1, swirl));
  Result r = run({"lic", f, "-a", "velocity", "--resolution", "64", "-o", out("l.jpg")});
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream jpg(out("l.jpg"), std::ios::binary);
  char magic[3] = {};
  jpg.read(magic, 3);
  EXPECT_EQ(std::string(magic, 3), "\xFF\xD8\xFF");
  r = run({"lic", f, "-a", "velocity", "--resolution", "64", "-o", out("l.bmp")});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("l.bmp"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(".png, .jpg or .jpeg"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out("l.bmp")));
}

// `fluidviz docs KEY` printed the whole reference whatever KEY was.
TEST_F(CliMessages, DocsOfAKeyPrintThatKeyOnlyAndUnknownKeysAreRefused) {
  Result r = run({"docs", "lbm.reynolds"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("lbm.reynolds (", 0), 0u) << r.out;
  EXPECT_EQ(r.out.find("lbm.viscosity"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Reynolds"), std::string::npos) << r.out;
  r = run({"docs", "reynolds"});  // the last part of a key finds it
  EXPECT_NE(r.out.find("lbm.reynolds ("), std::string::npos) << r.out;
  r = run({"docs", "output.time_series"});  // the keys below
  EXPECT_NE(r.out.find("output.time_series.interval ("), std::string::npos) << r.out;
  r = run({"docs", "reynold"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no scene key 'reynold'; keys containing it:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("lbm.reynolds"), std::string::npos) << r.err;
  // --keys lists one key a line: as many as the reference's table has rows.
  r = run({"docs", "--keys"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Result all = run({"docs"});
  std::size_t keys = 0, rows = 0;
  for (std::size_t p = 0; (p = r.out.find('\n', p)) != std::string::npos; ++p) ++keys;
  for (std::size_t p = 0; (p = all.out.find("\n| `", p)) != std::string::npos; ++p) ++rows;
  EXPECT_GT(keys, 100u);
  EXPECT_EQ(keys, rows);
  EXPECT_NE(r.out.find("\nlbm.reynolds\n"), std::string::npos);
}

}  // namespace
}  // namespace fluidviz
