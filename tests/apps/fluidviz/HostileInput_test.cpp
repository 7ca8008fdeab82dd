// Hostile input to every fluidviz command that reads a user's file (issue 8; the table in
// docs/reliability.md lists these cases by name). Each case writes its input into in/ (a valid
// file from our writers, then cut, garbled or edited), runs the command line in-process and
// checks:
//   - exit code 2 (bad input);
//   - a message naming the file and the array or key, and saying what is wrong;
//   - that nothing was written: out/ stays empty and in/ holds only what the case wrote (no
//     temporary files left behind);
//   - that VTK printed nothing itself (its messages belong in ours).
// UntouchedInputsAreAccepted runs the same command lines on the files before damage, so each
// refusal is due to the damage, not to the command line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <vtkPolyData.h>

#include "fieldviz/io/VtkXmlWriters.h"
#include "filters/resample/vtk/ParticleSetVtk.h"
#include "tests/apps/fluidviz/CliTestSupport.h"
#include "tests/fieldviz/io/IoTestSupport.h"

namespace fs = std::filesystem;

namespace fluidviz {
namespace {

using test::Result;
using test::run;
using testing::readText;
using testing::writeText;

// ---- Inputs -------------------------------------------------------------------------------------

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// 21 x 21 nodes over [-1, 1]^2: velocity (-y, x) (a rotation) and density 1 + x / 10.
FieldSet rotation() {
  FieldSet set;
  set.grid.dims = {21, 21, 1};
  set.grid.origin = {-1, -1, 0};
  set.grid.spacing = {0.1, 0.1, 1};
  VectorField v{"velocity", set.grid, {}};
  ScalarField rho{"density", set.grid, {}};
  for (int j = 0; j < 21; ++j)
    for (int i = 0; i < 21; ++i) {
      const Vec3 p = set.grid.position(i, j);
      v.values.push_back(Vec3(-p.y(), p.x(), 0.0));
      rho.values.push_back(1.0 + 0.1 * p.x());
    }
  set.add(v);
  set.add(rho);
  return set;
}

// 12 x 12 particles 0.05 m apart, water (mass, density) turning about the origin.
particles::ParticleSet particles() {
  particles::ParticleSet ps;
  particles::ParticleScalars mass{"mass", {}}, density{"density", {}};
  particles::ParticleVectors velocity{"velocity", {}};
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 12; ++i) {
      const Vec3 p(0.05 * i, 0.05 * j, 0.0);
      ps.positions.push_back(p);
      mass.values.push_back(1000.0 * 0.05 * 0.05);
      density.values.push_back(1000.0);
      velocity.values.push_back(Vec3(-p.y(), p.x(), 0.0));
    }
  ps.scalars = {mass, density};
  ps.vectors = {velocity};
  return ps;
}

// A small cavity scene; `lbmExtra` goes into the lbm object, `top` at the top level.
std::string sceneText(const std::string& lbmExtra = "", const std::string& top = "") {
  return R"({ "name": "cav", )" + top + R"(
  "lbm": { "domain_size": [1, 1], "resolution": 16, "reynolds": 20, "lattice_velocity": 0.1,
           "walls": {"y_max": {"type": "moving_wall", "velocity": [1, 0]}},
           "end_time": 0.5 )" + lbmExtra + R"( },
  "output": { "snapshots": 1 } })";
}

// Sets (or adds) attribute `attribute` of the XML start tag that contains `inTag` (e.g. "<ImageData",
// "<Piece", "Name=\"velocity\""), looking only at the header (before any appended data).
std::string withAttribute(const std::string& xml, const std::string& inTag,
                          const std::string& attribute, const std::string& value) {
  const std::size_t headerEnd = std::min(xml.find("<AppendedData"), xml.size());
  const std::size_t at = xml.find(inTag);
  if (at == std::string::npos || at > headerEnd)
    throw std::logic_error("no tag with " + inTag + " in the header");
  const std::size_t tagStart = xml.rfind('<', at);
  const std::size_t tagEnd = xml.find('>', at);
  const std::size_t attr = xml.find(" " + attribute + "=\"", tagStart);
  if (attr == std::string::npos || attr > tagEnd) {  // absent: add it after the tag's name
    const std::size_t nameEnd = xml.find(' ', tagStart);
    return xml.substr(0, nameEnd) + " " + attribute + "=\"" + value + "\"" + xml.substr(nameEnd);
  }
  const std::size_t valueStart = attr + attribute.size() + 3;
  const std::size_t valueEnd = xml.find('"', valueStart);
  return xml.substr(0, valueStart) + value + xml.substr(valueEnd);
}

struct Edit {
  std::string inTag, attribute, value;
};

// An ImageData file in ASCII with one point-data array, as a script might write it.
std::string asciiVti(const std::string& wholeExtent, const std::string& arrayAttributes,
                     const std::string& values) {
  return "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
         "  <ImageData WholeExtent=\"" + wholeExtent + "\" Origin=\"0 0 0\" Spacing=\"1 1 1\">\n"
         "    <Piece Extent=\"" + wholeExtent + "\">\n"
         "      <PointData>\n"
         "        <DataArray Name=\"velocity\" " + arrayAttributes + " format=\"ascii\">" +
         values + "</DataArray>\n"
         "      </PointData>\n"
         "    </Piece>\n"
         "  </ImageData>\n"
         "</VTKFile>\n";
}

