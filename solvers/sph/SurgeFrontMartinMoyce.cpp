#include "solvers/sph/SurgeFrontMartinMoyce.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "solvers/sph/SphSolver.h"

namespace fluidviz::sph {

namespace {
constexpr double kGateOpening = kGateOpeningT;
constexpr double kSampleStep = 0.05;    // in T
}  // namespace

std::vector<SurgeFrontPoint> readMartinMoyce(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read the Martin & Moyce data " + file);
  std::vector<SurgeFrontPoint> data;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'T') continue;
    std::istringstream s(line);
    SurgeFrontPoint p;
    char comma;
    if (s >> p.T >> comma >> p.Z) data.push_back(p);
  }
  if (data.empty()) throw std::runtime_error("no (T, Z) point in " + file);
  return data;
}

double interpolateFront(const std::vector<SurgeFrontPoint>& curve, double T) {
  if (T <= curve.front().T) return curve.front().Z;
  for (std::size_t k = 1; k < curve.size(); ++k)
    if (T <= curve[k].T)
      return curve[k - 1].Z + (curve[k].Z - curve[k - 1].Z) * (T - curve[k - 1].T) /
                                  (curve[k].T - curve[k - 1].T);
  return curve.back().Z;
}

std::pair<double, double> surgeFrontPositions(const std::vector<Vec3>& x, double dx) {
  double body = 0.0, any = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    any = std::max(any, x[i][0]);
    if (x[i][0] <= body) continue;
    int close = 0;
    for (std::size_t j = 0; j < x.size() && close < 2; ++j)
      if (j != i && (x[i] - x[j]).squaredNorm() < 2.25 * dx * dx) ++close;
    if (close >= 2) body = x[i][0];
  }
  return {body, any};
}

SurgeFrontPoint dimensionlessFront(const std::vector<Vec3>& x, double dx, double a, double g,
                                   double t) {
  return {t * std::sqrt(2 * g / a), (surgeFrontPositions(x, dx).first + 0.5 * dx) / a};
}

double maxFrontDeviation(const std::vector<SurgeFrontPoint>& simulated,
                         const std::vector<SurgeFrontPoint>& data, double Tmax) {
  double maxError = 0.0;
  for (const SurgeFrontPoint& d : data) {
    if (d.T > Tmax) continue;
    maxError = std::max(maxError, std::abs(interpolateFront(simulated, d.T - kGateOpening) - d.Z));
  }
  return maxError;
}

SurgeFrontComparison compareSurgeFront(SphSolver& solver, double a, double g,
                                       const std::vector<SurgeFrontPoint>& data, double Tmax) {
  const double dx = solver.params().particle_spacing;
  const double timeScale = std::sqrt(2 * g / a);
  SurgeFrontComparison r;
  r.simulated.push_back({0.0, 1.0});
  for (double T = kSampleStep; T <= Tmax - kGateOpening + kSampleStep + 1e-9; T += kSampleStep) {
    solver.advance(T / timeScale);
    const auto [body, any] = surgeFrontPositions(solver.state().x, dx);
    r.simulated.push_back({T, (body + 0.5 * dx) / a});
    r.maxRitterExcess = std::max(r.maxRitterExcess, (any + 0.5 * dx) / a - (1 + 2 * T));
  }
  r.maxError = maxFrontDeviation(r.simulated, data, Tmax);
  return r;
}

}  // namespace fluidviz::sph
