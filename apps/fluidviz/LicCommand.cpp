// fluidviz lic: a LIC picture of a vector array of a .vti file, coloured by a scalar.
#include <ostream>

#include "apps/fluidviz/FlowCommandSupport.h"
#include "apps/fluidviz/FlowCommands.h"
#include "apps/fluidviz/KeyOptions.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "pipeline/FlowFields.h"
#include "fieldviz/render/LicPicture.h"
#include "filters/lic/LineIntegralConvolution.h"
#include "filters/lic/PixelVelocity.h"

namespace fluidviz::app {

namespace {

const char* kLicAbout = R"(fluidviz lic FIELD.vti -a ARRAY -o OUT.png [options]

Line Integral Convolution of a vector array (Cabral & Leedom 1993; FastLIC, Stalling & Hege 1995):
white noise smeared along the streamlines, over a colour map of a scalar:
pixel = colour + w * (lic - 1/2) per channel (an average pixel shows the legend's colour), with a
colour legend and a title. The picture is sized so that every texture pixel is one picture pixel.
The options that set keys are those of output.lic in docs/scenes.md, with the same defaults and
ranges.

Errors (exit code 2): missing file or array (the arrays present are listed), a scalar array for
-a, a 3D field without --slice, a --slice or --crop outside the grid, options outside their
range. NaN or infinite values are masked (drawn in the mask colour).)";

struct LicArgs {
  std::vector<std::string> fields;
  std::filesystem::path png, vti;
  std::string array, slice, resolution, range, mask, crop;
  bool ignoreFileArrays = false;
  lic::LicParams lic;
  LicBlendParams blend;
  FieldImageParams picture;
  std::optional<std::string> units;  ///< --units; nullopt: the file's or m
  ImageSampling sampling;            ///< --spacing
};

// The command's own options and those generated from the keys of output.lic.
struct LicCommandLine {
  CLI::App app{kLicAbout, "fluidviz lic"};
  LicArgs r;
  KeyOptions texture, blend, picture, units, spacing;

  LicCommandLine() {
    app.add_option("FIELD", r.fields, "the .vti file")->group("Input");
    app.add_option("-a,--array", r.array, "vector array (2 or 3 components) to convolve")
        ->group("Input");
    app.add_option("--slice", r.slice, kSliceHelp)->type_name("SLICE")->group("Input");
    app.add_option("--mask", r.mask, kMaskHelp)->type_name("ARRAY")->group("Input");
    app.add_flag(kIgnoreFileArraysFlag, r.ignoreFileArrays, kIgnoreFileArraysHelp)->group("Input");
    app.add_option("--crop", r.crop, kCropHelp)->type_name("x0,x1,y0,y1")->group("Input");
    units.add<LengthUnitParams>(app, {{"units"}}, "Input");
    spacing.add<ImageSampling>(app, {{"spacing"}}, "Input");
    app.add_option("--resolution", r.resolution,
                   "texture size in px (default " + std::to_string(kDefaultPictureWidth) +
                       " wide, height from the aspect ratio)")
        ->type_name("WxH")
        ->group("Texture");
    texture.add<lic::LicParams>(app,
                                {{"length"}, {"method"}, {"kernel"}, {"step"}, {"noise_seed"},
                                 {"noise_grain"}, {"vectors"}, {"enhance"}, {"contrast"},
                                 {"contrast_sigmas"}, {"mask_speed"}},
                                "Texture");
    blend.add<LicBlendParams>(app, {{"color_by"}, {"lic_weight"}}, "Picture");
    picture.add<FieldImageParams>(app, {{"colormap"}, {"title"}, {"background"}, {"axes"}},
                                  "Picture");
    app.add_option("--range", r.range, "colour range (default: the scalar's range; symmetric "
                                       "for vorticity)")
        ->type_name("MIN,MAX")
        ->group("Picture");
    app.add_option("-o,--output", r.png, "the picture (written atomically)")->group("Outputs");
    app.add_option("--vti", r.vti, "also the texture as image data (arrays lic, lic_mask) for "
                                   "ParaView")
        ->group("Outputs");
  }

