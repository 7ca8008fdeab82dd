// fluidviz resample: SPH interpolation of a particle file (.vtp) onto a regular grid (.vti), with
// optional 3D pictures of the particles and of a volume rendering of the grid.
#include <omp.h>
#include <vtkImageData.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <ostream>

#include "apps/fluidviz/FlowCommandSupport.h"
#include "apps/fluidviz/KeyOptions.h"
#include "apps/fluidviz/ParticleCommands.h"
#include "apps/fluidviz/View3DFlags.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "fieldviz/render/ParticleRendering.h"
#include "fieldviz/render/VolumeRendering.h"
#include "filters/resample/ParticleResampler.h"
#include "filters/resample/vtk/ParticleSetVtk.h"
#include "fieldviz/vtk/ImageDataAdapter.h"

namespace fluidviz::app {

namespace {

namespace rs = fluidviz::resample;

const char* kResampleHelpHead = R"(fluidviz resample PARTICLES.vtp -o GRID.vti [options]

SPH interpolation of the particles' point arrays onto a regular grid, Shepard-normalised:
  A(x) = sum_j V_j A_j W(x - x_j, h) / sum_j V_j W(x - x_j, h),   V_j = m_j / rho_j
or, with --order linear, first order (exact for linear fields) where the particles allow it,
with the array 'resample_order' (1 there, 0 where the node kept the Shepard value).
The grid also gets 'color' = sum_j V_j W (~1 inside the fluid, 0.5 at a free surface: contour
it with fluidviz isosurface -a color --value 0.5), 'mask' (1 where color >= --threshold; the
other nodes hold NaN, or --empty-value) and, with masses, 'summation_density' = sum_j m_j W.
Without mass and density arrays every particle gets the volume s^d, s being --particle-spacing
or the median nearest-neighbour distance; the choices made are printed. The smoothing length is
the particles' array smoothing_length when they have one (fluidviz run's snapshots have it, with
mass and density), else 1.3 s. The grid flags the nodes with particle support in
vtkValidPointMask (1 = supported, as 'mask'), which lic, streamlines and topology mask by.

Grid and kernel (ranges: filters/resample/ResampleParams.h):
  --spacing D              grid node distance, m (default: the particle spacing s)
  --dims N                 nodes along the grid's longest axis, instead of --spacing
  --padding P              margin around the particles, m (default: kernel support 2h)
  --kernel NAME            cubic_spline (default), wendland_c2 or poly6; support 2h
)";

// The options whose help line is generated from their describe() declaration (the docs row).
const char* kResampleHelpGrid = R"(  --h H                    smoothing length, m (default: the array smoothing_length, else 1.3 s)
  --threshold T            support threshold on color, [0, 1] (default 0.05)
  --empty-value V          value of unsupported nodes (default NaN)
  --dimension 2|3          (default: 2 when all particles have the same z)
  --max-memory-mb M        refuse grids that need more memory (default 4096)
Particles:
  --arrays a,b,...         arrays to resample (default: all point arrays)
  --mass-array NAME        (default mass)      --density-array NAME   (default density)
  --particle-spacing S     s, m                --particle-volume V    V_j of every particle
  --ignore-file-arrays     do not take h from the particles' array smoothing_length
Pictures:
  --png-particles OUT.png  the particles as lit spheres of radius --radius (default s/2)
  --png-volume OUT.png     volume rendering of the grid's --volume-array (default color)
  --color-by ARRAY         colour the particles by this particle array (default: one colour)
  --radius R               sphere radius, m         --sprites   shaded discs (fast, 10^6)
  --colormap NAME          (default viridis; volume: inferno)
)";

const char* kResampleHelpTail = R"(Other:
  -o, --output GRID.vti    the grid (written atomically)
  --threads N              OpenMP threads (default: all cores)

Errors (exit code 2): missing or corrupt file, unknown array (those present are listed), a
grid that would need more than --max-memory-mb (the memory it would need is printed, nothing
is allocated or written), options outside their range.
)";

const std::vector<KeyFlag> kResampleFlags = {
    {"--spacing", "spacing", KeyFlag::number},
    {"--dims", "dims", KeyFlag::number},
    {"--padding", "padding", KeyFlag::number},
    {"--kernel", "kernel", KeyFlag::text},
    {"--order", "order", KeyFlag::text},
    {"--h", "smoothing_length", KeyFlag::number},
    {"--threshold", "support_threshold", KeyFlag::number},
    {"--empty-value", "empty_value", KeyFlag::number},
    {"--dimension", "dimension", KeyFlag::number},
    {"--max-memory-mb", "max_memory_mb", KeyFlag::number},
    {"--arrays", "arrays", KeyFlag::text},
    {"--mass-array", "mass_array", KeyFlag::text},
    {"--density-array", "density_array", KeyFlag::text},
    {"--particle-spacing", "particle_spacing", KeyFlag::number},
    {"--particle-volume", "particle_volume", KeyFlag::number}};
