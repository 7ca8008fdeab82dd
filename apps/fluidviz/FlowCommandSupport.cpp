#include "apps/fluidviz/FlowCommandSupport.h"

#include "fieldviz/render/RgbaImage.h"

#include <vtkImageData.h>
#include <vtkPointData.h>

#include <cmath>
#include <sstream>

#include "apps/fluidviz/KeyOptions.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "pipeline/FlowFields.h"
#include "fieldviz/vtk/ImageDataAdapter.h"

namespace fluidviz::app {

ParsedArgs parseArgs(const std::vector<std::string>& args, const std::set<std::string>& valued,
                     const std::set<std::string>& switches,
                     const std::map<std::string, std::string>& aliases) {
  ParsedArgs a;
  for (std::size_t i = 1; i < args.size(); ++i) {
    std::string arg = args[i];
    if (auto alias = aliases.find(arg); alias != aliases.end()) arg = alias->second;
    if (arg.size() < 2 || arg[0] != '-' || std::isdigit(static_cast<unsigned char>(arg[1]))) {
      a.positional.push_back(args[i]);
      continue;
    }
    const bool takesValue = valued.count(arg) > 0;
    if (!takesValue && !switches.count(arg))
      throw UsageError("unknown option '" + args[i] + "' (see fluidviz " + args[0] + " --help)");
    if (a.has(arg)) throw UsageError(arg + " is given twice");
    if (!takesValue) {
      a.switches.insert(arg);
    } else if (i + 1 >= args.size()) {
      throw UsageError(arg + " needs a value");
    } else {
      a.values[arg] = args[++i];
    }
  }
  return a;
}

std::string flagForKey(const std::vector<KeyFlag>& table, const std::string& key) {
  const std::size_t bracket = key.find('[');
  const std::string base = key.substr(0, bracket);
  for (const KeyFlag& f : table)
    if (f.key == base) return f.flag + (bracket == std::string::npos ? "" : key.substr(bracket));
  return key;
}

void putFlagValue(scene::json& json, const KeyFlag& f, const std::string& value) {
  scene::json* target = &json;
  std::string key = f.key;
  for (std::size_t dot; (dot = key.find('.')) != std::string::npos; key = key.substr(dot + 1))
    target = &(*target)[key.substr(0, dot)];
  if (f.kind == KeyFlag::text) {
    (*target)[key] = value;
    return;
  }
  (*target)[key] = parseFlagNumber(f.flag, value);
}

std::pair<int, int> parseSize(const std::string& flag, const std::string& text) {
  int w = -1, h = 0;
  char x = 0, rest = 0;
  std::istringstream s(text);
  const bool ok = (s >> w) && (s.eof() || ((s >> x) && (x == 'x' || x == 'X') && (s >> h) &&
                                           !(s >> rest)));
  if (!ok || w < 0 || h < 0 || (w == 0 && h == 0))
    throw UsageError(flag + " is '" + text + "'; expected WxH in pixels (e.g. 800x600), or W "
                     "alone (height from the field's aspect ratio)");
  return {w, h};
}

std::vector<double> parseNumbers(const std::string& flag, const std::string& text, int count) {
  std::vector<double> values;
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, ',')) {
    std::size_t used = 0;
    try {
      values.push_back(std::stod(item, &used));
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() || !std::isfinite(values.back()))
      throw UsageError(flag + " is '" + text + "'; '" + item + "' is not a number");
  }
  if (static_cast<int>(values.size()) != count)
    throw UsageError(flag + " is '" + text + "'; expected " + std::to_string(count) +
                     " comma-separated numbers");
  return values;
}

const char* const kSliceHelp =
    "3D fields (required for 3D): x=I, y=J or z=K (node layer, index in [0, n-1]); x@X, y@Y or "
    "z@Z (world coordinate, linearly interpolated between the two nearest layers); "
    "plane:ox,oy,oz,nx,ny,nz (a plane through o normal to n, sampled trilinearly on a square "
    "lattice of the grid's smallest spacing, axes e1, e2 in docs/slices.md; nodes outside the "
    "grid are masked). The 2D field is the in-plane velocity";
