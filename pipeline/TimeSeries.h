#pragma once
// output.time_series (pipeline/TimeSeriesParams.h): quantities of the flow sampled over a run.
//   <name>_time_series.csv  header comments (scene, quantities, deviation from a reference), then
//                           "t (s)" and one column per quantity with its unit (surge_front:
//                           "T (1)" and "Z (1)")
//   <name>_<quantity>.png   one plot per quantity against t (surge_front: Z against T + 0.175
//                           with the reference as markers)
// Values come from the solver's outputs (SolverOutputs::seriesValues); the run loop samples at
// t = 0 and after every chunk at or past the next due time. A resumed run continues the series
// from the CSV the interrupted run wrote at its checkpoint (rows up to the resumed time).
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/SceneParams.h"
#include "solvers/lbm/LbmSolver.h"
#include "solvers/sph/SphSolver.h"
#include "solvers/sph/SurgeFrontMartinMoyce.h"

namespace fluidviz {

/// The quantities named by time_series.quantities, in order. Throws ParamError (key
/// "output.time_series.quantities") for an unknown or repeated name, naming those there are.
std::vector<SeriesQuantity> seriesQuantities(const SceneParams& scene);

/// The rules of output.time_series: known quantities the solver offers (surge_front: solver sph,
/// one fluid block starting at x = 0, gravity; drag and lift: solver lbm in 2D, a roller `body`,
/// a reference speed), a readable reference. Throws ParamError.
void validateTimeSeries(const SceneParams& scene, const std::string& sceneFile);

/// Values of `quantities` for a lattice-Boltzmann state (fluid nodes only; drag and lift of
/// scene.output.time_series.body); NaN for surge_front.
std::vector<double> lbmSeriesValues(const lbm::LbmSolver& solver, const SceneParams& scene,
                                    const std::vector<SeriesQuantity>& quantities);
/// Values for an SPH state (fluid particles); surge_front is Z (dimensionlessFront).
std::vector<double> sphSeriesValues(const sph::SphSolver& solver,
                                    const std::vector<SeriesQuantity>& quantities);

/// A coefficient over the second half of its series (t >= t_last / 2, where a periodic flow has
/// settled): mean, extremes and the frequency of its upward crossings of the mean (NaN with
/// fewer than 3 crossings, i.e. two periods), each crossing placed by linear interpolation.
struct OscillationSummary {
  double from = 0.0;  ///< s, first time included
  double mean = 0.0, min = 0.0, max = 0.0;
  double frequency = 0.0;  ///< Hz
};
OscillationSummary summarizeOscillation(const std::vector<double>& times,
                                        const std::vector<double>& values);

class SolverOutputs;

class TimeSeries {
 public:
  /// Reads the surge-front reference (relative to sceneFile's folder).
  TimeSeries(const SceneParams& scene, const std::filesystem::path& sceneFile);

  bool empty() const { return quantities_.empty(); }
  /// Takes a sample if one is due at `time` (the first at any time); true if it did.
  bool sampleIfDue(double time, const SolverOutputs& outputs);
  /// Takes the run's last sample at `time` unless one was taken there (a steady stop falls
  /// between due times); true if it did.
  bool sampleFinal(double time, const SolverOutputs& outputs);
  /// When the next sample is due (s); +infinity without quantities.
  double nextSampleTime() const;
  /// Continues the rows of an earlier run's CSV in `dir` up to `time` (a resume).
  void resume(const std::filesystem::path& dir, double time);
  /// The CSV (also at checkpoints, so that a resume continues it) without the plots.
  std::filesystem::path writeCsv(const std::filesystem::path& dir) const;
  /// CSV and plots; prints the surge front's deviation from the reference to `log`.
  void write(const std::filesystem::path& dir, std::ostream& log,
             std::vector<std::filesystem::path>& written) const;

 private:
  void record(double time, const SolverOutputs& outputs);
  double nextDueAfter(double time) const;
  struct FrontDeviation {
    double maxError, Tmax;
  };
  /// The surge front against the reference (sph::maxFrontDeviation) up to the last sample.
  std::optional<FrontDeviation> surgeDeviation() const;
  /// "surge front deviates from REF by max |dZ| ..."; empty without a reference.
  std::string surgeDeviationText() const;
  /// "C_D over t >= 5 s: mean 3.17, min ..., max ...; C_L ...: St 0.3 (f 3 Hz)" of the force
  /// coefficients; empty without them.
  std::string coefficientSummaryText() const;

  const SceneParams& scene_;
  std::vector<SeriesQuantity> quantities_;
  std::vector<sph::SurgeFrontPoint> reference_;
  double timeScale_ = 0.0;  ///< sqrt(2 g / a) of surge_front, else 0
  double next_ = 0.0;       ///< time the next sample is due
  std::vector<double> times_;
  std::vector<std::vector<double>> values_;  ///< values_[quantity][sample]
};

}  // namespace fluidviz
