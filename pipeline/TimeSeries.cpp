#include "pipeline/TimeSeries.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

#include "fieldviz/io/CsvTable.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "fieldviz/render/LinePlot.h"
#include "pipeline/RunLoop.h"
#include "pipeline/SceneValidation.h"

namespace fluidviz {

namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const std::string kKey = "output.time_series.";

fs::path relativeToScene(const std::string& file, const fs::path& sceneFile) {
  const fs::path p(file);
  return p.is_absolute() ? p : sceneFile.parent_path() / p;
}

std::vector<sph::SurgeFrontPoint> readSurgeReference(const fs::path& file) {
  const CsvTable t = readCsv(file);
  const std::vector<double>& T = t.column("T", file);
  const std::vector<double>& Z = t.column("Z", file);
  std::vector<sph::SurgeFrontPoint> points;
  for (std::size_t r = 0; r < T.size(); ++r) points.push_back({T[r], Z[r]});
  return points;
}

double forceCoefficientVelocity(const SceneParams& scene) {
  const double u = scene.output.time_series.reference_velocity;
  return u > 0.0 ? u : lbm::referenceVelocity(scene.lbm);
}

double forceCoefficientLength(const SceneParams& scene) {
  const TimeSeriesParams& ts = scene.output.time_series;
  return ts.reference_length > 0.0 ? ts.reference_length
                                   : 2.0 * scene.lbm.rollers.at(ts.body).radius;
}

bool is3D(const SceneParams& scene) {
  return scene.solver == SolverKind::lbm ? lbm::is3D(scene.lbm) : scene.sph.dimension == 3;
}

// Column name with unit; surge_front is Z (its T is a column of its own).
std::string columnName(const SceneParams& scene, SeriesQuantity q) {
  switch (q) {
    case SeriesQuantity::kinetic_energy:
      return is3D(scene) ? "kinetic_energy (J)" : "kinetic_energy (J/m)";
    case SeriesQuantity::max_speed: return "max_speed (m/s)";
    case SeriesQuantity::surge_front: return "Z (1)";
    case SeriesQuantity::drag_coefficient: return "C_D (1)";
    case SeriesQuantity::lift_coefficient: return "C_L (1)";
  }
  return "";
}

// Width a of the collapsing column and |g|: what T and Z are made dimensionless with.
double surgeTimeScale(const SceneParams& scene) {
  const sph::SphBoxParams& block = scene.sph.fluid_blocks.front();
  const double a = block.upper[0] - block.lower[0];
  const auto& g = scene.sph.gravity;
  return std::sqrt(2 * std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]) / a);
}

void checkSurgeFrontScene(const SceneParams& scene) {
  const std::string key = kKey + "quantities";
  if (scene.solver != SolverKind::sph)
    throw ParamError(key, "names surge_front, which solver sph offers (a dam break), not " +
                              choiceName(scene.solver));
  if (scene.sph.fluid_blocks.size() != 1 || scene.sph.fluid_blocks[0].lower[0] != 0.0 ||
      !(scene.sph.fluid_blocks[0].upper[0] > 0.0))
    throw ParamError(key, "names surge_front: the scene needs one fluid block (the column) "
                          "starting at x = 0 (sph.fluid_blocks)");
  if (!(surgeTimeScale(scene) > 0.0))
    throw ParamError(key, "names surge_front: sph.gravity must not be zero");
}

bool isForceCoefficient(SeriesQuantity q) {
  return q == SeriesQuantity::drag_coefficient || q == SeriesQuantity::lift_coefficient;
}

bool namesForceCoefficient(const std::vector<SeriesQuantity>& quantities) {
  return std::any_of(quantities.begin(), quantities.end(), isForceCoefficient);
}

