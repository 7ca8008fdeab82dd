#pragma once
// The whole scene file as one struct: which solver, its parameters, and the outputs wanted.
// docs/scenes.md is generated from these declarations (`fluidviz docs`).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fieldviz/core/Params.h"
#include "fieldviz/render/FieldImage.h"
#include "fieldviz/render/LicBlend.h"
#include "fieldviz/render/ParticleRendering.h"
#include "fieldviz/render/StreamlineOverlay.h"
#include "fieldviz/render/SurfaceRendering.h"
#include "fieldviz/render/View3D.h"
#include "filters/resample/ResampleParams.h"
#include "filters/isosurface/IsosurfaceParams.h"
#include "filters/lic/LicParams.h"
#include "filters/streamlines/Seeding.h"
#include "filters/streamlines/StreamlineParams.h"
#include "filters/topology/TopologyParams.h"
#include "pipeline/LbmSketchParams.h"
#include "pipeline/PictureSeriesParams.h"
#include "pipeline/ProbeParams.h"
#include "pipeline/TimeSeriesParams.h"
#include "pipeline/TopologyOutputs.h"
#include "solvers/fhp/FhpParams.h"
#include "solvers/lbm/LbmParams.h"
#include "solvers/sph/SphParams.h"

namespace fluidviz {

/// A field of the final state that output.images can draw (named as the field's array).
enum class ImageField {
  speed, density, pressure, velocity_x, velocity_y, velocity_z, vorticity, stream_function
};
constexpr std::array<Choice<ImageField>, 8> paramChoices(ImageField) {
  return {{{ImageField::speed, "speed"},
           {ImageField::density, "density"},
           {ImageField::pressure, "pressure"},
           {ImageField::velocity_x, "velocity_x"},
           {ImageField::velocity_y, "velocity_y"},
           {ImageField::velocity_z, "velocity_z"},
           {ImageField::vorticity, "vorticity"},
           {ImageField::stream_function, "stream_function"}}};
}

/// The pictures that show the streamlines.
enum class DrawOn { lic, images, all, none };
constexpr std::array<Choice<DrawOn>, 4> paramChoices(DrawOn) {
  return {{{DrawOn::lic, "lic"}, {DrawOn::images, "images"}, {DrawOn::all, "all"},
           {DrawOn::none, "none"}}};
}

/// The grid array a free surface is the level set of (named as that array).
enum class SurfaceField { color, summation_density };
constexpr std::array<Choice<SurfaceField>, 2> paramChoices(SurfaceField) {
  return {{{SurfaceField::color, "color"}, {SurfaceField::summation_density, "summation_density"}}};
}

enum class ViewShow { surface, particles, surface_and_particles };
constexpr std::array<Choice<ViewShow>, 3> paramChoices(ViewShow) {
  return {{{ViewShow::surface, "surface"},
           {ViewShow::particles, "particles"},
           {ViewShow::surface_and_particles, "surface_and_particles"}}};
}

enum class SolverKind { lbm, sph, fhp };
constexpr std::array<Choice<SolverKind>, 3> paramChoices(SolverKind) {
  return {{{SolverKind::lbm, "lbm"}, {SolverKind::sph, "sph"}, {SolverKind::fhp, "fhp"}}};
}

/// Forwards the declarations of a struct to a visitor except those of the listed keys (to reuse
/// a struct's keys where some of them are set otherwise).
template <class V>
struct ExceptKeys {
  V& visitor;
  std::vector<std::string> skipped;
  template <class C, class T>
  void operator()(T C::*member, const ParamInfo& info) {
    for (const auto& k : skipped)
      if (k == info.key) return;
    visitor(member, info);
  }
};

/// The default title of output.images[]: scene, field, units and time.
inline constexpr const char* kImageTitleTemplate = "{name}: {field} ({units}), t = {time} s";
/// The default title of output.lic[].
inline constexpr const char* kLicTitleTemplate =
    "{name}: LIC coloured by {field} ({units}), t = {time} s";
/// What the title keys' docs say about placeholders.
inline constexpr const char* kTitlePlaceholderHelp =
    "placeholders: {name}, {field}, {units}, {time} (s), {solver} and any scene key with a value, "
    "by its dotted path ({lbm.reynolds}) or its last part if unique in the solver's section "
    "({reynolds}); {{ and }} are literal braces; empty: no title";

/// A PNG picture of one field of the final state (and, with every_snapshot, of each snapshot).
struct ImageOutput : FieldImageParams, PictureSeriesParams {
  ImageOutput() { title = kImageTitleTemplate; }

