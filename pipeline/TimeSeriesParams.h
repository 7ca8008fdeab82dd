#pragma once
// Scene keys of output.time_series (pipeline/TimeSeries.h): quantities of the flow sampled over
// the run.
#include <array>
#include <string>

#include "fieldviz/core/Params.h"

namespace fluidviz {

/// A quantity a time series records.
enum class SeriesQuantity {
  kinetic_energy, max_speed, surge_front, drag_coefficient, lift_coefficient
};
constexpr std::array<Choice<SeriesQuantity>, 5> paramChoices(SeriesQuantity) {
  return {{{SeriesQuantity::kinetic_energy, "kinetic_energy"},
           {SeriesQuantity::max_speed, "max_speed"},
           {SeriesQuantity::surge_front, "surge_front"},
           {SeriesQuantity::drag_coefficient, "drag_coefficient"},
           {SeriesQuantity::lift_coefficient, "lift_coefficient"}}};
}

struct TimeSeriesParams {
  std::string quantities;  ///< comma-separated SeriesQuantity names; empty: no series
  double interval = 0.1;   ///< s between samples
  std::string surge_front_reference;  ///< CSV of (T, Z), relative to the scene file; empty: none
  int body = 0;                    ///< lbm.rollers index of drag and lift
  double reference_velocity = 0.0;  ///< m/s of the coefficients; 0: lbm's U_ref
  double reference_length = 0.0;    ///< m of the coefficients; 0: the body's diameter

  template <class V>
  static void describe(V& v) {
    v(&TimeSeriesParams::quantities,
      {.key = "quantities",
       .description = "comma-separated quantities sampled over the run, written to "
                      "<name>_time_series.csv with one PNG plot each (<name>_<quantity>.png): "
                      "kinetic_energy (sum of rho |u|^2 / 2 dV over the fluid, J; J/m in 2D), "
                      "max_speed (largest |u| in the fluid, m/s), surge_front (solver sph, dam "
                      "break of one fluid block at x = 0: the front Z = x/a against "
                      "T = t sqrt(2 g / a), a the block's width, as Martin & Moyce 1952), "
                      "drag_coefficient and lift_coefficient (solver lbm, 2D: C_D = 2 F_x / "
                      "(rho U^2 D), C_L = 2 F_y / (rho U^2 D) of the force per metre of depth "
                      "on the roller `body`, by momentum exchange; rho = lbm.density, U = "
                      "reference_velocity, D = reference_length); empty: no series"});
    v(&TimeSeriesParams::interval,
      {.key = "interval", .unit = "s",
       .description = "time between samples, the first at t = 0; a sample is taken at the "
                      "first time step at or after it is due, and the last at the end of the run "
                      "(also when a steady state stops it between due times)",
       .min = 0, .minExclusive = true});
    v(&TimeSeriesParams::surge_front_reference,
      {.key = "surge_front_reference",
       .description = "CSV file with columns T and Z (e.g. data/martin_moyce_1952_surge_front.csv)"
                      " drawn as markers on the surge_front plot, with the simulated T shifted by "
                      "+0.175 (the experiment's gate opening), relative to the scene file's folder;"
                      " empty: none"});
    v(&TimeSeriesParams::body,
      {.key = "body",
       .description = "index in lbm.rollers of the body whose drag and lift are recorded (a "
                      "fixed cylinder is a roller with angular_velocity 0)",
       .min = 0});
    v(&TimeSeriesParams::reference_velocity,
      {.key = "reference_velocity", .unit = "m/s",
       .description = "U of the drag and lift coefficients; 0: lbm's reference speed U_ref (the "
                      "fastest wall or roller, or the mean speed of a velocity inlet: 2/3 of the "
                      "centre speed of a parabolic one)",
       .min = 0});
    v(&TimeSeriesParams::reference_length,
      {.key = "reference_length", .unit = "m",
       .description = "D of the drag and lift coefficients; 0: the body's diameter",
       .min = 0});
  }
};

}  // namespace fluidviz