void checkForceCoefficientScene(const SceneParams& scene) {
  const std::string key = kKey + "quantities";
  const TimeSeriesParams& ts = scene.output.time_series;
  if (scene.solver != SolverKind::lbm)
    throw ParamError(key, "names drag_coefficient or lift_coefficient, which solver lbm offers, "
                          "not " + choiceName(scene.solver));
  if (lbm::is3D(scene.lbm))
    throw ParamError(key, "names drag_coefficient or lift_coefficient, which are offered in 2D "
                          "only (lbm.lattice D2Q9; a 3D coefficient needs a reference area)");
  const int rollers = static_cast<int>(scene.lbm.rollers.size());
  if (rollers == 0)
    throw ParamError(key, "names drag_coefficient or lift_coefficient, but the scene has no body:"
                          " add a fixed cylinder to lbm.rollers (angular_velocity 0)");
  if (ts.body >= rollers)
    throw ParamError(kKey + "body", "is " + std::to_string(ts.body) + "; allowed: 0 to " +
                                        std::to_string(rollers - 1) + " (lbm.rollers has " +
                                        std::to_string(rollers) + ")");
  if (!(forceCoefficientVelocity(scene) > 0.0))
    throw ParamError(kKey + "reference_velocity",
                     "is 0 and nothing in the scene moves (no wall, roller or inlet gives U_ref, "
                     "e.g. a flow driven by lbm.body_force): give the speed of the coefficients, "
                     "e.g. the channel's mean speed, in m/s");
}

double kineticEnergyDensity(double rho, const Vec3& u) { return 0.5 * rho * u.squaredNorm(); }

}  // namespace

std::vector<SeriesQuantity> seriesQuantities(const SceneParams& scene) {
  std::vector<SeriesQuantity> quantities;
  const std::string& list = scene.output.time_series.quantities;
  std::size_t begin = 0;
  while (begin <= list.size() && !list.empty()) {
    const std::size_t comma = std::min(list.find(',', begin), list.size());
    std::string name = list.substr(begin, comma - begin);
    name.erase(0, name.find_first_not_of(' '));
    name.erase(name.find_last_not_of(' ') + 1);
    const std::optional<SeriesQuantity> q = choiceFromName<SeriesQuantity>(name);
    if (!q)
      throw ParamError(kKey + "quantities",
                       "names \"" + name +
                           "\"; allowed: " + joinNames(choiceNames<SeriesQuantity>()));
    if (std::find(quantities.begin(), quantities.end(), *q) != quantities.end())
      throw ParamError(kKey + "quantities", "names " + name + " twice");
    quantities.push_back(*q);
    begin = comma + 1;
  }
  return quantities;
}

void validateTimeSeries(const SceneParams& scene, const std::string& sceneFile) {
  const std::vector<SeriesQuantity> quantities = seriesQuantities(scene);
  const bool surge = std::find(quantities.begin(), quantities.end(),
                               SeriesQuantity::surge_front) != quantities.end();
  if (surge) checkSurgeFrontScene(scene);
  if (namesForceCoefficient(quantities)) checkForceCoefficientScene(scene);
  const std::string& ref = scene.output.time_series.surge_front_reference;
  if (ref.empty()) return;
  if (!surge)
    throw ParamError(kKey + "surge_front_reference", "is given but quantities has no surge_front");
  try {
    readSurgeReference(relativeToScene(ref, sceneFile));
  } catch (const FileError& e) {
    throw ParamError(kKey + "surge_front_reference", e.what());
  }
}