  ImageField field = ImageField::speed;
  std::string file;             ///< file name in the output folder; empty: <name>_<field>.png

  template <class V>
  static void describe(V& v) {
    v(&ImageOutput::field, {.key = "field",
                            .description = "field drawn: speed |u|, density, pressure (Pa), or a "
                                           "velocity component; LBM also: vorticity (dv/dx - du/dy) and stream_function "
                                           "(psi, 2D or the slice_index layer), computed only when "
                                           "asked"});
    v(&ImageOutput::file, {.key = "file",
                           .description = "PNG file name in the output folder; empty: "
                                          "<name>_<field>.png"});
    v(&ImageOutput::title, {.key = "title",
                            .description = std::string("text above the field; ") +
                                           kTitlePlaceholderHelp});
    ExceptKeys<V> picture{v, {"title"}};
    FieldImageParams::describe(picture);
    PictureSeriesParams::describe(v);
  }
};

/// A LIC picture of the final velocity (filters/lic): the LIC texture of the flow blended with a
/// colour-mapped scalar (fieldviz/render/LicBlend.h), with title and legend. The picture is sized
/// so that the texture (width x height px) maps 1:1 onto its pixels. Solid bodies (rollers) are
/// masked and drawn in mask_color: their nodes carry the rigid-body velocity, which is not flow.
/// A 3D flow is drawn in the xy node layer nearest slice_height (mid-height when unset).
struct LicOutput : lic::LicParams, LicBlendParams, FieldImageParams, PictureSeriesParams {
  std::string file;  ///< PNG file name in the output folder; empty: <name>_lic_<color_by>.png

  // A picture-sized texture, not 1 px per node.
  LicOutput() {
    lic::LicParams::width = kDefaultPictureWidth;
    title = kLicTitleTemplate;
  }

  // The slice here is the texture's height in m (FieldImageParams' layer index is not a key).
  static constexpr auto retiredKeys = lic::LicParams::retiredKeys;

  template <class V>
  static void describe(V& v) {
    lic::LicParams::describe(v);
    LicBlendParams::describe(v);
    // The picture's size follows from the texture's; the slice is LicParams' slice_height (m).
    v(&LicOutput::title, {.key = "title",
                          .description = std::string("text above the picture ({field}: color_by); ") +
                                         kTitlePlaceholderHelp});
    ExceptKeys<V> picture{v, {"width", "height", "slice_index", "title"}};
    FieldImageParams::describe(picture);
    v(&LicOutput::file, {.key = "file",
                         .description = "PNG file name in the output folder; empty: "
                                        "<name>_lic_<color_by>.png"});
    PictureSeriesParams::describe(v);
  }
};

/// Streamlines of the final velocity (filters/streamlines), written as a .vtp (polylines with
/// speed, integration_time, reason; filters/streamlines/vtk/StreamlinePolyData.h) and drawn over
/// pictures. Seeds inside solid bodies are skipped (their nodes carry rigid-body velocity).
struct StreamlinesOutput : StreamlineStyle {
  streamlines::SeedingParams seeding;         ///< where lines start
  streamlines::StreamlineParams integration;  ///< integrator, step, lengths (cells)
  std::string file;            ///< .vtp file name; empty: <name>_streamlines.vtp
  DrawOn draw_on = DrawOn::lic;

  template <class V>
  static void describe(V& v) {
    v(&StreamlinesOutput::seeding, {.key = "seeding", .description = "where lines start"});
    v(&StreamlinesOutput::integration,
      {.key = "integration", .description = "integrator parameters (lengths in cells)"});
    v(&StreamlinesOutput::file, {.key = "file",
                                 .description = ".vtp file name in the output folder; empty: "
                                                "<name>_streamlines.vtp"});
    v(&StreamlinesOutput::draw_on,
      {.key = "draw_on",
       .description = "pictures the lines are drawn on: lic (output.lic), images "
                      "(output.images), all, or none"});
    StreamlineStyle::describe(v);
  }
};

/// SPH particles resampled onto a grid (filters/resample/ResampleParams.h) for output.grids,
/// output.free_surface and output.views. The grid covers the SPH domain box plus `padding`, the
/// same grid at every snapshot; particle volumes are m/rho of the solver's particles, so the keys
/// choosing volumes, masses and the dimension are not scene keys here.
struct SphResampleParams : resample::ParticleResampleParams {
  SphResampleParams() { arrays = "velocity,speed,density,pressure"; }