// rotation() as a legacy ASCII .vtk file (structured points), as ParaView's "Legacy VTK" writer
// or a script writes it; `edit` changes its lines before they are written.
std::string legacyVtkText(const std::function<void(std::vector<std::string>&)>& edit = {}) {
  const FieldSet set = rotation();
  std::vector<std::string> lines = {"# vtk DataFile Version 3.0", "rotation", "ASCII",
                                    "DATASET STRUCTURED_POINTS", "DIMENSIONS 21 21 1",
                                    "ORIGIN -1 -1 0", "SPACING 0.1 0.1 1", "POINT_DATA 441",
                                    "VECTORS velocity double"};
  for (const Vec3& v : set.vectors[0].values)
    lines.push_back(std::to_string(v.x()) + " " + std::to_string(v.y()) + " 0");
  lines.insert(lines.end(), {"SCALARS density double 1", "LOOKUP_TABLE default"});
  for (double rho : set.scalars[0].values) lines.push_back(std::to_string(rho));
  if (edit) edit(lines);
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

// ---- Cases --------------------------------------------------------------------------------------

// The folders of one case; every output of a command line points into out/.
struct Folders {
  fs::path in, out;
  std::string input(const std::string& name) const { return (in / name).string(); }
  std::string output(const std::string& name) const { return (out / name).string(); }

  std::string vti(const std::string& name, const FieldSet& set = rotation()) const {
    writeVti(set, in / name);
    return input(name);
  }
  std::string editedVti(const std::string& name, const std::vector<Edit>& edits) const {
    std::string xml = readText(vti(name));
    for (const Edit& e : edits) xml = withAttribute(xml, e.inTag, e.attribute, e.value);
    writeText(in / name, xml);
    return input(name);
  }
  std::string vtp(const std::string& name, const particles::ParticleSet& ps = particles()) const {
    writeVtp(resample::toPolyData(ps), in / name);
    return input(name);
  }
  std::string editedVtp(const std::string& name, const std::vector<Edit>& edits) const {
    std::string xml = readText(vtp(name));
    for (const Edit& e : edits) xml = withAttribute(xml, e.inTag, e.attribute, e.value);
    writeText(in / name, xml);
    return input(name);
  }
  std::string text(const std::string& name, const std::string& content) const {
    writeText(in / name, content);
    return input(name);
  }
  std::string legacyVtk(const std::string& name,
                        const std::function<void(std::vector<std::string>&)>& edit = {}) const {
    return text(name, legacyVtkText(edit));
  }
  std::string scene(const std::string& name = "scene.json",
                    const std::string& content = sceneText()) const {
    return text(name, content);
  }
};

using CommandLine = std::vector<std::string>;

// The command lines of every command, reading `input` and writing into out/.
CommandLine licLine(const Folders& f, const std::string& input) {
  return {"lic", input, "-a", "velocity", "-o", f.output("lic.png"), "--resolution", "60"};
}
CommandLine streamlinesLine(const Folders& f, const std::string& input) {
  return {"streamlines", input, "-a", "velocity", "-o", f.output("lines.vtp"), "--seeds",
          "line:-0.5,0,0.5,0,3"};
}
CommandLine topologyLine(const Folders& f, const std::string& input) {
  return {"topology", input, "-a", "velocity", "-o", f.output("points.vtp"), "--csv",
          f.output("points.csv")};
}
CommandLine isosurfaceLine(const Folders& f, const std::string& input) {
  return {"isosurface", input, "-a", "density", "--value", "1.02", "-o", f.output("iso.vtp")};
}
CommandLine resampleLine(const Folders& f, const std::string& input) {
  return {"resample", input, "-o", f.output("grid.vti")};
}
CommandLine runSceneLine(const Folders& f, const std::string& input) {
  return {"run", input, "-o", f.output("run")};
}
CommandLine checkLine(const Folders&, const std::string& input) { return {"check", input}; }
CommandLine sweepLine(const Folders& f, const std::string& input) {
  return {"sweep", input, "--param", "lbm.reynolds", "--from", "10", "--to", "20", "--steps", "2",
          "-o", f.output("sweep"), "--no-pictures"};
}

struct HostileCase {
  std::string name;
  /// Writes the inputs into in/ and returns the command line.
  std::function<CommandLine(const Folders&)> setUp;
  /// Fragments the message must contain; "{in}" and "{out}" stand for the two folders.
  std::vector<std::string> expected;
};

std::string cutInHalf(const Folders& f, const std::string& file) {
  writeText(file, readText(file).substr(0, readText(file).size() / 2));
  (void)f;
  return file;
}

std::string garbled(const std::string& file) {
  std::string bytes = readText(file);
  const std::size_t data = bytes.find("<AppendedData");
  if (data == std::string::npos) throw std::logic_error("no appended data in " + file);
  for (std::size_t n = data + 200; n < data + 400 && n < bytes.size(); ++n) bytes[n] = char(n * 37);
  writeText(file, bytes);
  return file;
}

// Scalar field with one non-finite node, at (i, j) = (12, 7).
FieldSet rotationWith(double bad, bool inVelocity) {
  FieldSet set = rotation();
  const std::size_t n = set.grid.index(12, 7);
  if (inVelocity)
    set.vectors[0].values[n].x() = bad;
  else
    set.scalars[0].values[n] = bad;
  return set;
}

particles::ParticleSet particlesWith(const std::string& what, double bad) {
  particles::ParticleSet ps = particles();
  if (what == "position") ps.positions[17].y() = bad;
  if (what == "mass") ps.scalars[0].values[17] = bad;
  if (what == "velocity") ps.vectors[0].values[17].x() = bad;
  return ps;
}

const std::string kHugeExtent = "0 100000 0 100000 0 100000";

std::vector<HostileCase> vtiCases() {
  using F = const Folders&;
  return {
      // -- damaged files
      {"VtiCutInHalf", [](F f) { return licLine(f, cutInHalf(f, f.vti("cut.vti"))); },
       {"file {in}/cut.vti is corrupt", "velocity"}},
      {"VtiCutInsideTheXmlHeader",
       [](F f) {
         const std::string file = f.vti("head.vti");
         writeText(file, readText(file).substr(0, 300));
         return streamlinesLine(f, file);
       },
       {"file {in}/head.vti is corrupt or truncated"}},
      {"VtiGarbledCompressedData", [](F f) { return topologyLine(f, garbled(f.vti("garbled.vti"))); },
       {"file {in}/garbled.vti is corrupt"}},
      {"VtiThatIsPlainText",
       [](F f) { return isosurfaceLine(f, f.text("notes.vti", "velocity = 3 m/s\n")); },
       {"file {in}/notes.vti is not a VTK XML file"}},
      {"VtiThatIsEmpty", [](F f) { return licLine(f, f.text("empty.vti", "")); },
       {"file {in}/empty.vti is not a VTK XML file"}},
      {"VtpGivenForVti",
       [](F f) {
         fs::rename(f.vtp("p.vtp"), f.in / "p.vti");
         return licLine(f, f.input("p.vti"));
       },
       {"file {in}/p.vti holds VTK XML PolyData, expected ImageData (.vti)"}},
      // -- array types and component counts
      {"VectorDeclaredWith4ComponentsOver3",
       [](F f) { return licLine(f, f.editedVti("nc4.vti", {{"Name=\"velocity\"", "NumberOfComponents", "4"}})); },
       {"file {in}/nc4.vti is corrupt", "velocity"}},
      {"VectorDeclaredWith2ComponentsOver3",
       [](F f) {
         return streamlinesLine(f, f.editedVti("nc2.vti", {{"Name=\"velocity\"", "NumberOfComponents", "2"}}));
       },
       {"file {in}/nc2.vti: array 'velocity' holds more values than the 441 tuples x 2 "
        "components of Float64"}},
      {"VectorWith4Components",
       [](F f) {
         return licLine(f, f.text("four.vti", asciiVti("0 1 0 1 0 0", "type=\"Float32\" NumberOfComponents=\"4\"",
                                                   "1 0 0 0 1 0 0 0 1 0 0 0 1 0 0 0")));
       },
       {"file {in}/four.vti: array 'velocity' has 4 components; a vector field needs 2 or 3"}},
      {"ScalarGivenAsVector",
       [](F f) {
         CommandLine c = topologyLine(f, f.vti("rot.vti"));
         c[3] = "density";
         return c;
       },
       {"file {in}/rot.vti: array 'density' has 1 component; a vector field needs 2 or 3"}},
      {"Int32DeclaredOverFloat64Data",
       [](F f) { return topologyLine(f, f.editedVti("int.vti", {{"Name=\"velocity\"", "type", "Int32"}})); },
       {"file {in}/int.vti: array 'velocity' holds more values than the 441 tuples x 3 "
        "components of Int32"}},
      {"Float32DeclaredOverFloat64Data",
       [](F f) { return licLine(f, f.editedVti("f32.vti", {{"Name=\"velocity\"", "type", "Float32"}})); },
       {"file {in}/f32.vti: array 'velocity' holds more values than the 441 tuples x 3 "
        "components of Float32"}},
      {"UnknownArrayType",
       [](F f) { return isosurfaceLine(f, f.editedVti("bogus.vti", {{"Name=\"density\"", "type", "Complex128"}})); },
       {"file {in}/bogus.vti", "array 'density' has type \"Complex128\"; allowed: Int8"}},
      {"MissingArray",
       [](F f) {
         CommandLine c = licLine(f, f.vti("rot.vti"));
         c[3] = "vel";
         return c;
       },
       {"file {in}/rot.vti: no point-data array 'vel'; arrays present: velocity(3), density(1)"}},
      // -- dimensions that do not match the data
      {"WholeExtentLargerThanTheData",
       [](F f) {
         return licLine(f, f.editedVti("big.vti", {{"<ImageData", "WholeExtent", "0 40 0 20 0 0"},
                                               {"<Piece", "Extent", "0 40 0 20 0 0"}}));
       },
       {"file {in}/big.vti is corrupt", "velocity"}},
      {"WholeExtentSmallerThanTheData",
       [](F f) {
         return streamlinesLine(f, f.editedVti("small.vti", {{"<ImageData", "WholeExtent", "0 10 0 20 0 0"},
                                                         {"<Piece", "Extent", "0 10 0 20 0 0"}}));
       },
       {"file {in}/small.vti: array 'velocity' holds more values than the 231 tuples x 3 "
        "components of Float64 that Piece 0 Extent \"0 10 0 20 0 0\""}},
      {"PieceOutsideTheWholeExtent",
       [](F f) {
         return topologyLine(f, f.editedVti("outside.vti", {{"<ImageData", "WholeExtent", "0 10 0 20 0 0"}}));
       },
       {"file {in}/outside.vti: Piece 0 Extent \"0 20 0 20 0 0\" reaches outside WholeExtent "
        "\"0 10 0 20 0 0\""}},
      {"PieceCoveringPartOfTheWholeExtent",
       [](F f) {
         return isosurfaceLine(f, f.editedVti("part.vti", {{"<Piece", "Extent", "0 10 0 20 0 0"}}));
       },
       {"file {in}/part.vti: its pieces hold 231 of the 441 points of WholeExtent \"0 20 0 20 0 0\"; "
        "the file is incomplete"}},
      {"AsciiArrayShorterThanTheExtent",
       [](F f) {
         return licLine(f, f.text("short.vti", asciiVti("0 2 0 1 0 0", "type=\"Float32\" NumberOfComponents=\"3\"",
                                                    "1 0 0 0 1 0")));
       },
       {"file {in}/short.vti is corrupt or truncated", "velocity"}},
      {"AsciiArrayLongerThanTheExtent",
       [](F f) {
         return licLine(f, f.text("long.vti", asciiVti("0 1 0 1 0 0", "type=\"Float32\" NumberOfComponents=\"3\"",
                                                   "1 0 0 0 1 0 1 0 0 0 1 0 5 5 5")));
       },
       {"file {in}/long.vti: array 'velocity' holds more values than the 4 tuples x 3 components"}},
      {"InvertedExtent",
       [](F f) {
         return licLine(f, f.editedVti("inverted.vti", {{"<ImageData", "WholeExtent", "0 -5 0 20 0 0"},
                                                    {"<Piece", "Extent", "0 -5 0 20 0 0"}}));
       },
       {"file {in}/inverted.vti: grid dims along x is -4; allowed: >= 1"}},
      {"ExtentBeyondIntRange",
       [](F f) {
         const std::string e = "-2147483647 2147483647 0 20 0 0";
         return topologyLine(f, f.editedVti("wide.vti", {{"<ImageData", "WholeExtent", e}, {"<Piece", "Extent", e}}));
       },
       {"file {in}/wide.vti: ImageData WholeExtent \"-2147483647 2147483647 0 20 0 0\" gives "
        "4294967295 nodes along x; at most 2147483647 fit a grid"}},
      {"ExtentThatIsNotNumbers",
       [](F f) { return licLine(f, f.editedVti("words.vti", {{"<ImageData", "WholeExtent", "0 twenty 0 20 0 0"}})); },
       {"file {in}/words.vti: ImageData WholeExtent is \"0 twenty 0 20 0 0\"; allowed: 6 whole numbers"}},
      // -- spacing and origin
      {"ZeroSpacing",
       [](F f) { return licLine(f, f.editedVti("zero.vti", {{"<ImageData", "Spacing", "0 0.1 1"}})); },
       {"file {in}/zero.vti: grid spacing along x is 0.000000; allowed: finite and > 0"}},
      {"NegativeSpacing",
       [](F f) { return streamlinesLine(f, f.editedVti("neg.vti", {{"<ImageData", "Spacing", "0.1 -1 1"}})); },
       {"file {in}/neg.vti: grid spacing along y is -1.000000; allowed: finite and > 0"}},
      {"NaNSpacing",
       [](F f) { return topologyLine(f, f.editedVti("nan.vti", {{"<ImageData", "Spacing", "nan 0.1 1"}})); },
       {"file {in}/nan.vti: ImageData Spacing is \"nan 0.1 1\"; allowed: 3 finite numbers"}},
      {"InfiniteSpacing",
       [](F f) { return isosurfaceLine(f, f.editedVti("inf.vti", {{"<ImageData", "Spacing", "0.1 inf 1"}})); },
       {"file {in}/inf.vti: ImageData Spacing is \"0.1 inf 1\"; allowed: 3 finite numbers"}},
      {"SpacingThatIsNotNumbers",
       [](F f) { return licLine(f, f.editedVti("abc.vti", {{"<ImageData", "Spacing", "abc"}})); },
       {"file {in}/abc.vti: ImageData Spacing is \"abc\"; allowed: 3 finite numbers"}},
      {"NaNOrigin",
       [](F f) { return licLine(f, f.editedVti("origin.vti", {{"<ImageData", "Origin", "-1 nan 0"}})); },
       {"file {in}/origin.vti: ImageData Origin is \"-1 nan 0\"; allowed: 3 finite numbers"}},
      // -- NaN and infinity in fields
      // NaN/inf vectors are masked by lic and topology since issue 15 (no longer refused).
      {"InfinityInIsosurfaceScalars",
       [](F f) { return isosurfaceLine(f, f.vti("inf.vti", rotationWith(kInf, false))); },
       {"file {in}/inf.vti: array 'density' has 1 infinite value; an isosurface needs finite values"}},
      // -- enormous sizes, refused before allocating
      {"EnormousWholeExtentForLic",
       [](F f) {
         return licLine(f, f.editedVti("huge.vti", {{"<ImageData", "WholeExtent", kHugeExtent},
                                                {"<Piece", "Extent", kHugeExtent}}));
       },
       {"file {in}/huge.vti", "velocity", "would need", "refused before allocating"}},
      {"EnormousWholeExtentOnly",
       [](F f) { return isosurfaceLine(f, f.editedVti("huge.vti", {{"<ImageData", "WholeExtent", kHugeExtent}})); },
       {"file {in}/huge.vti", "would need", "velocity"}},
  };
}

// Legacy .vtk files (docs/reliability.md, "Legacy .vtk files"): every flow command reads them.
std::vector<HostileCase> legacyVtkCases() {
  using F = const Folders&;
  using Lines = std::vector<std::string>&;
  return {
      {"LegacyVtkCutInHalf", [](F f) { return licLine(f, cutInHalf(f, f.legacyVtk("cut.vtk"))); },
       {"file {in}/cut.vtk is corrupt or truncated: Error reading ascii data. Possible mismatch of "
        "datasize with declaration."}},
      {"LegacyVtkDeclaresMoreValuesThanItHolds",
       [](F f) {
         return streamlinesLine(
             f, f.legacyVtk("big.vtk", [](Lines l) { l[4] = "DIMENSIONS 2100 21 1"; l[7] = "POINT_DATA 44100"; }));
       },
       {"file {in}/big.vtk is corrupt or truncated: line 5 (DIMENSIONS) declares 44100 nodes, at "
        "least 88200 bytes, but the file has"}},
      {"LegacyVtkUnknownDatasetType",
       [](F f) {
         return topologyLine(f, f.legacyVtk("odd.vtk", [](Lines l) { l[3] = "DATASET HYPERCUBE"; }));
       },
       {"file {in}/odd.vtk is corrupt or truncated: line 4 (DATASET) has dataset type 'HYPERCUBE'; "
        "allowed: STRUCTURED_POINTS, STRUCTURED_GRID, RECTILINEAR_GRID, UNSTRUCTURED_GRID, "
        "POLYDATA"}},
      {"LegacyVtkNotANumber",
       [](F f) {
         return isosurfaceLine(f, f.legacyVtk("text.vtk", [](Lines l) { l[500] = "one"; }));
       },
       {"file {in}/text.vtk is corrupt or truncated: Unsupported point attribute type: one"}},
      {"LegacyVtkWithoutTheArray",
       [](F f) {
         CommandLine c = licLine(f, f.legacyVtk("novel.vtk"));
         c[3] = "vel";
         return c;
       },
       {"file {in}/novel.vtk", "'vel'", "velocity"}},
  };
}

std::vector<HostileCase> vtpCases() {
  using F = const Folders&;
  return {
      {"VtpCutInHalf", [](F f) { return resampleLine(f, cutInHalf(f, f.vtp("cut.vtp"))); },
       {"file {in}/cut.vtp is corrupt"}},
      {"VtpGarbledCompressedData", [](F f) { return resampleLine(f, garbled(f.vtp("garbled.vtp"))); },
       {"file {in}/garbled.vtp is corrupt"}},
      {"VtiGivenForVtp",
       [](F f) {
         fs::rename(f.vti("g.vti"), f.in / "g.vtp");
         return resampleLine(f, f.input("g.vtp"));
       },
       {"file {in}/g.vtp holds VTK XML ImageData, expected PolyData (.vtp)"}},
      {"NumberOfPointsSmallerThanTheData",
       [](F f) { return resampleLine(f, f.editedVtp("fewer.vtp", {{"<Piece", "NumberOfPoints", "100"}})); },
       {"file {in}/fewer.vtp: array", "holds more values than the 100 tuples"}},
      {"NumberOfPointsLargerThanTheData",
       [](F f) { return resampleLine(f, f.editedVtp("more.vtp", {{"<Piece", "NumberOfPoints", "200"}})); },
       {"file {in}/more.vtp is corrupt"}},
      {"NegativeNumberOfPoints",
       [](F f) { return resampleLine(f, f.editedVtp("neg.vtp", {{"<Piece", "NumberOfPoints", "-5"}})); },
       {"file {in}/neg.vtp: Piece 0 NumberOfPoints is \"-5\"; allowed: a whole number >= 0"}},
      {"EnormousNumberOfPoints",
       [](F f) {
         return resampleLine(f, f.editedVtp("huge.vtp", {{"<Piece", "NumberOfPoints", "100000000000000"}}));
       },
       {"file {in}/huge.vtp", "would need", "refused before allocating"}},
      {"ParticleMassDeclaredWith2Components",
       [](F f) { return resampleLine(f, f.editedVtp("mass2.vtp", {{"Name=\"mass\"", "NumberOfComponents", "2"}})); },
       {"file {in}/mass2.vtp is corrupt or truncated: Cannot read point data array \"mass\""}},
      {"NaNParticlePosition",
       [](F f) { return resampleLine(f, f.vtp("nan.vtp", particlesWith("position", kNaN))); },
       {"file {in}/nan.vtp", "particle 17", "non-finite position"}},
      {"InfiniteParticleMass",
       [](F f) { return resampleLine(f, f.vtp("inf.vtp", particlesWith("mass", kInf))); },
       {"file {in}/inf.vtp: particle array 'mass' has a NaN or infinite value at particle 17"}},
      {"InfiniteParticleMassNotResampled",
       [](F f) {
         CommandLine c = resampleLine(f, f.vtp("inf.vtp", particlesWith("mass", kInf)));
         c.insert(c.end(), {"--arrays", "velocity"});
         return c;
       },
       {"file {in}/inf.vtp: particle array 'mass' is inf at particle 17; masses and densities "
        "must be > 0"}},
      {"NaNParticleVelocity",
       [](F f) { return resampleLine(f, f.vtp("nanv.vtp", particlesWith("velocity", kNaN))); },
       {"file {in}/nanv.vtp: particle array 'velocity' has a NaN or infinite value at particle 17"}},
  };
}

std::vector<HostileCase> sceneCases() {
  using F = const Folders&;
  return {
      {"DeeplyNestedJson",
       [](F f) { return runSceneLine(f, f.scene("deep.json", std::string(100000, '[') + std::string(100000, ']'))); },
       {"{in}/deep.json: nesting deeper than 64 levels"}},
      {"DeeplyNestedJsonInASweep",
       [](F f) {
         return sweepLine(f, f.scene("deep.json", "{\"lbm\": " + std::string(5000, '[') + std::string(5000, ']') + "}"));
       },
       {"{in}/deep.json: nesting deeper than 64 levels"}},
      {"HugeJsonFile",
       [](F f) {
         const std::string file = f.scene("huge.json", "{\"name\": \"");
         fs::resize_file(file, 200u << 20);  // sparse: 200 MiB without writing them
         return checkLine(f, file);
       },
       {"{in}/huge.json: is larger than 16 MiB"}},
      {"JsonThatIsNotUtf8",
       [](F f) { return runSceneLine(f, f.scene("latin1.json", sceneText("", "\"title\": \"caf\xe9\","))); },
       {"{in}/latin1.json: is not valid JSON at line 1, column", "ill-formed UTF-8"}},
      {"DuplicateKey",
       [](F f) { return runSceneLine(f, f.scene("dup.json", sceneText(", \"resolution\": 32"))); },
       {"{in}/dup.json: key 'lbm.resolution' is given twice in the same object"}},
      {"DuplicateKeyInsideAList",
       [](F f) {
         return checkLine(f, f.scene("duplist.json",
                                 sceneText("", "\"output\": {\"images\": [{}, {\"field\": \"speed\", \"field\": \"density\"}]},")));
       },
       {"{in}/duplist.json: key 'output.images[1].field' is given twice"}},
      {"NumberBeyondDoubleRange",
       [](F f) { return checkLine(f, f.scene("overflow.json", sceneText(", \"max_steps\": 1e400"))); },
       {"{in}/overflow.json: key 'lbm.max_steps' is not a usable value: number overflow"}},
      {"IntegerBeyondInt64",
       [](F f) { return checkLine(f, f.scene("bigint.json", sceneText(", \"max_steps\": 99999999999999999999999"))); },
       {"{in}/bigint.json: key 'lbm.max_steps' must be a whole number that fits in 32 bits, got "
        "the number 9.99"}},
      {"IntegerBeyondInt32",
       [](F f) {
         std::string s = sceneText();
         s.replace(s.find("\"snapshots\": 1"), 14, "\"snapshots\": 3000000000");
         return runSceneLine(f, f.scene("int32.json", s));
       },
       {"{in}/int32.json: key 'output.snapshots' is 3000000000, outside the allowed range [0, "
        "100000]"}},
      {"FractionForAnInteger",
       [](F f) { return checkLine(f, f.scene("frac.json", sceneText(", \"max_steps\": 2.5"))); },
       {"{in}/frac.json: key 'lbm.max_steps' must be a whole number, got the number 2.5"}},
      {"OverrideBeyondDoubleRange",
       [](F f) {
         CommandLine c = runSceneLine(f, f.scene());
         c.insert(c.end(), {"--set", "lbm.reynolds=1e400"});
         return c;
       },
       {"{in}/scene.json: key 'lbm.reynolds' --set: '1e400' is not a usable value"}},
      {"NaNLiteral",
       [](F f) {
         std::string s = sceneText();
         s.replace(s.find("\"reynolds\": 20"), 14, "\"reynolds\": NaN");
         return checkLine(f, f.scene("nan.json", s));
       },
       {"{in}/nan.json: is not valid JSON at line 2", "inside key 'lbm.reynolds'"}},
      {"JsonListInsteadOfObject", [](F f) { return checkLine(f, f.scene("list.json", "[1, 2]")); },
       {"{in}/list.json: must be an object {...}, got a list"}},
      {"EmptyJsonFile", [](F f) { return runSceneLine(f, f.scene("empty.json", "")); },
       {"{in}/empty.json: is not valid JSON at line 1, column 1"}},
  };
}

// Every reading command, with its input missing, a folder, or its output impossible to write.
std::vector<HostileCase> pathCases() {
  using F = const Folders&;
  using Maker = std::function<CommandLine(F, const std::string&)>;
  struct Command {
    std::string name;
    Maker line;
    std::string extension;  // of the input
    std::function<std::string(F)> validInput;
    std::string missingMessage;  // "{file}" is the input path
    std::string folderMessage;
  };
  const std::string sceneMissing = "{file}: does not exist";
  const std::string sceneFolder = "{file}: is a folder, expected a scene file (.json)";
  const std::string vtkMissing = "file {file} does not exist";
  const std::string vtkFolder = "file {file} is a folder, not a VTK file";
  const std::vector<Command> commands = {
      {"Run", runSceneLine, ".json", [](F f) { return f.scene(); }, sceneMissing, sceneFolder},
      {"Check", checkLine, ".json", [](F f) { return f.scene(); }, sceneMissing, sceneFolder},
      {"Sweep", sweepLine, ".json", [](F f) { return f.scene(); }, sceneMissing, sceneFolder},
      {"Lic", licLine, ".vti", [](F f) { return f.vti("rot.vti"); }, vtkMissing, vtkFolder},
      {"Streamlines", streamlinesLine, ".vti", [](F f) { return f.vti("rot.vti"); }, vtkMissing, vtkFolder},
      {"Topology", topologyLine, ".vti", [](F f) { return f.vti("rot.vti"); }, vtkMissing, vtkFolder},
      {"Isosurface", isosurfaceLine, ".vti", [](F f) { return f.vti("rot.vti"); }, vtkMissing, vtkFolder},
      {"Resample", resampleLine, ".vtp", [](F f) { return f.vtp("p.vtp"); }, vtkMissing, vtkFolder},
  };
  auto replaceFile = [](std::string text, const std::string& file) {
    return text.replace(text.find("{file}"), 6, file);
  };
  std::vector<HostileCase> cases;
  for (const Command& c : commands) {
    const std::string missing = "{in}/none" + c.extension;
    cases.push_back({c.name + "InputDoesNotExist",
                     [c](F f) { return c.line(f, f.input("none" + c.extension)); },
                     {replaceFile(c.missingMessage, missing)}});
    cases.push_back({c.name + "InputIsAFolder",
                     [c](F f) {
                       fs::create_directory(f.in / ("folder" + c.extension));
                       return c.line(f, f.input("folder" + c.extension));
                     },
                     {replaceFile(c.folderMessage, "{in}/folder" + c.extension)}});
    if (c.name == "Check") continue;  // writes nothing
    // The output's folder is a regular file: the input itself (in/, not out/: out/ must stay
    // empty, and the path names a file that exists).
    cases.push_back({c.name + "OutputUnderARegularFile",
                     [c](F f) {
                       const std::string input = c.validInput(f);
                       CommandLine line = c.line(f, input);
                       const std::string outFolder = f.out.string();
                       for (std::string& a : line)
                         if (a.rfind(outFolder, 0) == 0) a = input + a.substr(outFolder.size());
                       return line;
                     },
                     {"cannot", "{in}/", "is not a folder"}});
    if (c.extension == ".json") continue;  // run and sweep create their output folder
    cases.push_back({c.name + "OutputInAFolderThatDoesNotExist",
                     [c](F f) {
                       CommandLine line = c.line(f, c.validInput(f));
                       const std::string outFolder = f.out.string();
                       for (std::string& a : line)
                         if (a.rfind(outFolder, 0) == 0)
                           a = outFolder + "/missing" + a.substr(outFolder.size());
                       return line;
                     },
                     {"folder '{out}/missing' does not exist"}});
  }
  // Secondary outputs (pictures, tables) are checked before the first file is written.
  cases.push_back({"StreamlinesPictureInAFolderThatDoesNotExist",
                   [](F f) {
                     CommandLine c = streamlinesLine(f, f.vti("rot.vti"));
                     c.insert(c.end(), {"--png", f.output("missing/lines.png")});
                     return c;
                   },
                   {"cannot write {out}/missing/lines.png: folder '{out}/missing' does not exist"}});
  cases.push_back({"TopologyCsvInAFolderThatDoesNotExist",
                   [](F f) {
                     CommandLine c = topologyLine(f, f.vti("rot.vti"));
                     c[7] = f.output("missing/points.csv");
                     return c;
                   },
                   {"cannot write {out}/missing/points.csv: folder '{out}/missing' does not exist"}});
  cases.push_back({"ResamplePictureInAFolderThatDoesNotExist",
                   [](F f) {
                     CommandLine c = resampleLine(f, f.vtp("p.vtp"));
                     c.insert(c.end(), {"--png-particles", f.output("missing/p.png")});
                     return c;
                   },
                   {"cannot write {out}/missing/p.png: folder '{out}/missing' does not exist"}});
  cases.push_back({"IsosurfaceOutputIsAFolder",
                   [](F f) {
                     fs::create_directory(f.in / "iso.vtp");
                     CommandLine c = isosurfaceLine(f, f.vti("rot.vti"));
                     c[7] = f.input("iso.vtp");
                     return c;
                   },
                   {"cannot write {in}/iso.vtp: a folder of that name exists"}});
  return cases;
}

// Test names in gtest's output instead of the bytes of the struct.
void PrintTo(const HostileCase& c, std::ostream* os) { *os << c.name; }

std::vector<HostileCase> allCases() {
  std::vector<HostileCase> all;
  for (auto make : {vtiCases, vtpCases, legacyVtkCases, sceneCases, pathCases})
    for (HostileCase& c : make()) all.push_back(std::move(c));
  return all;
}

std::string substituted(std::string text, const Folders& f) {
  for (const auto& [token, folder] : {std::pair{std::string("{in}"), f.in}, {"{out}", f.out}})
    for (std::size_t at; (at = text.find(token)) != std::string::npos;)
      text.replace(at, token.size(), folder.string());
  return text;
}

std::set<std::string> listing(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(folder))
    names.insert(fs::relative(e.path(), folder).string());
  return names;
}

