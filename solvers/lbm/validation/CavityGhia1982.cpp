#include "solvers/lbm/validation/CavityGhia1982.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "fieldviz/core/Sampling.h"

namespace fluidviz::lbm {

std::vector<GhiaPoint> readGhiaCentreline(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read the Ghia et al. 1982 table " + file);
  std::vector<GhiaPoint> rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::istringstream s(line);
    GhiaPoint p;
    char comma;
    if (s >> p.position >> comma >> p.re100 && p.position > 0.0 && p.position < 1.0)
      rows.push_back(p);
  }
  if (rows.empty()) throw std::runtime_error("no interior row in " + file);
  return rows;
}

namespace {

struct Differences {
  double sum2 = 0, max = 0;
  int count = 0;
  void add(double d) {
    sum2 += d * d;
    max = std::max(max, std::abs(d));
    ++count;
  }
};

Vec3 velocityAt(const VectorField& velocity, const Vec3& x) {
  const auto s = sample(velocity, x);
  if (!s)
    throw std::invalid_argument("Ghia table point (" + std::to_string(x.x()) + ", " +
                                std::to_string(x.y()) + ") lies outside the velocity grid");
  return *s;
}

}  // namespace

GhiaComparison compareWithGhia(const VectorField& velocity, double lid,
                               const std::vector<GhiaPoint>& uTable,
                               const std::vector<GhiaPoint>& vTable) {
  Differences u, v;
  for (const GhiaPoint& p : uTable)
    u.add(velocityAt(velocity, Vec3(0.5, p.position, 0.0)).x() / lid - p.re100);
  for (const GhiaPoint& p : vTable)
    v.add(velocityAt(velocity, Vec3(p.position, 0.5, 0.0)).y() / lid - p.re100);
  GhiaComparison c;
  c.uRms = std::sqrt(u.sum2 / u.count);
  c.uMax = u.max;
  c.vRms = std::sqrt(v.sum2 / v.count);
  c.vMax = v.max;
  c.rms = std::sqrt((u.sum2 + v.sum2) / (u.count + v.count));
  return c;
}

}  // namespace fluidviz::lbm