  template <class V>
  static void describe(V& v) {
    ExceptKeys<V> keys{v, {"mass_array", "density_array", "particle_volume", "particle_spacing",
                           "dimension"}};
    resample::ParticleResampleParams::describe(keys);
  }
};

/// SPH: the particles resampled onto a grid (.vti) with their arrays, "color" (the colour field
/// sum_j V_j W, 0.5 at a free surface), "mask" and "summation_density".
struct GridOutput : SphResampleParams {
  std::string file;             ///< .vti name; empty: <name>_grid.vti (<name>_grid<i+1>.vti for i > 0)
  bool every_snapshot = false;  ///< also one per snapshot: <stem>.pvd of <stem>/<stem>_NNNN.vti

  template <class V>
  static void describe(V& v) {
    SphResampleParams::describe(v);
    v(&GridOutput::file, {.key = "file",
                          .description = ".vti file name of the final state; empty: "
                                         "<name>_grid.vti (<name>_grid2.vti, ... for later "
                                         "entries)"});
    v(&GridOutput::every_snapshot,
      {.key = "every_snapshot",
       .description = "also resample every snapshot: <stem>.pvd listing <stem>/<stem>_NNNN.vti"});
  }
};

/// SPH free surface: the level set of the resampled colour field (or summation density) -
/// isolines in 2D, a triangulated surface in 3D (filters/isosurface, Flying Edges).
struct FreeSurfaceParams : isosurface::IsosurfaceParams {
  SphResampleParams grid;       ///< the grid the surface is contoured on
  SurfaceField field = SurfaceField::color;
  std::optional<double> level;  ///< iso value; empty: 0.5 (color) or 0.5 rest_density

  template <class V>
  static void describe(V& v) {
    v(&FreeSurfaceParams::grid,
      {.key = "grid", .description = "resampling of the particles the surface is contoured on"});
    v(&FreeSurfaceParams::field,
      {.key = "field",
       .description = "contoured grid array: color (sum_j V_j W, ~1 in the fluid) or "
                      "summation_density (sum_j m_j W, kg/m^d)"});
    v(&FreeSurfaceParams::level,
      {.key = "level",
       .description = "iso value; empty: 0.5 for color, 0.5 x sph.rest_density for "
                      "summation_density",
       .min = 0,
       .minExclusive = true});
    ExceptKeys<V> rest{v, {"array", "value"}};
    isosurface::IsosurfaceParams::describe(rest);
  }
};

struct FreeSurfaceOutput : FreeSurfaceParams {
  std::string file;  ///< .vtp name; empty: <name>_free_surface.vtp (..._surface<i+1>.vtp for i > 0)
  bool every_snapshot = false;  ///< also one per snapshot: <stem>.pvd of <stem>/<stem>_NNNN.vtp

  template <class V>
  static void describe(V& v) {
    FreeSurfaceParams::describe(v);
    v(&FreeSurfaceOutput::file,
      {.key = "file",
       .description = ".vtp file name of the final state; empty: <name>_free_surface.vtp "
                      "(<name>_free_surface2.vtp, ... for later entries)"});
    v(&FreeSurfaceOutput::every_snapshot,
      {.key = "every_snapshot",
       .description = "also every snapshot: <stem>.pvd listing <stem>/<stem>_NNNN.vtp"});
  }
};

/// Particles of a 3D picture: ParticleStyle with a default radius.
struct ViewParticleStyle : ParticleStyle {
  std::optional<double> sphere_radius;  ///< m; empty: half the particle spacing

  ViewParticleStyle() { color_by = "speed"; }

  template <class V>
  static void describe(V& v) {
    v(&ViewParticleStyle::sphere_radius,
      {.key = "radius",
       .unit = "m",
       .description = "sphere radius; empty: half of sph.particle_spacing",
       .min = 0,
       .minExclusive = true});
    ExceptKeys<V> rest{v, {"radius"}};
    ParticleStyle::describe(rest);
  }
};

/// SPH: a 3D picture (fieldviz/render/View3D.h) of the shaded free surface and/or the particles
/// as spheres, framed on the SPH domain (its outline drawn). 2D scenes are drawn in the same
/// way, the isolines as lines in front of the particles (use azimuth 0, elevation 0).
struct ViewOutput : View3DParams, PictureSeriesParams {
  ViewShow show = ViewShow::surface;
  FreeSurfaceParams free_surface;   ///< the surface drawn
  SurfaceStyle surface;             ///< how it is drawn
  ViewParticleStyle particles;      ///< how the particles are drawn
  std::string file;                 ///< PNG name; empty: <name>_view.png (<name>_view<i+1>.png)
  std::string title = "{name}, t = {time} s";  ///< template, as output.images[].title

