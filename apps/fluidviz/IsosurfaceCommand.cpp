// fluidviz isosurface: the level set of a scalar array of a .vti (surface in 3D, isolines in 2D)
// as a .vtp, its size, and optionally a picture.
#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStripper.h>

#include <memory>
#include <ostream>
#include <sstream>

#include "apps/fluidviz/FlowCommandSupport.h"
#include "apps/fluidviz/ParticleCommands.h"
#include "apps/fluidviz/View3DFlags.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "fieldviz/render/LicPicture.h"
#include "fieldviz/render/SurfaceRendering.h"
#include "filters/isosurface/vtk/Isosurface.h"

namespace fluidviz::app {

namespace {

namespace iso = fluidviz::isosurface;

const char* kIsosurfaceHelp = R"(fluidviz isosurface GRID.vti -a ARRAY --value V -o OUT.vtp [options]

The level set ARRAY = V of a 1-component point array: a triangulated surface for 3D grids
(Flying Edges, vtkFlyingEdges3D) with normals, isolines for 2D grids (vtkFlyingEdges2D); the
grid's other arrays are interpolated onto it. Prints its size: triangles, area and enclosed
volume (3D; the volume is that of the closed parts), or segments and length (2D).
For particles resampled with fluidviz resample, the free surface is -a color --value 0.5.

Surface:
  -a, --array ARRAY        1-component point array
  --value V                iso value, inside the array's range
  --smooth N               windowed-sinc smoothing passes, [0, 500] (default 0)
  --passband B             windowed-sinc pass band, (0, 2] (default 0.1; smaller: smoother)
  --no-normals             no point normals
  --no-arrays              do not interpolate the grid's other arrays
)";

const char* kIsosurfaceHelpPicture = R"(Picture (--png OUT.png):
  3D: the shaded surface inside the grid's outline; 2D: the array with its isolines on top
  --color-by ARRAY         3D: colour the surface by an interpolated array
  --color R,G,B            3D: surface colour, each in [0, 1] (default 0.3,0.55,0.85)
  --colormap NAME          (default viridis)
  --axes                   2D: x and y axes with round ticks in world coordinates
)";

const char* kIsosurfaceHelpTail = R"(Outputs:
  -o, --output OUT.vtp     the surface or isolines (written atomically)

Errors (exit code 2): missing or corrupt file, missing array (those present are listed), a
vector array, an array with NaN (resampled nodes without particle support: contour 'color'),
a value outside the array's range, options outside their range.
)";

const std::vector<KeyFlag> kSurfaceFlags = {
    {"--array", "array", KeyFlag::text},
    {"--value", "value", KeyFlag::number},
    {"--smooth", "smoothing_iterations", KeyFlag::number},
    {"--passband", "smoothing_passband", KeyFlag::number},
    {"--no-normals", "normals", KeyFlag::custom},
    {"--no-arrays", "interpolate_arrays", KeyFlag::custom}};
const std::vector<KeyFlag> kStyleFlags = {
    {"--color-by", "color_by", KeyFlag::text},
    {"--colormap", "colormap", KeyFlag::text},
    {"--color", "color", KeyFlag::custom}};

struct IsosurfaceArgs {
  std::filesystem::path grid, vtp, png;
  iso::IsosurfaceParams params;
  SurfaceStyle style;
  View3DParams view;
  bool axes = false;                 ///< --axes (2D pictures)
  std::optional<std::string> units;  ///< --units; nullopt: the file's or m
  ImageSampling sampling;            ///< --spacing
};

ParsedArgs parseIsosurfaceCommandLine(const std::vector<std::string>& args) {
  std::set<std::string> valued = view3DValuedOptions();
  valued.insert({"--array", "--value", "--smooth", "--passband", "--output", "--png",
                 "--color-by", "--colormap", "--color", "--units", "--spacing"});
  std::set<std::string> switches = view3DSwitches();
  switches.insert({"--help", "--no-normals", "--no-arrays", "--axes"});
  return parseArgs(args, valued, switches, {{"-o", "--output"}, {"-a", "--array"}, {"-h", "--help"}});
}

IsosurfaceArgs parseIsosurfaceArgs(const ParsedArgs& a) {
  IsosurfaceArgs r;
  if (a.positional.size() != 1)
    throw UsageError("needs exactly one grid file (.vti), got " +
                     std::to_string(a.positional.size()));
  r.grid = a.positional[0];
  if (!a.has("--array")) throwMissingArrayOption(r.grid);
  if (!a.has("--value")) throw UsageError("needs --value V (the iso value)");
  r.vtp = a.value("--output");
  if (r.vtp.empty()) throw UsageError("needs -o OUT.vtp");
  r.png = a.value("--png");
  r.axes = a.has("--axes");
  r.units = unitsOption(a);
  r.sampling = samplingOption(a);
  scene::json surface = scene::json::object();
  surface["normals"] = !a.has("--no-normals");
  surface["interpolate_arrays"] = !a.has("--no-arrays");
  readFlags(a, kSurfaceFlags, r.params, surface);
  scene::json style = scene::json::object();
  if (a.has("--color")) style["color"] = parseNumbers("--color", a.value("--color"), 3);
  readFlags(a, kStyleFlags, r.style, style);
  r.view = readView3DFlags(a);
  return r;
}