  LicArgs read() {
    if (r.fields.size() != 1)
      throw UsageError("needs exactly one field file (.vti), got " +
                       std::to_string(r.fields.size()));
    if (r.png.empty()) throw UsageError("needs -o OUT.png");
    scene::json size = scene::json::object();
    size["width"] = kDefaultPictureWidth;
    if (!r.resolution.empty()) {
      const auto [w, h] = parseSize("--resolution", r.resolution);
      size["width"] = w, size["height"] = h;
    }
    texture.read(r.lic, size);
    texture.checkWithFlagNames([&] { lic::validateLicParams(r.lic); });
    blend.read(r.blend);
    scene::json colours = scene::json::object();
    if (!r.range.empty()) {
      const auto range = parseNumbers("--range", r.range, 2);
      colours["range_min"] = range[0], colours["range_max"] = range[1];
    }
    // A signed scalar reads best on a diverging map whose middle colour is zero.
    if (r.blend.color_by == "vorticity") colours["colormap"] = "coolwarm";
    picture.read(r.picture, colours);
    picture.checkWithFlagNames([&] { validateFieldImageParams(r.picture); });
    if (units.given("units")) {
      LengthUnitParams given;
      units.read(given);
      units.checkWithFlagNames([&] { validateLengthUnit(given); });
      r.units = given.units;
    }
    if (spacing.given("spacing")) spacing.read(r.sampling);
    return r;
  }
};

// LIC refuses non-finite vectors; the message must name the file as well as the array, and the
// option that masks regions as the user types it here.
lic::LicImage computeTexture(const FlowInput& in, const lic::LicParams& params,
                             const std::string& maskOption) {
  try {
    return lic::computeLic(in.velocity, params, in.mask);
  } catch (const lic::NonFiniteFieldError& e) {
    const std::string remedy = lic::NonFiniteFieldError::maskRemedy(maskOption);
    throw FileError(in.file, in.source + ": " + e.message(remedy), in.array);
  } catch (const std::invalid_argument& e) {
    throw FileError(in.file, in.source + ": " + e.what(), in.array);
  }
}

void writeTextureVti(const lic::LicImage& img, const std::filesystem::path& vti) {
  FieldSet set;
  set.grid = img.texture.grid;
  set.add(img.texture);
  set.add(ScalarField{"lic_mask", img.texture.grid,
                      std::vector<double>(img.mask.begin(), img.mask.end())});
  writeVti(set, vti);
}

}  // namespace

int licCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream&, bool) {
  LicCommandLine commandLine;
  if (!parseCommandLine(commandLine.app, args, out)) return kSuccess;
  LicArgs r = commandLine.read();
  const std::filesystem::path field = r.fields[0];
  if (r.array.empty()) throwMissingArrayOption(field);
  const FlowInput in = readFlowInput(
      {field, r.array, r.slice, r.units, r.sampling, r.mask, r.crop, false, !r.ignoreFileArrays});
  const ColourScalar colour = colourScalar(in, r.blend.color_by);
  requirePictureFile(r.png);
  requireWritableFolder(r.png);
  if (!r.vti.empty()) requireWritableFolder(r.vti);
  const lic::LicImage texture =
      computeTexture(in, r.lic, commandLine.texture.flagForKey("mask_speed"));
  if (!commandLine.picture.given("title"))  // an empty --title: no title
    r.picture.title = "LIC of " + r.array + ", coloured by " + r.blend.color_by;
  if (r.picture.scalar_bar_title.empty()) r.picture.scalar_bar_title = colour.legendTitle;
  r.picture.axes_unit = in.units;
  if (r.blend.color_by == "vorticity") useSymmetricRange(colour.field, r.picture);
  const LicPicture picture =
      renderLicPicture(texture.texture, texture.mask, colour.field, r.picture, r.blend);
  writePicture(picture.image, r.png);
  const PixelRect& t = picture.texture;
  out << "wrote " << r.png.string() << " (" << picture.image.width << " x "
      << picture.image.height << " px; texture " << texture.width() << " x " << texture.height()
      << " px at picture pixels x [" << t.left << ", " << t.right << "), y [" << t.top << ", "
      << t.bottom << "); colour range [" << picture.range[0] << ", " << picture.range[1]
      << "])\n";
  if (!r.vti.empty()) {
    writeTextureVti(texture, r.vti);
    out << "wrote " << r.vti.string() << "\n";
  }
  return kSuccess;
}

}  // namespace fluidviz::app
