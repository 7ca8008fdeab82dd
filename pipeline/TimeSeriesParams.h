#pragma once
// Scene keys of output.time_series (pipeline/TimeSeries.h): quantities of the flow sampled over
// the run.
#include <array>
#include <string>

#include "fieldviz/core/Params.h"

namespace fluidviz {

/// A quantity a time series records.
enum class SeriesQuantity { kinetic_energy, max_speed, surge_front };
constexpr std::array<Choice<SeriesQuantity>, 3> paramChoices(SeriesQuantity) {
  return {{{SeriesQuantity::kinetic_energy, "kinetic_energy"},
           {SeriesQuantity::max_speed, "max_speed"},
           {SeriesQuantity::surge_front, "surge_front"}}};
}

struct TimeSeriesParams {
  std::string quantities;  ///< comma-separated SeriesQuantity names; empty: no series
  double interval = 0.1;   ///< s between samples
  std::string surge_front_reference;  ///< CSV of (T, Z), relative to the scene file; empty: none

  template <class V>
  static void describe(V& v) {
    v(&TimeSeriesParams::quantities,
      {.key = "quantities",
       .description = "comma-separated quantities sampled over the run, written to "
                      "<name>_time_series.csv with one PNG plot each (<name>_<quantity>.png): "
                      "kinetic_energy (sum of rho |u|^2 / 2 dV over the fluid, J; J/m in 2D), "
                      "max_speed (largest |u| in the fluid, m/s), surge_front (solver sph, dam "
                      "break of one fluid block at x = 0: the front Z = x/a against "
                      "T = t sqrt(2 g / a), a the block's width, as Martin & Moyce 1952); "
                      "empty: no series"});
    v(&TimeSeriesParams::interval,
      {.key = "interval", .unit = "s",
       .description = "time between samples; a sample is taken at the end of the first solver "
                      "chunk at or after it is due (LBM chunks: at most lbm.check_interval steps "
                      "and a few million node updates; SPH: one time step), and at t = 0",
       .min = 0, .minExclusive = true});
    v(&TimeSeriesParams::surge_front_reference,
      {.key = "surge_front_reference",
       .description = "CSV file with columns T and Z (e.g. data/martin_moyce_1952_surge_front.csv)"
                      " drawn as markers on the surge_front plot, with the simulated T shifted by "
                      "+0.175 (the experiment's gate opening), relative to the scene file's folder;"
                      " empty: none"});
  }
};

}  // namespace fluidviz