// "  --order NAME             <docs row of key order>": help from the declaration.
std::string declaredOptionHelp(const std::string& key, const std::string& valueName) {
  std::vector<scene::DocRow> rows;
  scene::documentParams<rs::ParticleResampleParams>(rows, "");
  for (const scene::DocRow& row : rows)
    if (row.key == key) {
      std::string option = "  " + optionFlag(row) + " " + valueName;
      option.resize(std::max<std::size_t>(option.size() + 1, 27), ' ');
      return option + keyHelp(row) + "\n";
    }
  throw std::logic_error("ParticleResampleParams declares no key '" + key + "'");
}

std::string resampleHelp() {
  return kResampleHelpHead + declaredOptionHelp("order", "NAME") + kResampleHelpGrid;
}

const std::vector<KeyFlag> kParticleFlags = {
    {"--radius", "radius", KeyFlag::number},
    {"--color-by", "color_by", KeyFlag::text},
    {"--colormap", "colormap", KeyFlag::text}};
const std::vector<KeyFlag> kVolumeFlags = {{"--colormap", "colormap", KeyFlag::text}};

struct ResampleArgs {
  std::filesystem::path particles, grid, particlesPng, volumePng;
  rs::ParticleResampleParams params;
  View3DParams view;
  ParticleStyle particleStyle;
  VolumeStyle volumeStyle;
  std::string volumeArray = "color";
  bool radiusGiven = false;  // else s / 2, known after resampling
  bool fileArrays = true;    // not --ignore-file-arrays: h from the array smoothing_length
  int threads = 0;
};

ParsedArgs parseResampleCommandLine(const std::vector<std::string>& args) {
  std::set<std::string> valued = view3DValuedOptions();
  for (const auto* table : {&kResampleFlags, &kParticleFlags})
    for (const KeyFlag& f : *table) valued.insert(f.flag);
  valued.insert({"--output", "--png-particles", "--png-volume", "--volume-array", "--threads"});
  std::set<std::string> switches = view3DSwitches();
  switches.insert({"--help", "--sprites", kIgnoreFileArraysFlag});
  return parseArgs(args, valued, switches, {{"-o", "--output"}, {"-h", "--help"}});
}