  template <class V>
  static void describe(V& v) {
    v(&ViewOutput::show, {.key = "show",
                          .description = "what is drawn: the free surface, the particles, or "
                                         "both (give the surface an opacity < 1 to see the "
                                         "particles inside)"});
    v(&ViewOutput::free_surface,
      {.key = "free_surface", .description = "the surface drawn (as output.free_surface)"});
    v(&ViewOutput::surface, {.key = "surface", .description = "surface colour and shading"});
    v(&ViewOutput::particles, {.key = "particles", .description = "particle spheres"});
    v(&ViewOutput::file, {.key = "file",
                          .description = "PNG file name; empty: <name>_view.png "
                                         "(<name>_view2.png, ... for later entries)"});
    v(&ViewOutput::title,
      {.key = "title",
       .description = std::string("text at the top ({field}: particles.color_by); ") +
                      kTitlePlaceholderHelp});
    View3DParams::describe(v);
    PictureSeriesParams::describe(v);
  }
};

/// The default title of output.topology[] pictures.
inline constexpr const char* kTopologyTitleTemplate = "{name}: topology of the velocity, t = {time} s";

/// The topology of the final velocity, found as `fluidviz topology` finds it in the final
/// snapshot (the same image: solids masked, resting walls named): critical points (.vtp, .csv),
/// separatrices (.vtp) and, for a 3D field, separating surfaces (.vtp), and a picture: the planar
/// one of `fluidviz topology --png` for a 2D field, the 3D one for a 3D field.
struct TopologyOutput : topology::TopologyParams {
  bool separatrices = true;     ///< trace separatrices (and, in 3D, separating surfaces)
  bool picture = true;          ///< write <file>.png
  std::string file;             ///< stem of the files; empty: <name>_topology
  std::string title = kTopologyTitleTemplate;
  TopologyPictureParams planar;  ///< the picture of a 2D field
  View3DParams view;             ///< the picture of a 3D field

  template <class V>
  static void describe(V& v) {
    topology::TopologyParams::describe(v);
    v(&TopologyOutput::separatrices,
      {.key = "separatrices",
       .description = "trace the separatrices of saddles (in 3D also their separating surfaces)"});
    v(&TopologyOutput::picture, {.key = "picture", .description = "write <file>.png"});
    v(&TopologyOutput::file,
      {.key = "file",
       .description = "stem of the files in the output folder (<file>.vtp, <file>.csv, "
                      "<file>_separatrices.vtp, 3D: <file>_surfaces.vtp, <file>.png); empty: "
                      "<name>_topology"});
    v(&TopologyOutput::title,
      {.key = "title", .description = std::string("text above the picture; ") + kTitlePlaceholderHelp});
    v(&TopologyOutput::planar,
      {.key = "planar", .description = "the picture of a 2D field (as fluidviz topology --png)"});
    v(&TopologyOutput::view,
      {.key = "view", .description = "the picture of a 3D field: size, camera, background"});
  }
};

struct OutputParams {
  int snapshots = 10;  ///< snapshots over the run after t = 0, evenly spaced; the last is the final state
  std::vector<ImageOutput> images{ImageOutput{}};  ///< pictures of the final state
  std::vector<LicOutput> lic;                      ///< LIC pictures of the final velocity
  std::vector<StreamlinesOutput> streamlines;      ///< streamlines of the final velocity
  std::vector<TopologyOutput> topology;            ///< topology of the final velocity
  std::vector<GridOutput> grids;                   ///< SPH: resampled grids (.vti)
  std::vector<FreeSurfaceOutput> free_surface;     ///< SPH: free surfaces (.vtp)
  std::vector<ViewOutput> views;                   ///< SPH: 3D pictures of surface and particles
  std::vector<ProbeOutput> probes;                 ///< LBM: line probes of the final state
  TimeSeriesParams time_series;                    ///< quantities sampled over the run

