#pragma once
// What `fluidviz lic` and `fluidviz streamlines` share: option parsing, flags that set keys of a
// parameter struct (with the struct's own range checks and messages), and reading the vector
// field (2D, or one z layer of a 3D field) with errors that name the file and the array.
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "apps/fluidviz/Commands.h"
#include "fieldviz/core/Field.h"
#include "fieldviz/core/FieldSlices.h"
#include "fieldviz/core/PointMask.h"
#include "fieldviz/core/RestingWalls.h"
#include "fieldviz/core/LengthUnit.h"
#include "fieldviz/io/ImageSampling.h"
#include "fieldviz/scene/ParamVisitors.h"

class vtkImageData;

namespace fluidviz::app {

/// A command line split into positional arguments, options with a value and switches.
struct ParsedArgs {
  std::vector<std::string> positional;
  std::map<std::string, std::string> values;  ///< "--length" -> "30"
  std::set<std::string> switches;             ///< "--enhance"
  bool has(const std::string& option) const {
    return values.count(option) > 0 || switches.count(option) > 0;
  }
  std::string value(const std::string& option, const std::string& fallback = "") const {
    auto it = values.find(option);
    return it == values.end() ? fallback : it->second;
  }
};

/// `aliases` maps short forms ("-a") to long ones ("--array"). Throws UsageError for unknown
/// options, a missing value or an option given twice.
ParsedArgs parseArgs(const std::vector<std::string>& args, const std::set<std::string>& valued,
                     const std::set<std::string>& switches,
                     const std::map<std::string, std::string>& aliases);

/// A flag that sets one key of a parameter struct.
struct KeyFlag {
  enum Kind {
    number,  ///< the value is a number
    text,    ///< the value is a string
    custom   ///< the command parses the value itself; listed to name the flag in messages
  };
  std::string flag;  ///< "--length"
  std::string key;   ///< "length" (dotted for nested keys: "evenly_spaced.separating_distance")
  Kind kind;
};

/// Reads the flags of `table` present in `a` into `params` through the struct's describe()
/// declaration (so ranges, choices and messages are the scene file's). Extra keys already in
/// `json` are read too. Throws UsageError naming the flag: "--length is 0 px, outside ...".
template <class S>
void readFlags(const ParsedArgs& a, const std::vector<KeyFlag>& table, S& params,
               scene::json json = scene::json::object());

/// Flag name for a key of `table` ("length" -> "--length", "line_color[1]" ->
/// "--line-color[1]"), or the key itself.
std::string flagForKey(const std::vector<KeyFlag>& table, const std::string& key);

/// Runs `check` (a validate function of a parameter struct) and turns its ParamError into a
/// UsageError naming the flag of the key.
template <class F>
void checkWithFlagNames(const std::vector<KeyFlag>& table, F&& check) {
  try {
    check();
  } catch (const ParamError& e) {
    throw UsageError(flagForKey(table, e.key()) + " " + e.what());
  }
}

/// Adds flag `f`'s value to `json` at its (dotted) key. Throws UsageError for a bad number.
void putFlagValue(scene::json& json, const KeyFlag& f, const std::string& value);

/// "WxH", "W" or "Wx0" -> {W, H}. Throws UsageError naming `flag`.
std::pair<int, int> parseSize(const std::string& flag, const std::string& text);
/// "a,b,c" -> numbers (exactly `count` of them). Throws UsageError naming `flag`.
std::vector<double> parseNumbers(const std::string& flag, const std::string& text, int count);

/// --units for the commands that parse their own flags (lic declares it through KeyOptions).
extern const std::vector<KeyFlag> kUnitsFlag;
/// The help line of --units, from LengthUnitParams' declaration (the docs/units.md row).
std::string unitsHelpLine();
/// The --units value of `a`, checked; nullopt when not given. Throws UsageError naming --units.
std::optional<std::string> unitsOption(const ParsedArgs& a);
/// The length unit in force for `image` read from `source` ("file X"): `option` when given, else
/// the image's field-data string length_unit (docs/units.md), else "m". Throws FileError for a
/// length_unit that is not an allowed name.
std::string lengthUnitOf(vtkImageData* image, const std::filesystem::path& file,
                         const std::optional<std::string>& option);

/// A parsed --slice: how the 2D field is cut out of a 3D one.
struct SliceSpec {
  enum Kind { none, byIndex, byCoordinate, byPlane } kind = none;
  int axis = 2;             ///< 0, 1, 2 for x, y, z (index and coordinate)
  int index = 0;            ///< node index (kind byIndex)
  double coordinate = 0.0;  ///< world coordinate (kind byCoordinate)
  SlicePlane plane;         ///< (kind byPlane)
};

/// The help of --slice and --mask and --crop, shared by lic, streamlines and topology.
extern const char* const kSliceHelp;
extern const char* const kMaskHelp;
extern const char* const kCropHelp;
/// The switch that turns off what the commands take from the file's own arrays without being
/// asked (FlowRequest::file_arrays; resample: the particles' smoothing_length), and its help.
extern const char* const kIgnoreFileArraysFlag;
extern const char* const kIgnoreFileArraysHelp;
/// The help line of --ignore-file-arrays for the commands that print their own help.
std::string ignoreFileArraysHelpLine();

/// --spacing for the commands that parse their own flags (lic declares it through KeyOptions).
extern const std::vector<KeyFlag> kSpacingFlag;
/// The help line of --spacing, from ImageSampling's declaration (the docs/input_formats.md row).
std::string spacingHelpLine();
/// The --spacing value of `a`, checked (> 0); automatic sampling when not given. Throws
/// UsageError naming --spacing.
ImageSampling samplingOption(const ParsedArgs& a);

/// The vector field a flow command works on.
struct FlowInput {
  std::filesystem::path file;
  std::string source;                   ///< "file X", the prefix of messages
  vtkSmartPointer<vtkImageData> image;  ///< for further arrays (colour scalars)
  std::string array;
  int layer = 0;                        ///< z layer of a 3D field (0 in 2D)
  bool slice = false;                   ///< velocity is a z layer of a 3D field
  VectorField velocity;                 ///< 2D: the file's field or its slice, cropped
  std::string units = "m";              ///< length unit in force (lengthUnitOf)
  SliceSpec sliceSpec;                  ///< the --slice in force
  std::optional<NodeBox> cropBox;       ///< --crop, nodes of the uncropped 2D field
  /// Masked nodes of `velocity` (PointMask.h): NaN/inf, vtkValidPointMask, --mask, outside a
  /// plane slice, no-slip solids. Empty when nothing is masked.
  PointMask mask;
  /// Velocity with NaN at masked nodes: what LIC, streamlines and separatrices follow.
  VectorField maskedVelocity() const { return withMaskedNaN(velocity, mask); }
  /// The nodes a threshold --mask (ARRAY>V, ARRAY<V) masks: the edge of such a region is no wall.
  PointMask thresholded;
  /// The field critical points are found in: NaN at masked nodes, except the wall layer of a
  /// solid, a NaN region or a mask array (withWallLayerContinued), continued from the fluid so
  /// that stagnation points on a body's wall are found. A threshold of an image (PC-MRI
  /// magnitude) has no wall, the flow goes on past its edge: no zero is made up there.
  VectorField topologyVelocity() const;
  /// The no-slip walls at rest (RestingWalls.h): masked nodes of zero velocity that are no
  /// threshold's edge, and the sides the file names in its field data, which are the grid's own
  /// sides only without --crop and for the file's 2D field or a z layer of a 3D one.
  RestingWalls restingWalls() const;
};

/// What a flow command asks of its input file: each command-line option that shapes the field
/// (the file, -a, --slice, --units, --spacing) lands here, so that every command reads its input
/// the same way.
struct FlowRequest {
  std::filesystem::path file;
  std::string array;
  std::string slice;                 ///< the --slice value, "" when not given
  std::optional<std::string> units;  ///< --units; nullopt: the file's length_unit, else m
  ImageSampling sampling;            ///< how a grid that is not an image is resampled
  std::string mask;                  ///< --mask ARRAY (nonzero = fluid), "" when not given
  std::string crop;                  ///< --crop x0,x1,y0,y1, "" when not given
  bool keep_3d = false;              ///< a 3D field without --slice stays 3D (3D streamlines)
  /// The file's vtkValidPointMask (snapshots' solids, resampled grids' particle support) masks
  /// when no --mask is given; false: --ignore-file-arrays.
  bool file_arrays = true;
};

/// Reads `request.array` of `request.file`. Throws FileError (missing/corrupt file, bad
/// length_unit), DataArrayError (missing array, listing those present; a scalar array) and
/// UsageError (3D field without --slice unless keep_3d, a --slice or --crop outside the grid or
/// not of an allowed form, a --mask array that is missing).
FlowInput readFlowInput(const FlowRequest& request);

/// A colour scalar and its legend title.
struct ColourScalar {
  ScalarField field;
  std::string legendTitle;  ///< "speed |v| (m/s)", "in-plane speed |v_xy| (m/s)", "vorticity (1/s)"
};

/// A 1-component array of in.image on in.velocity's grid (the same slice and crop).
ScalarField onFlowGrid(const FlowInput& in, const ScalarField& field);

/// A scalar for colouring: "speed" or "vorticity" of the input's vectors, else the named
/// 1-component array of the file (same layer). The speed of a z layer of a 3D field is its
/// in-plane part |v_xy| = sqrt(vx^2 + vy^2), the speed LIC and streamlines follow. `units`
/// overrides in.units in the title. NaN at in.mask's nodes. Throws DataArrayError naming the file.
ColourScalar colourScalar(const FlowInput& in, const std::string& name,
                          const std::string& units = "");

/// Message for a -a that was not given: the arrays of the file, so the user can pick one.
[[noreturn]] void throwMissingArrayOption(const std::filesystem::path& file);

// ------------------------------------------------------------------------------------------------

template <class S>
void readFlags(const ParsedArgs& a, const std::vector<KeyFlag>& table, S& params,
               scene::json json) {
  for (const KeyFlag& f : table)
    if (f.kind != KeyFlag::custom && a.values.count(f.flag)) putFlagValue(json, f, a.values.at(f.flag));
  checkWithFlagNames(table, [&] { scene::readParams(json, params, ""); });
}

/// --background is the backdrop (white|dark) in every command; the picture under the lines or
/// glyphs (`what`) is --underlay lic|speed (issue 16, defect 10). Throws UsageError telling the
/// new flag when --background is given lic or speed.
void refuseUnderlayAsBackground(const ParsedArgs& a, const std::string& what);

/// A picture output's name must end in .png, .jpg or .jpeg (the format follows it): checked
/// before anything is computed. Throws UsageError naming the file.
void requirePictureFile(const std::filesystem::path& file);

}  // namespace fluidviz::app