vtkSmartPointer<vtkPolyData> contour(const IsosurfaceArgs& r, vtkImageData* image) {
  try {
    vtkSmartPointer<vtkPolyData> surface;
    checkWithFlagNames(kSurfaceFlags, [&] {
      surface = iso::extractIsosurface(image, r.params, "file " + r.grid.string());
    });
    return surface;
  } catch (const DataArrayError& e) {
    throw FileError(r.grid, e.what(), e.arrayName());
  }
}

// Sizes in the length unit in force (--units, the file's length_unit, else m).
void report(const vtkSmartPointer<vtkPolyData>& surface, bool is2D, const std::string& unit,
            std::ostream& out) {
  const iso::SurfaceMeasures m = iso::measureSurface(surface);
  if (is2D) {
    out << "isolines: " << m.cells << " segments, " << m.points << " points, length " << m.length
        << " " << unit << "\n";
    return;
  }
  out << "isosurface: " << m.cells << " triangles, " << m.points << " points, area " << m.area
      << " " << unit << "^2, enclosed volume " << m.volume << " " << unit << "^3\n";
}

// Isolines as polylines (world coordinates) for the 2D picture.
std::vector<std::vector<Vec3>> polylines(vtkPolyData* lines) {
  vtkNew<vtkStripper> stripper;
  stripper->SetInputData(lines);
  stripper->JoinContiguousSegmentsOn();
  stripper->Update();
  vtkPolyData* joined = stripper->GetOutput();
  std::vector<std::vector<Vec3>> result;
  vtkNew<vtkIdList> ids;
  vtkCellArray* cells = joined->GetLines();
  for (cells->InitTraversal(); cells->GetNextCell(ids);) {
    result.emplace_back();
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
      Vec3 p;
      joined->GetPoint(ids->GetId(k), p.data());
      result.back().push_back(p);
    }
  }
  return result;
}

RgbaImage isolinePicture(const IsosurfaceArgs& r, vtkImageData* image, vtkPolyData* lines) {
  const ScalarField field = scalarFieldFrom(image, r.params.array, "file " + r.grid.string());
  FieldImageParams picture;
  picture.colormap = r.style.colormap;
  picture.background = r.view.background;
  std::ostringstream title;
  title << r.params.array << " with its isoline at " << r.params.value;
  picture.title = title.str();
  picture.axes = r.axes;
  picture.axes_unit = lengthUnitOf(image, r.grid, r.units);  // as report() prints it
  fitPictureToField(field, picture, r.view.width);
  StreamlineStyle style;
  style.arrows = false;
  return renderFieldPicture(field, picture, {LineOverlay{polylines(lines), style}}).image;
}

std::unique_ptr<Scene3D> surfaceScene(const IsosurfaceArgs& r, vtkImageData* image,
                                      vtkPolyData* surface) {
  auto scene = std::make_unique<Scene3D>(r.view);
  try {
    const SurfaceActor actor = makeSurfaceActor(surface, r.style);
    scene->add(actor.actor);
    if (actor.coloring) scene->setLegend(actor.coloring->table, actor.coloring->title);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--color-by: ") + e.what());
  }
  std::array<double, 6> bounds;
  image->GetBounds(bounds.data());
  scene->setBounds(bounds);
  return scene;
}

int runIsosurface(const IsosurfaceArgs& r, std::ostream& out) {
  requireWritableFolder(r.vtp);
  if (!r.png.empty()) requirePictureFile(r.png), requireWritableFolder(r.png);
  vtkSmartPointer<vtkImageData> image = readImageData(r.grid, r.sampling);
  const std::string unit = lengthUnitOf(image, r.grid, r.units);
  const vtkSmartPointer<vtkPolyData> surface = contour(r, image);
  int dims[3];
  image->GetDimensions(dims);
  const bool is2D = dims[2] == 1;
  if (r.axes && !is2D)
    throw UsageError("--axes is for the 2D picture of a 2D grid; the 3D picture draws the grid's "
                     "outline (--no-outline)");
  report(surface, is2D, unit, out);
  std::unique_ptr<Scene3D> scene;  // built before writing: its errors stop everything
  if (!r.png.empty() && !is2D) scene = surfaceScene(r, image, surface);
  RgbaImage picture;
  if (!r.png.empty() && is2D) picture = isolinePicture(r, image, surface);
  writeVtp(surface, r.vtp);
  out << "wrote " << r.vtp.string() << "\n";
  if (scene) writeScenePictures(*scene, r.png, out);
  if (is2D && !r.png.empty()) {
    writePicture(picture, r.png);
    out << "wrote " << r.png.string() << "\n";
  }
  return kSuccess;
}

}  // namespace

int isosurfaceCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream&,
                      bool) {
  const ParsedArgs a = parseIsosurfaceCommandLine(args);
  if (a.has("--help")) {
    out << kIsosurfaceHelp << unitsHelpLine() << spacingHelpLine() << kIsosurfaceHelpPicture << kView3DHelp
        << kIsosurfaceHelpTail;
    return kSuccess;
  }
  return runIsosurface(parseIsosurfaceArgs(a), out);
}

}  // namespace fluidviz::app