  template <class V>
  static void describe(V& v) {
    v(&OutputParams::snapshots,
      {.key = "snapshots",
       .description = "number of snapshots (.vti, SPH .vtp) evenly spaced over the run after "
                      "the one of the initial state at t = 0: <name>.pvd lists snapshots + 1, "
                      "the last being the final state; a run that stops early (steady state, "
                      "max_steps) lists fewer, its last the state it stopped at, and says so in "
                      "its output; 0 writes none and no .pvd",
       .min = 0,
       .max = 100000});
    v(&OutputParams::images,
      {.key = "images",
       .description = "PNG pictures of the final state (every_snapshot: also of each snapshot, "
                      "movie: and a movie of them)"});
    v(&OutputParams::lic,
      {.key = "lic",
       .description = "LIC pictures of the final velocity (computed only if listed; "
                      "every_snapshot and movie as output.images)"});
    v(&OutputParams::streamlines,
      {.key = "streamlines",
       .description = "streamlines of the final velocity: .vtp files, drawn over pictures "
                      "(computed only if listed)"});
    v(&OutputParams::topology,
      {.key = "topology",
       .description = "solver lbm: critical points, separatrices (3D: and separating surfaces) "
                      "of the final velocity, .vtp, .csv and a picture (computed only if listed)"});
    v(&OutputParams::grids, {.key = "grids",
                             .description = "solver sph: the particles resampled onto grids "
                                            "covering the SPH domain box plus padding (.vti; "
                                            "computed only if listed)"});
    v(&OutputParams::free_surface,
      {.key = "free_surface",
       .description = "solver sph: free surfaces, level sets of the resampled colour field "
                      "(.vtp; computed only if listed)"});
    v(&OutputParams::views,
      {.key = "views",
       .description = "solver sph: 3D pictures of the free surface and the particles (PNG; "
                      "computed only if listed)"});
    v(&OutputParams::probes,
      {.key = "probes",
       .description = "solver lbm: line probes of the final state, <name>_<probe>.csv and a PNG "
                      "plot, compared with a reference CSV when one is given"});
    v(&OutputParams::time_series,
      {.key = "time_series",
       .description = "quantities sampled over the run: <name>_time_series.csv and a PNG plot "
                      "per quantity"});
  }
};

/// When a run writes its checkpoint <name>.checkpoint (pipeline/Checkpoint.h), from
/// which `fluidviz run SCENE --resume DIR` continues. SIGINT and SIGTERM always write one.
struct CheckpointParams {
  double interval = 300.0;   ///< s of wall-clock time between checkpoints; 0: none on a timer
  bool at_snapshots = true;  ///< also one with every snapshot (a kill loses at most one interval)
  bool keep = false;         ///< keep the checkpoint after the run completed

  template <class V>
  static void describe(V& v) {
    v(&CheckpointParams::interval,
      {.key = "interval",
       .unit = "s",
       .description = "wall-clock time between checkpoints (the whole solver state, written "
                      "atomically to <name>.checkpoint); 0: none on a timer. SIGINT/SIGTERM "
                      "always write one before stopping",
       .min = 0,
       .max = 1e7});
    v(&CheckpointParams::at_snapshots,
      {.key = "at_snapshots",
       .description = "also write the checkpoint with every snapshot, so that a killed run "
                      "resumes from its last snapshot"});
    v(&CheckpointParams::keep,
      {.key = "keep",
       .description = "keep <name>.checkpoint after the run completed (false: it is removed "
                      "once every output is written)"});
  }
};

struct SceneParams {
  std::string name = "scene";  ///< output file prefix: letters, digits, '_' and '-'
  std::string description;     ///< what the scene shows (free text)
  SolverKind solver = SolverKind::lbm;
  LbmSceneParams lbm;          ///< Lattice-Boltzmann parameters (solver = "lbm"), lbm.sketch
  sph::SphParams sph;          ///< SPH parameters (solver = "sph"; pipeline/SphOutputs.h)
  fhp::FhpParams fhp;          ///< FHP lattice-gas parameters (solver = "fhp"; pipeline/FhpOutputs.h)
  OutputParams output;
  CheckpointParams checkpoint;
  /// Not a key: the scene file's folder, where relative input paths (lbm.sketch.file) start;
  /// set by readSceneParams.
  std::filesystem::path folder;

  template <class V>
  static void describe(V& v) {
    v(&SceneParams::name, {.key = "name",
                           .description = "prefix of every output file: letters, digits, _ and -"});
    v(&SceneParams::description, {.key = "description", .description = "what the scene shows"});
    v(&SceneParams::solver, {.key = "solver", .description = "solver that runs the scene"});
    v(&SceneParams::lbm, {.key = "lbm", .description = "Lattice-Boltzmann solver (solver = lbm)"});
    v(&SceneParams::sph, {.key = "sph",
                          .description = "SPH solver (solver = sph): particles, written as .vtp; "
                                         "output.images draws the particles"});
    v(&SceneParams::fhp, {.key = "fhp",
                          .description = "FHP lattice gas (solver = fhp): Boolean particles on a "
                                         "triangular lattice, averaged over blocks and time "
                                         "windows into .vti snapshots"});
    v(&SceneParams::output, {.key = "output", .description = "what the run writes"});
    v(&SceneParams::checkpoint,
      {.key = "checkpoint",
       .description = "checkpoints for `fluidviz run SCENE --resume DIR` (docs/checkpoints.md)"});
  }
};

}  // namespace fluidviz
