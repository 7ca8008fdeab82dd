#pragma once
// The whole scene file as one struct: which solver, its parameters, and the outputs wanted.
// docs/scenes.md is generated from these declarations (`fluidviz docs`).
#include <string>
#include <vector>

#include "fieldviz/core/Params.h"
#include "fieldviz/render/FieldImage.h"
#include "fieldviz/render/LicBlend.h"
#include "fieldviz/render/StreamlineOverlay.h"
#include "filters/lic/LicParams.h"
#include "filters/streamlines/Seeding.h"
#include "filters/streamlines/StreamlineParams.h"
#include "solvers/lbm/LbmParams.h"
#include "solvers/sph/SphParams.h"

namespace fluidviz {

/// A PNG picture of one field of the final state.
struct ImageOutput : FieldImageParams {
  std::string field = "speed";  ///< which field to draw
  std::string file;             ///< file name in the output folder; empty: <name>_<field>.png

  template <class V>
  static void describe(V& v) {
    v(&ImageOutput::field, {.key = "field",
                            .description = "field drawn: speed |u|, density, or a velocity component; "
                                           "LBM also: vorticity (dv/dx - du/dy) and stream_function "
                                           "(psi, 2D or the slice_z layer), computed only when asked",
                            .choices = {"speed", "density", "velocity_x", "velocity_y", "velocity_z",
                                        "vorticity", "stream_function"}});
    v(&ImageOutput::file, {.key = "file",
                           .description = "PNG file name in the output folder; empty: "
                                          "<name>_<field>.png"});
    FieldImageParams::describe(v);
  }
};

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

/// A LIC picture of the final velocity (filters/lic): the LIC texture of the flow blended with a
/// colour-mapped scalar (fieldviz/render/LicBlend.h), with title and legend. The picture is sized
/// so that the texture (width x height px) maps 1:1 onto its pixels. Solid bodies (rollers) are
/// masked and drawn in mask_color: their nodes carry the rigid-body velocity, which is not flow.
/// A 3D flow is drawn in the xy node layer nearest slice_z (mid-height when unset).
struct LicOutput : lic::LicParams, LicBlendParams, FieldImageParams {
  std::string file;  ///< PNG file name in the output folder; empty: <name>_lic_<color_by>.png

  LicOutput() { lic::LicParams::width = 800; }  // a picture-sized texture, not 1 px per node

  template <class V>
  static void describe(V& v) {
    lic::LicParams::describe(v);
    LicBlendParams::describe(v);
    // The picture's size follows from the texture's; slice_z is LicParams' (in m).
    ExceptKeys<V> picture{v, {"width", "height", "slice_z"}};
    FieldImageParams::describe(picture);
    v(&LicOutput::file, {.key = "file",
                         .description = "PNG file name in the output folder; empty: "
                                        "<name>_lic_<color_by>.png"});
  }
};

/// Streamlines of the final velocity (filters/streamlines), written as a .vtp (polylines with
/// speed, integration_time, reason; filters/streamlines/vtk/StreamlinePolyData.h) and drawn over
/// pictures. Seeds inside solid bodies are skipped (their nodes carry rigid-body velocity).
struct StreamlinesOutput : StreamlineStyle {
  streamlines::SeedingParams seeding;         ///< where lines start
  streamlines::StreamlineParams integration;  ///< integrator, step, lengths (cells)
  std::string file;            ///< .vtp file name; empty: <name>_streamlines.vtp
  std::string draw_on = "lic"; ///< pictures that show the lines: lic, images, all or none

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
                      "(output.images), all, or none",
       .choices = {"lic", "images", "all", "none"}});
    StreamlineStyle::describe(v);
  }
};

struct OutputParams {
  int snapshots = 10;  ///< .vti snapshots over the run, evenly spaced in time; the last is the final state
  std::vector<ImageOutput> images{ImageOutput{}};  ///< pictures of the final state
  std::vector<LicOutput> lic;                      ///< LIC pictures of the final velocity
  std::vector<StreamlinesOutput> streamlines;      ///< streamlines of the final velocity

  template <class V>
  static void describe(V& v) {
    v(&OutputParams::snapshots,
      {.key = "snapshots",
       .description = "number of .vti snapshots evenly spaced over the run (the last one is the "
                      "final state), listed in <name>.pvd; 0 writes none",
       .min = 0,
       .max = 100000});
    v(&OutputParams::images, {.key = "images", .description = "PNG pictures of the final state"});
    v(&OutputParams::lic,
      {.key = "lic", .description = "LIC pictures of the final velocity (computed only if listed)"});
    v(&OutputParams::streamlines,
      {.key = "streamlines",
       .description = "streamlines of the final velocity: .vtp files, drawn over pictures "
                      "(computed only if listed)"});
  }
};

struct SceneParams {
  std::string name = "scene";  ///< output file prefix: letters, digits, '_' and '-'
  std::string description;     ///< what the scene shows (free text)
  std::string solver = "lbm";  ///< which solver runs the scene
  lbm::LbmParams lbm;          ///< Lattice-Boltzmann parameters (solver = "lbm")
  sph::SphParams sph;          ///< SPH parameters (solver = "sph"; fieldviz/pipeline/RunSphScene.h)
  OutputParams output;

  template <class V>
  static void describe(V& v) {
    v(&SceneParams::name, {.key = "name",
                           .description = "prefix of every output file: letters, digits, _ and -"});
    v(&SceneParams::description, {.key = "description", .description = "what the scene shows"});
    v(&SceneParams::solver, {.key = "solver", .description = "solver that runs the scene",
                             .choices = {"lbm", "sph"}});
    v(&SceneParams::lbm, {.key = "lbm", .description = "Lattice-Boltzmann solver (solver = lbm)"});
    v(&SceneParams::sph, {.key = "sph",
                          .description = "SPH solver (solver = sph): particles, written as .vtp; "
                                         "output.images draws the particles"});
    v(&SceneParams::output, {.key = "output", .description = "what the run writes"});
  }
};

/// Checks rules that span several keys (name characters, unique image files). Throws ParamError.
void validateScene(const SceneParams& scene);

}  // namespace fluidviz
