// fluidviz lic: a LIC picture of a vector array of a .vti file, coloured by a scalar.
#include <ostream>

#include "apps/fluidviz/FlowCommandSupport.h"
#include "apps/fluidviz/FlowCommands.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "pipeline/FlowFields.h"
#include "fieldviz/render/LicPicture.h"
#include "filters/lic/LineIntegralConvolution.h"

namespace fluidviz::app {

namespace {

const char* kLicHelp = R"(fluidviz lic FIELD.vti -a ARRAY -o OUT.png [options]

Line Integral Convolution of a vector array (Cabral & Leedom 1993; FastLIC, Stalling & Hege 1995):
white noise smeared along the streamlines, over a colour map of a scalar:
pixel = colour + w * (lic - 1/2) per channel (an average pixel shows the legend's colour), with a
colour legend and a title. The picture is sized so
that every texture pixel is one picture pixel.

Input:
  -a, --array ARRAY        vector array (2 or 3 components) to convolve
  --slice z=K              3D fields: the z layer K to use, [0, nz-1] (required for 3D)
Texture (defaults and ranges: docs/scenes.md, output.lic):
  --resolution WxH         texture size in px (default 800 wide, height from the aspect ratio)
  --length L               kernel half-length in px, [1, 1000] (default 20)
  --method fast|reference  FastLIC (default) or one streamline per pixel
  --kernel box|hann        convolution kernel (default box)
  --step H                 px between samples along a streamline, [0.05, 10] (default 0.5)
  --seed S                 noise seed, [0, 2147483647] (default 1)
  --grain G                noise cell size in px, [1, 100] (default 1)
  --vectors normalized|speed   full kernel everywhere, or kernel length ~ |v|
  --enhance                second pass over the first (Okada & Kao 1997)
  --no-contrast            keep the raw convolution values (no histogram stretch)
  --contrast-sigmas S      std devs mapped to half the grey range, (0, 10] (default 2.5)
  --mask-speed F           mask pixels with |v| <= F max|v|, [0, 1) (default 0: none)
Picture:
  --color-by NAME          speed (default), vorticity, or a scalar array of the file
  --weight W               LIC contrast w in [0, 1] (default 0.6; 0 = colour map only)
  --colormap NAME          viridis (default; coolwarm for vorticity), inferno, coolwarm, ...
  --range MIN,MAX          colour range (default: the scalar's range; symmetric for vorticity)
  --title TEXT             title above the picture
  --background white|dark  picture background
Outputs:
  -o, --output OUT.png     the picture (written atomically)
  --vti OUT.vti            also the texture as image data (arrays lic, lic_mask) for ParaView

Errors (exit code 2): missing file or array (the arrays present are listed), a scalar array for
-a, a 3D field without --slice, NaN or infinite values in the array, options outside their range.
)";

const std::vector<KeyFlag> kLicFlags = {
    {"--length", "length", KeyFlag::number},
    {"--method", "method", KeyFlag::text},
    {"--kernel", "kernel", KeyFlag::text},
    {"--step", "step", KeyFlag::number},
    {"--seed", "noise_seed", KeyFlag::number},
    {"--grain", "noise_grain", KeyFlag::number},
    {"--vectors", "vectors", KeyFlag::text},
    {"--contrast-sigmas", "contrast_sigmas", KeyFlag::number},
    {"--mask-speed", "mask_speed", KeyFlag::number},
    {"--resolution", "width", KeyFlag::custom},
    {"--resolution", "height", KeyFlag::custom}};
const std::vector<KeyFlag> kBlendFlags = {
    {"--color-by", "color_by", KeyFlag::text},
    {"--weight", "lic_weight", KeyFlag::number}};
const std::vector<KeyFlag> kPictureFlags = {
    {"--colormap", "colormap", KeyFlag::text},
    {"--title", "title", KeyFlag::text},
    {"--background", "background", KeyFlag::text},
    {"--range", "range_min", KeyFlag::custom},
    {"--range", "range_max", KeyFlag::custom}};

struct LicArgs {
  std::filesystem::path field, png, vti;
  std::string array, slice;
  lic::LicParams lic;
  LicBlendParams blend;
  FieldImageParams picture;
};

LicArgs parseLicArgs(const ParsedArgs& a) {
  LicArgs r;
  if (a.positional.size() != 1)
    throw UsageError("fluidviz lic needs exactly one field file (.vti), got " +
                     std::to_string(a.positional.size()));
  r.field = a.positional[0];
  r.array = a.value("--array");
  r.slice = a.value("--slice");
  r.png = a.value("--output");
  r.vti = a.value("--vti");
  if (r.png.empty()) throw UsageError("fluidviz lic needs -o OUT.png");
  // Texture keys go through LicParams' own declaration, so ranges and messages are the scene's.
  scene::json texture = scene::json::object();
  texture["width"] = 800;
  if (a.has("--resolution")) {
    const auto [w, h] = parseSize("--resolution", a.value("--resolution"));
    texture["width"] = w, texture["height"] = h;
  }
  texture["enhance"] = a.has("--enhance");
  texture["contrast"] = !a.has("--no-contrast");
  readFlags(a, kLicFlags, r.lic, texture);
  checkWithFlagNames(kLicFlags, [&] { lic::validateLicParams(r.lic); });
  readFlags(a, kBlendFlags, r.blend);
  scene::json picture = scene::json::object();
  if (a.has("--range")) {
    const auto range = parseNumbers("--range", a.value("--range"), 2);
    picture["range_min"] = range[0], picture["range_max"] = range[1];
  }
  // A signed scalar reads best on a diverging map whose middle colour is zero.
  if (r.blend.color_by == "vorticity") picture["colormap"] = "coolwarm";
  readFlags(a, kPictureFlags, r.picture, picture);
  checkWithFlagNames(kPictureFlags, [&] { validateFieldImageParams(r.picture); });
  return r;
}

// LIC refuses non-finite vectors; the message must name the file as well as the array.
lic::LicImage computeTexture(const FlowInput& in, const lic::LicParams& params) {
  try {
    return lic::computeLic(in.velocity, params);
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
  const ParsedArgs a = parseArgs(
      args,
      {"--array", "--output", "--slice", "--resolution", "--length", "--method", "--kernel",
       "--step", "--seed", "--grain", "--vectors", "--contrast-sigmas", "--mask-speed",
       "--color-by", "--weight", "--colormap", "--range", "--title", "--background", "--vti"},
      {"--help", "--enhance", "--no-contrast"},
      {{"-a", "--array"}, {"-o", "--output"}, {"-h", "--help"}});
  if (a.has("--help")) {
    out << kLicHelp;
    return kSuccess;
  }
  LicArgs r = parseLicArgs(a);
  if (r.array.empty()) throwMissingArrayOption("lic", r.field);
  const FlowInput in = readFlowInput(r.field, r.array, r.slice);
  const ScalarField colour = colourScalar(in, r.blend.color_by);
  requireWritableFolder(r.png);
  if (!r.vti.empty()) requireWritableFolder(r.vti);
  const lic::LicImage texture = computeTexture(in, r.lic);
  if (r.picture.title.empty())
    r.picture.title = "LIC of " + r.array + ", coloured by " + r.blend.color_by;
  if (r.blend.color_by == "vorticity") useSymmetricRange(colour, r.picture);
  const LicPicture picture =
      renderLicPicture(texture.texture, texture.mask, colour, r.picture, r.blend);
  writePng(picture.image, r.png);
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