const char* const kMaskHelp =
    "a 1-component array: nonzero = fluid, 0 = masked; or ARRAY>V, ARRAY<V: fluid where the "
    "array is above (below) V, e.g. a PC-MRI magnitude image (the file's vtkValidPointMask, "
    "1 = fluid, is used without it unless --ignore-file-arrays; NaN/inf velocity and zero-velocity solids are always masked). Masked nodes hold no critical "
    "points, end streamlines and separatrices and are drawn in the mask colour by LIC";
const char* const kCropHelp =
    "region of interest x0,x1,y0,y1 in world coordinates of the 2D field (of a plane slice: its "
    "e1, e2 coordinates); inside the grid, at least 2 x 2 nodes";

const char* const kIgnoreFileArraysFlag = "--ignore-file-arrays";
const char* const kIgnoreFileArraysHelp =
    "do not use the file's own arrays unasked: its vtkValidPointMask (the solids of a "
    "snapshot, the particle support of a resampled grid) then masks nothing";

std::string ignoreFileArraysHelpLine() {
  return "  " + std::string(kIgnoreFileArraysFlag) + "     " + kIgnoreFileArraysHelp + "\n";
}

namespace {

const std::string kSliceForms =
    "expected x=I, y=J or z=K (node index), x@X, y@Y or z@Z (world coordinate) or "
    "plane:ox,oy,oz,nx,ny,nz";

int axisOf(char c) { return c == 'x' ? 0 : c == 'y' ? 1 : c == 'z' ? 2 : -1; }

SliceSpec parseSlice(const std::string& slice) {
  const auto bad = [&] { return UsageError("--slice is '" + slice + "'; " + kSliceForms); };
  SliceSpec spec;
  if (slice.rfind("plane:", 0) == 0) {
    std::vector<double> n;
    try {
      n = parseNumbers("--slice plane:", slice.substr(6), 6);
    } catch (const UsageError&) {
      throw bad();
    }
    if (n[3] == 0 && n[4] == 0 && n[5] == 0)
      throw UsageError("--slice is '" + slice + "'; the normal nx,ny,nz must not be zero");
    spec.kind = SliceSpec::byPlane;
    spec.plane = slicePlane({n[0], n[1], n[2]}, {n[3], n[4], n[5]});
    return spec;
  }
  if (slice.size() < 3 || axisOf(slice[0]) < 0 || (slice[1] != '=' && slice[1] != '@'))
    throw bad();
  spec.axis = axisOf(slice[0]);
  const std::string number = slice.substr(2);
  std::size_t used = 0;
  try {
    if (slice[1] == '=') spec.index = std::stoi(number, &used);
    else spec.coordinate = std::stod(number, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != number.size() || !std::isfinite(spec.coordinate)) throw bad();
  spec.kind = slice[1] == '=' ? SliceSpec::byIndex : SliceSpec::byCoordinate;
  return spec;
}

void checkSliceRange(const SliceSpec& spec, const FlowInput& in, const std::string& slice) {
  const Grid& g = in.velocity.grid;
  const std::string axis(1, "xyz"[spec.axis]);
  const int n = g.dims[spec.axis];
  if (spec.kind == SliceSpec::byIndex && (spec.index < 0 || spec.index >= n))
    throw UsageError("--slice is " + slice + ", outside [0, " + std::to_string(n - 1) + "] for " +
                     in.source + " (" + g.describe() + ")");
  const double lo = g.origin[spec.axis], hi = lo + (n - 1) * g.spacing[spec.axis];
  if (spec.kind == SliceSpec::byCoordinate &&
      !(spec.coordinate >= lo - 1e-9 * g.spacing[spec.axis] &&
        spec.coordinate <= hi + 1e-9 * g.spacing[spec.axis]))
    throw UsageError("--slice is " + slice + ", outside " + axis + " in [" + std::to_string(lo) +
                     ", " + std::to_string(hi) + "] for " + in.source + " (" + g.describe() + ")");
}

template <class Field>
Field sliceOf(const Field& f, const SliceSpec& spec) {
  switch (spec.kind) {
    case SliceSpec::byIndex: return sliceAxis(f, spec.axis, spec.index);
    case SliceSpec::byCoordinate: return sliceAt(f, spec.axis, spec.coordinate);
    default: return f;
  }
}

// The velocity of the slice, and the nodes of a plane slice that lie outside the grid.
PointMask applySlice(FlowInput& in, const std::string& slice) {
  if (in.sliceSpec.kind != SliceSpec::byPlane) {
    checkSliceRange(in.sliceSpec, in, slice);
    if (in.sliceSpec.kind == SliceSpec::byIndex && in.sliceSpec.axis == 2)
      in.layer = in.sliceSpec.index;
    in.velocity = sliceOf(in.velocity, in.sliceSpec);
    return {};
  }
  try {
    PlaneSlice p = sliceOnPlane(in.velocity, in.sliceSpec.plane);
    in.velocity = std::move(p.velocity);
    return std::move(p.outside);
  } catch (const std::invalid_argument& e) {
    throw UsageError("--slice is '" + slice + "': " + e.what() + " of " + in.source);
  }
}

ScalarField slicedScalar(const FlowInput& in, const ScalarField& f) {
  if (f.grid.is2D() || in.sliceSpec.kind == SliceSpec::none) return f;
  if (in.sliceSpec.kind == SliceSpec::byPlane) return sliceOnPlane(f, in.sliceSpec.plane);
  return sliceOf(f, in.sliceSpec);
}

bool isThresholdMask(const std::string& option) {
  return option.find_first_of("<>") != std::string::npos;
}

// --mask ARRAY>V or ARRAY<V: fluid where the array is above (below) V, e.g. the magnitude image
// of PC-MRI, whose velocity outside the vessels is noise. 1 = fluid, 0 = masked.
std::optional<ScalarField> thresholdMask(const FlowInput& in, const std::string& option) {
  if (!isThresholdMask(option)) return std::nullopt;
  const std::size_t op = option.find_first_of("<>");
  const std::string name = option.substr(0, op);
  double threshold = 0.0;
  std::size_t used = 0;
  try {
    threshold = std::stod(option.substr(op + 1), &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (name.empty() || used == 0 || op + 1 + used != option.size() || !std::isfinite(threshold))
    throw UsageError("--mask is '" + option + "'; allowed: ARRAY (nonzero = fluid), ARRAY>V or "
                     "ARRAY<V (fluid where ARRAY is above or below the number V)");
  ScalarField fluid = scalarFieldFrom(in.image, name, in.source);
  for (double& v : fluid.values) v = (option[op] == '>' ? v > threshold : v < threshold) ? 1 : 0;
  return fluid;
}

// --mask, else vtkValidPointMask (unless --ignore-file-arrays), on the 3D grid, as fluid flags.
std::optional<ScalarField> fileMask(const FlowInput& in, const FlowRequest& request) {
  const std::string& option = request.mask;
  if (std::optional<ScalarField> threshold = thresholdMask(in, option)) return threshold;
  if (!option.empty()) return scalarFieldFrom(in.image, option, in.source);
  if (request.file_arrays && in.image->GetPointData()->GetArray(kValidPointMaskArray))
    return scalarFieldFrom(in.image, kValidPointMaskArray, in.source);
  return std::nullopt;
}

void applyCrop(FlowInput& in, const std::string& text) {
  const std::vector<double> c = parseNumbers("--crop", text, 4);
  try {
    in.cropBox = cropBox(in.velocity.grid, {c[0], c[1], c[2], c[3]});
  } catch (const std::invalid_argument& e) {
    throw UsageError("--crop is '" + text + "': " + e.what() + " of " + in.source +
                     "'s 2D field (" + in.velocity.grid.describe() + ")");
  }
  in.mask = crop(in.mask, in.velocity.grid, *in.cropBox);
  in.thresholded = crop(in.thresholded, in.velocity.grid, *in.cropBox);
  in.velocity = crop(in.velocity, *in.cropBox);
}

// A 3D field traced in 3D (FlowRequest::keep_3d): masked where the mask array says so and where
// v is not finite; solids and crops are 2D notions (a layer's connected regions, a rectangle).
FlowInput kept3D(FlowInput in, const std::optional<ScalarField>& fluid, const FlowRequest& request) {
  if (!request.crop.empty())
    throw UsageError("--crop is for 2D fields and slices; " + in.source + " array '" + in.array +
                     "' is 3D (" + in.velocity.grid.describe() + "): give --slice too");
  if (fluid) addMask(in.mask, zeroNodes(*fluid));
  addMask(in.mask, nonFiniteNodes(in.velocity));
  if (maskedCount(in.mask) == 0) in.mask.clear();
  return in;
}

}  // namespace

const std::vector<KeyFlag> kUnitsFlag = {{"--units", "units", KeyFlag::text}};

std::string unitsHelpLine() {
  std::vector<scene::DocRow> rows;
  scene::documentParams<LengthUnitParams>(rows, "");
  return "  --units NAME             " + keyHelp(rows.front()) + "\n";
}

std::optional<std::string> unitsOption(const ParsedArgs& a) {
  if (!a.has("--units")) return std::nullopt;
  LengthUnitParams units;
  readFlags(a, kUnitsFlag, units);
  checkWithFlagNames(kUnitsFlag, [&] { validateLengthUnit(units); });
  return units.units;
}

const std::vector<KeyFlag> kSpacingFlag = {{"--spacing", "spacing", KeyFlag::number}};

std::string spacingHelpLine() {
  std::vector<scene::DocRow> rows;
  scene::documentParams<ImageSampling>(rows, "");
  return "  --spacing H              " + keyHelp(rows.front()) + "\n";
}

ImageSampling samplingOption(const ParsedArgs& a) {
  ImageSampling sampling;
  if (a.has("--spacing")) readFlags(a, kSpacingFlag, sampling);
  return sampling;
}

std::string lengthUnitOf(vtkImageData* image, const std::filesystem::path& file,
                         const std::optional<std::string>& option) {
  if (option) return *option;
  const std::string fromFile = fieldDataString(image, "length_unit");
  if (fromFile.empty()) return LengthUnitParams{}.units;
  if (!isLengthUnitName(fromFile))
    throw FileError(file, "file " + file.string() + ": field-data string length_unit is '" +
                              fromFile + "'; allowed: " + kLengthUnitAllowed +
                              " (or give --units)");
  return fromFile;
}

FlowInput readFlowInput(const FlowRequest& request) {
  const std::filesystem::path& file = request.file;
  const std::string& array = request.array;
  const std::string& slice = request.slice;
  FlowInput in;
  in.file = file;
  in.source = "file " + file.string();
  in.array = array;
  in.image = readImageData(file, request.sampling);
  in.units = lengthUnitOf(in.image, file, request.units);
  in.velocity = vectorFieldFrom(in.image, array, in.source);
  const int nz = in.velocity.grid.dims[2];
  if (nz > 1 && slice.empty() && !request.keep_3d)
    throw UsageError(in.source + ": array '" + array + "' is 3D (" + in.velocity.grid.describe() +
                     "); give --slice z=K with K in [0, " + std::to_string(nz - 1) +
                     "] to work on one layer");
  const std::optional<ScalarField> fluid = fileMask(in, request);
  if (nz > 1 && slice.empty()) return kept3D(std::move(in), fluid, request);
  if (!slice.empty()) {
    in.sliceSpec = parseSlice(slice);
    in.mask = applySlice(in, slice);
    in.slice = nz > 1;
  }
  if (in.velocity.grid.dims[0] < 2 || in.velocity.grid.dims[1] < 2 || !in.velocity.grid.is2D())
    throw DataArrayError(in.source + ": array '" + array + "' needs at least 2 x 2 nodes in x "
                         "and y, the grid is " + in.velocity.grid.describe(), array);
  const std::optional<ScalarField> slicedFluid =
      fluid ? std::optional<ScalarField>(slicedScalar(in, *fluid)) : std::nullopt;
  if (slicedFluid && isThresholdMask(request.mask)) in.thresholded = zeroNodes(*slicedFluid);
  addMask(in.mask, flowMask(in.velocity, slicedFluid ? &*slicedFluid : nullptr));
  if (maskedCount(in.mask) == 0) in.mask.clear();
  if (!request.crop.empty()) applyCrop(in, request.crop);
  return in;
}

VectorField FlowInput::topologyVelocity() const {
  if (thresholded.empty()) return withWallLayerContinued(velocity, mask);
  PointMask walled = mask;
  for (std::size_t n = 0; n < walled.size(); ++n) walled[n] = walled[n] && !thresholded[n];
  return withMaskedNaN(withWallLayerContinued(velocity, walled), thresholded);
}

RestingWalls FlowInput::restingWalls() const {
  RestingWalls walls = restingWallsOf(image, velocity, mask, source);
  for (std::size_t n = 0; n < thresholded.size() && !walls.solid.empty(); ++n)
    walls.solid[n] = walls.solid[n] && !thresholded[n];
  const bool zLayer = sliceSpec.kind == SliceSpec::none ||
                      (sliceSpec.axis == 2 && sliceSpec.kind != SliceSpec::byPlane);
  if (cropBox || !zLayer) walls.sides = {};
  return walls;
}

ScalarField onFlowGrid(const FlowInput& in, const ScalarField& field) {
  ScalarField s = slicedScalar(in, field);
  return in.cropBox ? crop(s, *in.cropBox) : s;
}

ColourScalar colourScalar(const FlowInput& in, const std::string& name, const std::string& units) {
  const std::string speedUnit = " (" + (units.empty() ? in.units : units) + "/s)";
  ColourScalar c;
  if (name == "speed" && in.slice)
    c = {magnitude(inPlaneVelocity(in.velocity), "in-plane speed"),
         "in-plane speed |v_xy|" + speedUnit};
  else if (name == "speed")
    c = {magnitude(in.velocity, "speed"), "speed |v|" + speedUnit};
  else if (name == "vorticity")
    c = {*derivedScalar(in.velocity, name), "vorticity (1/s)"};
  else
    c = {onFlowGrid(in, scalarFieldFrom(in.image, name, in.source)), name};
  c.field = withMaskedNaN(c.field, in.mask);  // solids in the masked grey, out of the range
  return c;
}

void throwMissingArrayOption(const std::filesystem::path& file) {
  vtkSmartPointer<vtkImageData> image = readImageData(file);
  throw UsageError("needs -a ARRAY, the vector array to use; file " +
                   file.string() + " has: " + describePointArrays(image));
}

void refuseUnderlayAsBackground(const ParsedArgs& a, const std::string& what) {
  const std::string b = a.value("--background");
  if (b == "speed" || b == "lic")
    throw UsageError("--background " + b + ": --background is the backdrop (white|dark, as in "
                     "fluidviz lic); the picture under the " + what + " is --underlay " + b);
}

void requirePictureFile(const std::filesystem::path& file) {
  try {
    pictureFormatOf(file);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

}  // namespace fluidviz::app