class HostileInput : public ::testing::TestWithParam<HostileCase> {
 protected:
  void SetUp() override {
    root_ = std::make_unique<testing::TestFolder>();
    folders_.in = root_->path() / "in";
    folders_.out = root_->path() / "out";
    fs::create_directories(folders_.in);
    fs::create_directories(folders_.out);
  }
  std::unique_ptr<testing::TestFolder> root_;
  Folders folders_;
};

}  // namespace

TEST_P(HostileInput, ExitsWithTwoNamingTheProblemAndWritesNothing) {
  const HostileCase& c = GetParam();
  const CommandLine line = c.setUp(folders_);
  const std::set<std::string> inputs = listing(folders_.in);
  testing::VtkOutputCounter vtkOutput;
  const Result r = run(line);
  EXPECT_EQ(r.code, 2) << "stderr: " << r.err << "\nstdout: " << r.out;
  for (const std::string& fragment : c.expected) {
    const std::string piece = substituted(fragment, folders_);
    EXPECT_NE(r.err.find(piece), std::string::npos)
        << "message: " << r.err << "\nlacks: " << piece;
  }
  EXPECT_EQ(r.err.rfind("fluidviz " + line.front() + ": error: ", 0), 0u) << r.err;
  EXPECT_EQ(r.out.find(": valid"), std::string::npos) << "stdout: " << r.out;
  EXPECT_TRUE(listing(folders_.out).empty()) << "bad input must not write anything";
  EXPECT_EQ(listing(folders_.in), inputs) << "bad input must not leave files next to the input";
  EXPECT_EQ(vtkOutput.count(), 0) << "VTK printed: " << vtkOutput.last();
}

