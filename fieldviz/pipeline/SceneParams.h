#pragma once
// The whole scene file as one struct: which solver, its parameters, and the outputs wanted.
// docs/scenes.md is generated from these declarations (`fluidviz docs`).
#include <string>
#include <vector>

#include "fieldviz/core/Params.h"
#include "fieldviz/render/FieldImage.h"
#include "solvers/lbm/LbmParams.h"

namespace fluidviz {

/// A PNG picture of one field of the final state.
struct ImageOutput : FieldImageParams {
  std::string field = "speed";  ///< which field to draw
  std::string file;             ///< file name in the output folder; empty: <name>_<field>.png

  template <class V>
  static void describe(V& v) {
    v(&ImageOutput::field, {.key = "field",
                            .description = "field drawn: speed |u|, density, or a velocity component",
                            .choices = {"speed", "density", "velocity_x", "velocity_y"}});
    v(&ImageOutput::file, {.key = "file",
                           .description = "PNG file name in the output folder; empty: "
                                          "<name>_<field>.png"});
    FieldImageParams::describe(v);
  }
};

struct OutputParams {
  int snapshots = 10;  ///< .vti snapshots over the run, evenly spaced in time; the last is the final state
  std::vector<ImageOutput> images{ImageOutput{}};  ///< pictures of the final state

  template <class V>
  static void describe(V& v) {
    v(&OutputParams::snapshots,
      {.key = "snapshots",
       .description = "number of .vti snapshots evenly spaced over the run (the last one is the "
                      "final state), listed in <name>.pvd; 0 writes none",
       .min = 0,
       .max = 100000});
    v(&OutputParams::images, {.key = "images", .description = "PNG pictures of the final state"});
  }
};

struct SceneParams {
  std::string name = "scene";  ///< output file prefix: letters, digits, '_' and '-'
  std::string description;     ///< what the scene shows (free text)
  std::string solver = "lbm";  ///< which solver runs the scene
  lbm::LbmParams lbm;          ///< Lattice-Boltzmann parameters (solver = "lbm")
  OutputParams output;

  template <class V>
  static void describe(V& v) {
    v(&SceneParams::name, {.key = "name",
                           .description = "prefix of every output file: letters, digits, _ and -"});
    v(&SceneParams::description, {.key = "description", .description = "what the scene shows"});
    v(&SceneParams::solver, {.key = "solver", .description = "solver that runs the scene",
                             .choices = {"lbm"}});
    v(&SceneParams::lbm, {.key = "lbm", .description = "Lattice-Boltzmann solver (solver = lbm)"});
    v(&SceneParams::output, {.key = "output", .description = "what the run writes"});
  }
};

/// Checks rules that span several keys (name characters, unique image files). Throws ParamError.
void validateScene(const SceneParams& scene);

}  // namespace fluidviz
