#pragma once
// Scene keys of output.probes (pipeline/Probes.h): a field of the final state sampled along a
// line, optionally compared with a reference profile from a CSV file.
#include <array>
#include <string>

#include "fieldviz/core/Params.h"

namespace fluidviz {

/// A field a probe samples (named as the field's array or the velocity component).
enum class ProbeField { velocity_x, velocity_y, velocity_z, speed, density };
constexpr std::array<Choice<ProbeField>, 5> paramChoices(ProbeField) {
  return {{{ProbeField::velocity_x, "velocity_x"},
           {ProbeField::velocity_y, "velocity_y"},
           {ProbeField::velocity_z, "velocity_z"},
           {ProbeField::speed, "speed"},
           {ProbeField::density, "density"}}};
}

struct ProbeOutput {
  std::string name;  ///< <scene>_<name>.csv and .png
  std::array<double, 3> start{0.0, 0.0, 0.0};  ///< m
  std::array<double, 3> end{0.0, 0.0, 0.0};    ///< m
  int samples = 101;
  ProbeField field = ProbeField::velocity_x;
  std::string reference;           ///< CSV file, relative to the scene file's folder; empty: none
  std::string reference_position;  ///< its column of the distance from start (m)
  std::string reference_value;     ///< its column of the field's value
  double reference_scale = 1.0;    ///< reference values are multiplied by it
  std::string reference_label = "reference";
  std::string title;               ///< of the plot; empty: "<scene>: <field> along <name>"

  template <class V>
  static void describe(V& v) {
    v(&ProbeOutput::name, {.key = "name",
                           .description = "probe name: files <name>_<probe>.csv and "
                                          "<name>_<probe>.png (letters, digits, _ and -)",
                           .required = true});
    v(&ProbeOutput::start, {.key = "start", .unit = "m",
                            .description = "[x, y, z] first point of the line (z = 0 in 2D)",
                            .required = true});
    v(&ProbeOutput::end, {.key = "end", .unit = "m",
                          .description = "[x, y, z] last point of the line", .required = true});
    v(&ProbeOutput::samples, {.key = "samples",
                              .description = "evenly spaced points from start to end (both "
                                             "included), sampled bilinearly (2D) or trilinearly",
                              .min = 2, .max = 100000});
    v(&ProbeOutput::field, {.key = "field",
                            .description = "sampled field: a velocity component (m/s), speed "
                                           "(m/s) or density (kg/m^3)"});
    v(&ProbeOutput::reference,
      {.key = "reference",
       .description = "CSV file of a reference profile ('#' comments, a header line naming the "
                      "columns, then numbers), relative to the scene file's folder; empty: none"});
    v(&ProbeOutput::reference_position,
      {.key = "reference_position",
       .description = "column of the reference's distance from start along the line (m)"});
    v(&ProbeOutput::reference_value,
      {.key = "reference_value", .description = "column of the reference's field values"});
    v(&ProbeOutput::reference_scale,
      {.key = "reference_scale",
       .description = "factor on the reference values (e.g. the lid speed for velocities "
                      "normalised by it)"});
    v(&ProbeOutput::reference_label,
      {.key = "reference_label", .description = "legend entry of the reference"});
    v(&ProbeOutput::title,
      {.key = "title",
       .description = "plot title, a template as output.images[].title ({name}, {field}, "
                      "{units}, {time}, any scene key such as {reynolds}); empty: \"<name>: "
                      "<field> along <probe>\""});
  }
};

}  // namespace fluidviz
