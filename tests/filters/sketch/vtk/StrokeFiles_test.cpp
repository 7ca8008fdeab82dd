// Stroke files (filters/sketch/vtk/StrokeFiles.h): an .svg path of lines, a horizontal and a
// vertical line, a cubic Bezier (its midpoint (p0 + 3 p1 + 3 p2 + p3) / 8 to 1e-15) and a close,
// and a relative path with implicit linetos, read with y flipped in the viewBox and the
// data-speed attribute; the spiral drawn as a .vtp polyline
// (examples/sketch/spiral.vtp, made from spiral.csv by tests/fuzz/tools/make_stroke_seeds.py)
// reads as the same stroke as its CSV (points to 1e-12 m, speed exactly); the speed comes from
// the cell-data array "speed", else the point-data one, else is 1 m/s; hostile files are refused
// with a FileError naming the file and the problem.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "fieldviz/io/FileError.h"
#include "filters/sketch/vtk/StrokeFiles.h"

namespace fluidviz::sketch {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = FLUIDVIZ_SOURCE_DIR;

// An ASCII .vtp of 5 points (0, 0.3), (0.5, 0.3), (0.995, 0.3), (0, 0.7), (0.995, 0.7) with the
// given line connectivity and offsets and extra <CellData> / <PointData> content.
std::string strokeVtp(const std::string& connectivity, const std::string& offsets,
                      const std::string& cellData = "", const std::string& pointData = "") {
  return R"(<?xml version="1.0"?>
<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian" header_type="UInt32">
  <PolyData>
    <Piece NumberOfPoints="5" NumberOfVerts="0" NumberOfLines="2" NumberOfStrips="0" NumberOfPolys="0">
      <PointData>)" + pointData + R"(</PointData>
      <CellData>)" + cellData + R"(</CellData>
      <Points>
        <DataArray type="Float64" Name="Points" NumberOfComponents="3" format="ascii">
          0 0.3 0 0.5 0.3 0 0.995 0.3 0 0 0.7 0 0.995 0.7 0
        </DataArray>
      </Points>
      <Lines>
        <DataArray type="Int64" Name="connectivity" format="ascii">)" + connectivity +
         R"(</DataArray>
        <DataArray type="Int64" Name="offsets" format="ascii">)" + offsets + R"(</DataArray>
      </Lines>
    </Piece>
  </PolyData>
</VTKFile>
)";
}

std::string speedArray(const std::string& values, int components = 1) {
  return R"(<DataArray type="Float64" Name="speed" NumberOfComponents=")" +
         std::to_string(components) + R"(" format="ascii">)" + values + "</DataArray>";
}

class StrokeFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fluidviz_stroke_files_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  /// The message of the FileError reading `file` throws; empty if it reads.
  static std::string refusal(const fs::path& file) {
    try {
      readStrokeFile(file);
    } catch (const FileError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

TEST_F(StrokeFiles, SpiralVtpReadsAsItsCsv) {
  const std::vector<Stroke> csv = readStrokeFile(kSource / "examples/sketch/spiral.csv");
  const std::vector<Stroke> vtp = readStrokeFile(kSource / "examples/sketch/spiral.vtp");
  ASSERT_EQ(vtp.size(), csv.size());
  ASSERT_EQ(vtp[0].points.size(), csv[0].points.size());
  EXPECT_EQ(vtp[0].speed, csv[0].speed);
  for (std::size_t k = 0; k < csv[0].points.size(); ++k)
    EXPECT_LT((vtp[0].points[k] - csv[0].points[k]).norm(), 1e-12) << k;
}

TEST_F(StrokeFiles, SpeedFromCellDataElsePointDataElseOne) {
  const std::string lines = "0 1 2 3 4", offsets = "3 5";
  const auto cell = readStrokeFile(write("cell.vtp", strokeVtp(lines, offsets, speedArray("0.02 0.06"))));
  ASSERT_EQ(cell.size(), 2u);
  EXPECT_EQ(cell[0].speed, 0.02);
  EXPECT_EQ(cell[1].speed, 0.06);
  EXPECT_EQ(cell[0].points.size(), 3u);
  EXPECT_EQ(cell[1].points[1], Vec3(0.995, 0.7, 0));
  const auto point = readStrokeFile(
      write("point.vtp", strokeVtp(lines, offsets, "", speedArray("-1 -1 -1 2.5 2.5"))));
  EXPECT_EQ(point[0].speed, -1.0);
  EXPECT_EQ(point[1].speed, 2.5);
  const auto none = readStrokeFile(write("none.vtp", strokeVtp(lines, offsets)));
  EXPECT_EQ(none[0].speed, kDefaultStrokeSpeed);
  EXPECT_EQ(none[1].speed, 1.0);
}

TEST_F(StrokeFiles, HostileFilesAreRefusedNamingTheFileAndTheProblem) {
  const std::string lines = "0 1 2 3 4", offsets = "3 5";
  const struct {
    std::string name, text, message;
  } cases[] = {
      {"garbage.vtp", "not xml at all", ""},
      {"varying.vtp", strokeVtp(lines, offsets, "", speedArray("1 1 2 3 3")),
       "line 1: point-data speed 2 at point 2 differs from 1"},
      {"nan.vtp", strokeVtp(lines, offsets, speedArray("nan 1")), "line 1: speed is nan"},
      {"two.vtp", strokeVtp(lines, offsets, speedArray("1 1 1 1", 2)),
       "cell-data array 'speed' must be numeric with 1 component"},
      {"count.vtp", strokeVtp(lines, offsets, "", speedArray("1 1 1")),
       "\"speed\""},
      {"index.vtp", strokeVtp("0 1 7 3 4", offsets), ""},
      {"nolines.vtp", strokeVtp("", ""), ""},
      {"strokes.txt", "stroke,x,y,speed\n1,0,0,1\n1,1,0,1\n", "is not a stroke file"},
  };
  for (const auto& c : cases) {
    const fs::path file = write(c.name, c.text);
    const std::string message = refusal(file);
    EXPECT_NE(message.find(file.string()), std::string::npos) << c.name << ": " << message;
    EXPECT_NE(message.find(c.message), std::string::npos) << c.name << ": " << message;
    RecordProperty(c.name, message);
  }
  EXPECT_NE(refusal(dir_ / "missing.vtp").find("missing.vtp"), std::string::npos);
  // Particles (vertices), no lines.
  EXPECT_NE(refusal(kSource / "tests/fuzz/corpus/vtp_reader/2d_ascii_none.vtp")
                .find("2d_ascii_none.vtp: has no polylines (line cells)"),
            std::string::npos);
}

std::string svgOf(const std::string& paths, const std::string& svgAttributes =
                                                  R"(viewBox="0 0 1 1")") {
  return R"(<?xml version="1.0"?>
<svg xmlns="http://www.w3.org/2000/svg" )" + svgAttributes + ">\n" + paths + "\n</svg>\n";
}

TEST_F(StrokeFiles, SvgPathsBecomeStrokesWithYUpInTheViewBox) {
  const auto strokes = readStrokeFile(write("drawing.svg", svgOf(
      R"(<path data-speed="0.05" d="M 0.1 0.9 L 0.5 0.9 H 0.9 V 0.5 C 0.9 0.3 0.7 0.1 0.5 0.1 z"/>
         <path d='m0.2,0.5 l0.1,0 0.1,0'/>)")));
  ASSERT_EQ(strokes.size(), 2u);
  const Stroke& a = strokes[0];
  EXPECT_EQ(a.speed, 0.05);
  ASSERT_EQ(a.points.size(), 4u + (kSvgCurveSegments - 1) + 1 + 1);
  EXPECT_LT((a.points[0] - Vec3(0.1, 0.1, 0)).norm(), 1e-15);
  EXPECT_LT((a.points[2] - Vec3(0.9, 0.1, 0)).norm(), 1e-15);
  EXPECT_LT((a.points[3] - Vec3(0.9, 0.5, 0)).norm(), 1e-15);
  // t = 1/2 of the cubic, 8 of its 16 segments in: ((0.9 + 2.7 + 2.1 + 0.5) / 8, 1 - 1.8 / 8).
  EXPECT_LT((a.points[3 + kSvgCurveSegments / 2] - Vec3(0.775, 0.775, 0)).norm(), 1e-15);
  EXPECT_LT((a.points[a.points.size() - 2] - Vec3(0.5, 0.9, 0)).norm(), 1e-15);
  EXPECT_LT((a.points.back() - Vec3(0.1, 0.1, 0)).norm(), 1e-15);  // z: back to the start
  const Stroke& b = strokes[1];
  EXPECT_EQ(b.speed, kDefaultStrokeSpeed);
  ASSERT_EQ(b.points.size(), 3u);
  EXPECT_LT((b.points[2] - Vec3(0.4, 0.5, 0)).norm(), 1e-15);
}

TEST_F(StrokeFiles, HostileSvgIsRefusedNamingTheFileAndTheProblem) {
  const struct {
    std::string name, text, message;
  } cases[] = {
      {"arc.svg", svgOf(R"(<path d="M 0 0 A 1 1 0 0 1 1 1"/>)"), "path 1: path command 'A' is not supported"},
      {"nobox.svg", svgOf(R"(<path d="M 0 0 L 1 1"/>)", R"(width="10")"), "has no viewBox"},
      {"badbox.svg", svgOf(R"(<path d="M 0 0 L 1 1"/>)", R"(viewBox="0 0 0 1")"), "viewBox"},
      {"moved.svg", svgOf(R"x(<g transform="scale(2)"><path d="M 0 0 L 1 1"/></g>)x"),
       "has a transform attribute"},
      {"nomove.svg", svgOf(R"(<path d="L 1 1 L 0 0"/>)"), "does not start with a moveto"},
      {"text.svg", svgOf(R"(<path d="M 0 0 L 1 "/>)"), "path 1: expected a number at character 11"},
      {"inf.svg", svgOf(R"(<path d="M 1e999 0 L 1 1"/>)"), "is not finite"},
      {"number.svg", svgOf(R"(<path d="M 0 0 z 1 1"/>)"), "a number where a path command is due"},
      {"speed.svg", svgOf(R"(<path data-speed="fast" d="M 0 0 L 1 1"/>)"),
       "path 1: data-speed \"fast\" is not a finite number"},
      {"empty.svg", svgOf(R"(<rect width="1" height="1"/>)"), "has no <path> with path data"},
      {"html.svg", "<html><body>not a drawing</body></html>", "is not an SVG file"},
  };
  for (const auto& c : cases) {
    const fs::path file = write(c.name, c.text);
    const std::string message = refusal(file);
    EXPECT_NE(message.find(file.string()), std::string::npos) << c.name << ": " << message;
    EXPECT_NE(message.find(c.message), std::string::npos) << c.name << ": " << message;
  }
}

}  // namespace
}  // namespace fluidviz::sketch