int parseThreads(const ParsedArgs& a) {
  if (!a.has("--threads")) return 0;
  const std::string v = a.value("--threads");
  std::size_t used = 0;
  int n = 0;
  try {
    n = std::stoi(v, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != v.size() || n < 1 || n > 1024)
    throw UsageError("--threads is '" + v + "'; allowed: a whole number from 1 to 1024");
  return n;
}

void readPictureFlags(const ParsedArgs& a, ResampleArgs& r) {
  r.particlesPng = a.value("--png-particles");
  r.volumePng = a.value("--png-volume");
  r.volumeArray = a.value("--volume-array", "color");
  r.view = readView3DFlags(a);
  scene::json particle = scene::json::object();
  particle["radius"] = 1.0;  // placeholder until the particle spacing is known (s / 2)
  particle["method"] = a.has("--sprites") ? "sprites" : "spheres";
  readFlags(a, kParticleFlags, r.particleStyle, particle);
  r.radiusGiven = a.has("--radius");
  readFlags(a, kVolumeFlags, r.volumeStyle);
}

ResampleArgs parseResampleArgs(const ParsedArgs& a) {
  ResampleArgs r;
  if (a.positional.size() != 1)
    throw UsageError("needs exactly one particle file (.vtp), got " +
                     std::to_string(a.positional.size()));
  r.particles = a.positional[0];
  r.grid = a.value("--output");
  if (r.grid.empty()) throw UsageError("needs -o GRID.vti");
  readFlags(a, kResampleFlags, r.params);
  checkWithFlagNames(kResampleFlags, [&] { rs::validateResampleParams(r.params); });
  readPictureFlags(a, r);
  r.threads = parseThreads(a);
  r.fileArrays = !a.has(kIgnoreFileArraysFlag);
  return r;
}

// Everything the user named must exist before any work is done.
void checkNamedArrays(const ResampleArgs& r, const particles::ParticleSet& ps) {
  const std::string& c = r.particleStyle.color_by;
  if (!c.empty() && !ps.findScalar(c) && !ps.findVector(c))
    throw FileError(r.particles, "file " + r.particles.string() + ": --color-by names '" + c +
                                     "', which the particles do not have",
                    c);
}

// The particles' own smoothing length (the array of a fluidviz snapshot, one value per particle:
// their median) unless --h or --ignore-file-arrays is given; the choice is printed.
rs::ParticleResampleParams withFileSmoothingLength(const ResampleArgs& r,
                                                   const particles::ParticleSet& ps,
                                                   std::ostream& out) {
  rs::ParticleResampleParams params = r.params;
  if (params.smoothing_length || !r.fileArrays) return params;
  const std::optional<double> mid = rs::medianSmoothingLength(ps);
  if (!mid) return params;
  if (!(*mid > 0) || !std::isfinite(*mid))
    throw FileError(r.particles, "file " + r.particles.string() + ": particle array '" +
                                     rs::kSmoothingLengthArray + "' has median " +
                                     std::to_string(*mid) + "; a smoothing length must be > 0 "
                                     "(give --h, or --ignore-file-arrays)",
                    rs::kSmoothingLengthArray);
  params.smoothing_length = *mid;
  out << "smoothing length h from the particles' array '" << rs::kSmoothingLengthArray
      << "' (--h or " << kIgnoreFileArraysFlag << " overrides it)\n";
  return params;
}

rs::ResampleResult resampleOrThrow(const ResampleArgs& r, const particles::ParticleSet& ps,
                                   std::ostream& out) {
  const rs::ParticleResampleParams params = withFileSmoothingLength(r, ps, out);
  try {
    rs::ResampleResult result;
    checkWithFlagNames(kResampleFlags, [&] { result = rs::resampleParticles(ps, params); });
    return result;
  } catch (const std::invalid_argument& e) {  // the particle data (ParamError is a UsageError)
    throw FileError(r.particles, "file " + r.particles.string() + ": " + e.what());
  }
}

// The particles as spheres (radius s / 2 unless --radius), coloured by --color-by.
std::unique_ptr<Scene3D> particlesScene(const ResampleArgs& r, const particles::ParticleSet& ps,
                                        const rs::ResampleReport& report) {
  ParticleStyle style = r.particleStyle;
  if (!r.radiusGiven) style.radius = 0.5 * report.particleSpacing;
  auto scene = std::make_unique<Scene3D>(r.view);
  const ParticleActor particles = makeParticleActor(rs::toPolyData(ps), style);
  scene->add(particles.actor);
  if (particles.coloring) scene->setLegend(particles.coloring->table, particles.coloring->title);
  return scene;
}

// 1 where the grid's 'mask' is not 1: nodes without particle support.
PointMask unsupportedNodes(const FieldSet& fields) {
  const ScalarField* support = fields.findScalar(rs::kMaskArray);
  return support ? zeroNodes(*support) : PointMask{};
}

// Volume rendering of --volume-array of the grid.
std::unique_ptr<Scene3D> volumeScene(const ResampleArgs& r, const FieldSet& fields) {
  if (fields.grid.is2D())
    throw UsageError("--png-volume needs a 3D grid; these particles are 2D (use fluidviz "
                     "isosurface --png for isolines)");
  auto scene = std::make_unique<Scene3D>(r.view);
  try {
    const VolumeProp volume = makeVolume(toImageData(fields), r.volumeArray, r.volumeStyle);
    scene->add(volume.volume);
    scene->setLegend(volume.colors, volume.title);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--volume-array: ") + e.what());
  }
  return scene;
}

int runResample(const ResampleArgs& r, std::ostream& out) {
  if (r.threads > 0) omp_set_num_threads(r.threads);
  // Every output folder is checked before the grid is written: no grid without its pictures.
  for (const std::filesystem::path& f : {r.grid, r.particlesPng, r.volumePng})
    if (!f.empty()) requireWritableFolder(f);
  const particles::ParticleSet ps = rs::readParticleVtp(r.particles);
  checkNamedArrays(r, ps);
  const rs::ResampleResult result = resampleOrThrow(r, ps, out);
  out << result.report.summary();
  std::unique_ptr<Scene3D> particles, volume;  // built first: their errors stop everything
  try {
    if (!r.particlesPng.empty()) particles = particlesScene(r, ps, result.report);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--png-particles: ") + e.what());
  }
  if (!r.volumePng.empty()) volume = volumeScene(r, result.fields);
  writeVti(result.fields, unsupportedNodes(result.fields), r.grid);
  out << "wrote " << r.grid.string() << "\n";
  if (particles) writeScenePictures(*particles, r.particlesPng, out);
  if (volume) writeScenePictures(*volume, r.volumePng, out);
  return kSuccess;
}

}  // namespace

int resampleCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream&,
                    bool) {
  const ParsedArgs a = parseResampleCommandLine(args);
  if (a.has("--help")) {
    out << resampleHelp() << kView3DHelp << kResampleHelpTail;
    return kSuccess;
  }
  return runResample(parseResampleArgs(a), out);
}

}  // namespace fluidviz::app