std::vector<double> lbmSeriesValues(const lbm::LbmSolver& solver, const SceneParams& scene,
                                    const std::vector<SeriesQuantity>& quantities) {
  const FieldSet f = solver.fields();
  const Grid& g = f.grid;
  const std::vector<double>& rho = f.findScalar("density")->values;
  const std::vector<Vec3>& u = f.findVector("velocity")->values;
  const double cell = g.spacing[0] * g.spacing[1] * (g.is2D() ? 1.0 : g.spacing[2]);
  double energy = 0.0, maxSpeed = 0.0;
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i) {
        if (solver.isSolid(i, j, k)) continue;  // solid nodes carry their body's velocity
        const std::size_t n = g.index(i, j, k);
        energy += kineticEnergyDensity(rho[n], u[n]) * cell;
        maxSpeed = std::max(maxSpeed, u[n].norm());
      }
  Vec3 coefficients = Vec3::Constant(kNaN);  // (C_D, C_L, -)
  if (namesForceCoefficient(quantities)) {
    const double U = forceCoefficientVelocity(scene), D = forceCoefficientLength(scene);
    const Vec3 force = solver.bodyForces().at(scene.output.time_series.body).force;
    coefficients = 2.0 * force / (scene.lbm.density * U * U * D);
  }
  std::vector<double> values;
  for (SeriesQuantity q : quantities) {
    switch (q) {
      case SeriesQuantity::kinetic_energy: values.push_back(energy); break;
      case SeriesQuantity::max_speed: values.push_back(maxSpeed); break;
      case SeriesQuantity::drag_coefficient: values.push_back(coefficients.x()); break;
      case SeriesQuantity::lift_coefficient: values.push_back(coefficients.y()); break;
      case SeriesQuantity::surge_front: values.push_back(kNaN); break;
    }
  }
  return values;
}

std::vector<double> sphSeriesValues(const sph::SphSolver& solver,
                                    const std::vector<SeriesQuantity>& quantities) {
  const particles::ParticleSet fluid = solver.fluid();
  const std::vector<Vec3>& v = fluid.findVector("velocity")->values;
  double energy = 0.0, maxSpeed = 0.0;
  for (const Vec3& vi : v) {
    energy += 0.5 * solver.particleMass() * vi.squaredNorm();
    maxSpeed = std::max(maxSpeed, vi.norm());
  }
  std::vector<double> values;
  for (SeriesQuantity q : quantities) {
    if (q == SeriesQuantity::surge_front) {
      const sph::SphBoxParams& block = solver.params().fluid_blocks.front();
      const auto& g = solver.params().gravity;
      values.push_back(sph::dimensionlessFront(fluid.positions, solver.params().particle_spacing,
                                               block.upper[0] - block.lower[0],
                                               std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]),
                                               solver.time())
                           .Z);
    } else {
      values.push_back(q == SeriesQuantity::kinetic_energy ? energy : maxSpeed);
    }
  }
  return values;
}

OscillationSummary summarizeOscillation(const std::vector<double>& times,
                                        const std::vector<double>& values) {
  OscillationSummary s;
  s.frequency = kNaN;
  if (times.empty()) return s;
  s.from = times.back() / 2;
  std::size_t first = 0;
  while (times[first] < s.from) ++first;
  double sum = 0.0;
  s.min = s.max = values[first];
  for (std::size_t n = first; n < times.size(); ++n) {
    sum += values[n];
    s.min = std::min(s.min, values[n]);
    s.max = std::max(s.max, values[n]);
  }
  s.mean = sum / static_cast<double>(times.size() - first);
  std::vector<double> crossings;
  for (std::size_t n = first + 1; n < times.size(); ++n) {
    const double a = values[n - 1] - s.mean, b = values[n] - s.mean;
    if (a < 0.0 && b >= 0.0)
      crossings.push_back(times[n - 1] + (times[n] - times[n - 1]) * -a / (b - a));
  }
  if (crossings.size() >= 3)
    s.frequency =
        static_cast<double>(crossings.size() - 1) / (crossings.back() - crossings.front());
  return s;
}

TimeSeries::TimeSeries(const SceneParams& scene, const fs::path& sceneFile)
    : scene_(scene), quantities_(seriesQuantities(scene)), values_(quantities_.size()) {
  const std::string& ref = scene.output.time_series.surge_front_reference;
  if (!ref.empty()) reference_ = readSurgeReference(relativeToScene(ref, sceneFile));
  if (std::find(quantities_.begin(), quantities_.end(), SeriesQuantity::surge_front) !=
      quantities_.end())
    timeScale_ = surgeTimeScale(scene);
}

