#include "apps/fluidviz/FlowCommandSupport.h"

#include <vtkImageData.h>

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

namespace {

// "z=K" -> K, checked against the field's layers.
int parseLayer(const std::string& slice, const FlowInput& in, int nz) {
  std::size_t used = 0;
  int k = -1;
  try {
    if (slice.rfind("z=", 0) == 0) k = std::stoi(slice.substr(2), &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used + 2 != slice.size())
    throw UsageError("--slice is '" + slice + "'; expected z=K with K the z index of a layer");
  if (k < 0 || k >= nz)
    throw UsageError("--slice is z=" + std::to_string(k) + ", outside [0, " +
                     std::to_string(nz - 1) + "] for " + in.source + " (" +
                     in.velocity.grid.describe() + ")");
  return k;
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
  if (nz > 1 && slice.empty())
    throw UsageError(in.source + ": array '" + array + "' is 3D (" + in.velocity.grid.describe() +
                     "); give --slice z=K with K in [0, " + std::to_string(nz - 1) +
                     "] to work on one layer");
  if (!slice.empty()) {
    in.layer = parseLayer(slice, in, nz);
    in.velocity = sliceZ(in.velocity, in.layer);
    in.slice = nz > 1;
  }
  if (in.velocity.grid.dims[0] < 2 || in.velocity.grid.dims[1] < 2)
    throw DataArrayError(in.source + ": array '" + array + "' needs at least 2 x 2 nodes in x "
                         "and y, the grid is " + in.velocity.grid.describe(), array);
  return in;
}

ColourScalar colourScalar(const FlowInput& in, const std::string& name, const std::string& units) {
  const std::string speedUnit = " (" + (units.empty() ? in.units : units) + "/s)";
  if (name == "speed" && in.slice)
    return {magnitude(inPlaneVelocity(in.velocity), "in-plane speed"),
            "in-plane speed |v_xy|" + speedUnit};
  if (name == "speed") return {magnitude(in.velocity, "speed"), "speed |v|" + speedUnit};
  if (name == "vorticity") return {*derivedScalar(in.velocity, name), "vorticity (1/s)"};
  ScalarField s = scalarFieldFrom(in.image, name, in.source);
  return {s.grid.is2D() ? s : sliceZ(s, in.layer), name};
}

void throwMissingArrayOption(const std::filesystem::path& file) {
  vtkSmartPointer<vtkImageData> image = readImageData(file);
  throw UsageError("needs -a ARRAY, the vector array to use; file " +
                   file.string() + " has: " + describePointArrays(image));
}

}  // namespace fluidviz::app