INSTANTIATE_TEST_SUITE_P(AllCommands, HostileInput, ::testing::ValuesIn(allCases()),
                         [](const ::testing::TestParamInfo<HostileCase>& info) {
                           return info.param.name;
                         });

// The inputs before damage, through the same command lines: accepted (exit 0), so every refusal
// above comes from the damage.
TEST(HostileInputBaseline, UntouchedInputsAreAccepted) {
  testing::TestFolder root;
  Folders f{root.path() / "in", root.path() / "out"};
  fs::create_directories(f.in);
  fs::create_directories(f.out);
  const std::string vti = f.vti("rot.vti"), vtp = f.vtp("p.vtp"), scene = f.scene();
  const std::string vtk = f.legacyVtk("rot.vtk");
  for (const CommandLine& line :
       {licLine(f, vti), streamlinesLine(f, vti), topologyLine(f, vti), isosurfaceLine(f, vti), resampleLine(f, vtp),
        checkLine(f, scene), runSceneLine(f, scene), licLine(f, vtk), streamlinesLine(f, vtk),
        topologyLine(f, vtk), isosurfaceLine(f, vtk)}) {
    const Result r = run(line);
    EXPECT_EQ(r.code, 0) << line[0] << ": " << r.err;
  }
  // The ASCII form used by the cases above, with consistent sizes, reads too.
  const std::string ascii = f.text("ok.vti", asciiVti("0 1 0 1 0 0", "type=\"Float32\" NumberOfComponents=\"3\"",
                                                      "1 0 0 0 1 0 -1 0 0 0 -1 0"));
  const Result r = run({"streamlines", ascii, "-a", "velocity", "-o", f.output("ascii.vtp"), "--seeds",
                        "points:0.5,0.5"});
  EXPECT_EQ(r.code, 0) << r.err;
}

}  // namespace fluidviz