double TimeSeries::nextSampleTime() const {
  if (empty()) return std::numeric_limits<double>::infinity();
  return times_.empty() ? 0.0 : next_;
}

void TimeSeries::record(double time, const SolverOutputs& outputs) {
  const std::vector<double> v = outputs.seriesValues(quantities_);
  times_.push_back(time);
  for (std::size_t q = 0; q < quantities_.size(); ++q) values_[q].push_back(v[q]);
}

bool TimeSeries::sampleIfDue(double time, const SolverOutputs& outputs) {
  if (empty() || (!times_.empty() && time < next_)) return false;
  record(time, outputs);
  next_ = nextDueAfter(time);
  return true;
}

double TimeSeries::nextDueAfter(double time) const {
  // On the grid k * interval, past `time` (a sample may fall a step after its due time).
  const double interval = scene_.output.time_series.interval;
  return (std::floor(time / interval + 1e-9) + 1.0) * interval;
}

bool TimeSeries::sampleFinal(double time, const SolverOutputs& outputs) {
  if (empty() || (!times_.empty() && times_.back() >= time)) return false;
  record(time, outputs);
  return true;
}

void TimeSeries::resume(const fs::path& dir, double time) {
  const fs::path file = dir / (scene_.name + "_time_series.csv");
  if (empty() || !fs::exists(file)) return;
  const CsvTable t = readCsv(file);
  const std::vector<double>& times = t.column("t", file);
  std::vector<const std::vector<double>*> columns;
  for (SeriesQuantity q : quantities_) columns.push_back(&t.column(columnName(scene_, q), file));
  for (std::size_t r = 0; r < times.size() && times[r] <= withoutRoundOff(time); ++r) {
    times_.push_back(times[r]);
    for (std::size_t q = 0; q < quantities_.size(); ++q) values_[q].push_back((*columns[q])[r]);
  }
  if (!times_.empty()) next_ = nextDueAfter(times_.back());
}

std::optional<TimeSeries::FrontDeviation> TimeSeries::surgeDeviation() const {
  const auto q = std::find(quantities_.begin(), quantities_.end(), SeriesQuantity::surge_front);
  if (q == quantities_.end() || reference_.empty() || times_.empty()) return std::nullopt;
  const std::vector<double>& Z = values_[static_cast<std::size_t>(q - quantities_.begin())];
  std::vector<sph::SurgeFrontPoint> simulated;
  for (std::size_t n = 0; n < times_.size(); ++n)
    simulated.push_back({times_[n] * timeScale_, Z[n]});
  const double Tmax = simulated.back().T + sph::kGateOpeningT;
  return FrontDeviation{sph::maxFrontDeviation(simulated, reference_, Tmax), Tmax};
}

std::string TimeSeries::surgeDeviationText() const {
  const std::optional<FrontDeviation> d = surgeDeviation();
  if (!d) return "";
  return "surge front deviates from " + scene_.output.time_series.surge_front_reference +
         " by max |dZ| " + formatNumber(d->maxError, 3) + " for T <= " +
         formatNumber(d->Tmax, 3) + " (simulated T + 0.175)";
}

std::string TimeSeries::coefficientSummaryText() const {
  std::string text;
  for (std::size_t q = 0; q < quantities_.size(); ++q) {
    if (!isForceCoefficient(quantities_[q])) continue;
    const OscillationSummary s = summarizeOscillation(times_, values_[q]);
    const bool lift = quantities_[q] == SeriesQuantity::lift_coefficient;
    text += (text.empty() ? "" : "; ") + std::string(lift ? "C_L" : "C_D") + " over t >= " +
            formatNumber(s.from, 3) + " s: mean " + formatNumber(s.mean, 4) + ", min " +
            formatNumber(s.min, 4) + ", max " + formatNumber(s.max, 4);
    // Shedding makes the lift change sign; a steady flow's lift only rings with the box's
    // pressure waves, whose frequency is no Strouhal number.
    if (lift && std::isfinite(s.frequency) && s.min < 0.0 && s.max > 0.0)
      text += ", St = f D / U " +
              formatNumber(s.frequency * forceCoefficientLength(scene_) /
                               forceCoefficientVelocity(scene_), 3) +
              " (f " + formatNumber(s.frequency, 3) + " Hz)";
  }
  if (!text.empty())
    text += " (roller " + std::to_string(scene_.output.time_series.body) + ", U " +
            formatShortest(withoutRoundOff(forceCoefficientVelocity(scene_))) + " m/s, D " +
            formatShortest(withoutRoundOff(forceCoefficientLength(scene_))) + " m)";
  return text;
}

fs::path TimeSeries::writeCsv(const fs::path& dir) const {
  CsvTable t;
  t.comments.push_back("scene " + scene_.name + ": quantities sampled every " +
                       formatShortest(scene_.output.time_series.interval) +
                       " s (at the end of the first solver chunk at or after each due time)");
  t.names.push_back("t (s)");
  std::vector<double> times;  // 5, not the 5.000000000000001 of n * dt
  for (double time : times_) times.push_back(withoutRoundOff(time));
  t.columns.push_back(times);
  if (const std::string c = coefficientSummaryText(); !c.empty()) t.comments.push_back(c);
  for (std::size_t q = 0; q < quantities_.size(); ++q) {
    if (quantities_[q] == SeriesQuantity::surge_front) {
      t.comments.push_back("surge_front: Z = (x_front + dx/2) / a against T = t sqrt(2 g / a), a "
                           "the column's width (Martin & Moyce 1952)");
      if (const std::string d = surgeDeviationText(); !d.empty()) t.comments.push_back(d);
      t.names.push_back("T (1)");
      std::vector<double> T;
      for (double time : times_) T.push_back(time * timeScale_);
      t.columns.push_back(T);
    }
    t.names.push_back(columnName(scene_, quantities_[q]));
    t.columns.push_back(values_[q]);
  }
  const fs::path file = dir / (scene_.name + "_time_series.csv");
  writeTextOutput(file, formatCsv(t));
  return file;
}

void TimeSeries::write(const fs::path& dir, std::ostream& log,
                       std::vector<fs::path>& written) const {
  if (empty()) return;
  written.push_back(writeCsv(dir));
  if (const std::string c = coefficientSummaryText(); !c.empty())
    log << scene_.name << ": " << c << "\n";
  for (std::size_t q = 0; q < quantities_.size(); ++q) {
    const std::string name = choiceName(quantities_[q]);
    LinePlotParams params;
    std::string spoken = name;  // "drag_coefficient" -> "drag coefficient"
    std::replace(spoken.begin(), spoken.end(), '_', ' ');
    params.title = scene_.name + ": " + spoken;
    std::vector<PlotSeries> series;
    if (quantities_[q] == SeriesQuantity::surge_front) {
      PlotSeries sim{"simulation (T + 0.175, the gate opening)", {}, values_[q], PlotMarks::line};
      for (double time : times_) sim.x.push_back(time * timeScale_ + sph::kGateOpeningT);
      series.push_back(sim);
      params.x_label = "T = t sqrt(2 g / a)";
      params.y_label = "surge front Z = x / a";
      if (!reference_.empty()) {
        PlotSeries ref{"Martin & Moyce 1952", {}, {}, PlotMarks::markers};
        for (const sph::SurgeFrontPoint& p : reference_) {
          ref.x.push_back(p.T);
          ref.y.push_back(p.Z);
        }
        series.push_back(ref);
        if (const std::string d = surgeDeviationText(); !d.empty())
          log << scene_.name << ": " << d << "\n";
      }
    } else {
      series.push_back({"simulation", times_, values_[q], PlotMarks::line});
      params.x_label = "t (s)";
      params.y_label = columnName(scene_, quantities_[q]);
    }
    const fs::path png = dir / (scene_.name + "_" + name + ".png");
    writePicture(renderLinePlot(series, params), png);
    written.push_back(png);
  }
}

}  // namespace fluidviz
